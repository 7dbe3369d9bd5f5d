#include "commands/help.hpp"

#include <nlohmann/json.hpp>
#include <sstream>

#include "formats/formats.hpp"
#include "report/render.hpp"

namespace tripack::commands {

std::string help_footer() {
  std::string text = "Packing-file formats (by extension; --format NAME):\n";
  for (const auto& f : packing_formats()) {
    std::string extensions;
    for (const auto& e : f.extensions) extensions += (extensions.empty() ? "" : " ") + e;
    text += "  " + f.name + " (" + extensions + "): " + f.description +
            (f.read ? "" : " [written only]") + "\n";
  }
  return text + "Every command: tripack COMMAND --help. Manual: docs/cli.md.";
}

std::string error_output(const std::string& message, const std::string& format) {
  std::ostringstream out;
  try {
    report::render_error(out, message, format);
  } catch (const std::exception&) {  // an unknown format: the error line on stderr says so
    return "";
  }
  return out.str();
}

std::string requested_format(int argc, const char* const* argv) {
  const std::string prefix = "--output-format=";
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--json") return "json";
    if (arg == "--csv") return "csv";
    if (arg == "--output-format" && i + 1 < argc) return argv[i + 1];
    if (arg.rfind(prefix, 0) == 0) return arg.substr(prefix.size());
  }
  return "text";
}

}  // namespace tripack::commands
