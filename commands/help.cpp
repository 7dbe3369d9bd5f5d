#include "commands/help.hpp"

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

std::string error_json(const std::string& message) {
  std::ostringstream out;
  report::render_error_json(out, message);
  return out.str();
}

}  // namespace tripack::commands
