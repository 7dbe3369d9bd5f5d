#include "commands/common.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "core/io.hpp"
#include "report/diagram.hpp"

namespace tripack::commands {

Catalogue load_catalogue(const Context& context) {
  return Catalogue::load(context.catalogue.empty() ? Catalogue::default_path() : context.catalogue);
}

void Output::choose(const std::string& format, const std::string& given_as) {
  bool known = false;
  for (const auto& w : report::output_writers()) known = known || w.format == format;
  if (!known)
    throw std::invalid_argument("--output-format must be one of " + report::output_format_names() +
                                ", not '" + format + "'");
  if (!name.empty() && name != format)
    throw std::invalid_argument(given_as + " asks for " + format + " output, but " + name +
                                " was asked for already: give one format");
  name = format;
}

void Output::declare(OptionList& o, bool with_points) {
  o.flag_action(
      "--json", [this] { choose("json", "--json"); },
      "print one JSON object (the same as --output-format json)");
  o.flag_action(
      "--csv", [this] { choose("csv", "--csv"); },
      "print CSV, a header then rows (the same as --output-format csv)");
  o.parsed(
      "--output-format", [this](const std::string& s) { choose(s, "--output-format " + s); },
      "text", "print the result as " + report::output_format_names());
  if (with_points) o.flag("--points", points, "with --json: every packing's coordinates");
}

void Diagrams::declare(OptionList& o) {
  o.option("--svg", svg, "draw the packing to this SVG file");
  o.option("--png", png, "draw the packing to this PNG file");
  o.option("--pdf", pdf, "draw the packing to this PDF file");
  o.flag("--forces", forces, "draw the stress certificate's bond forces as widths");
}

void Diagrams::draw(const Pattern& pattern, const std::string& label,
                    const std::vector<long double>& bond_forces) const {
  report::Diagram diagram{pattern, label, format_significant(pattern.packing.d, 15), bond_forces};
  report::DiagramOptions options;
  options.forces = forces;
  for (const auto* path : {&svg, &png, &pdf})
    if (!path->empty()) report::draw_packing(diagram, *path, options);
}

report::ProgressLineOptions terminal_line(std::string job, const Output& out,
                                          double quiet_seconds) {
  report::ProgressLineOptions options;
  options.job = std::move(job);
  options.terminal = out.format_name() == "text" && isatty(fileno(stderr));
  options.quiet_seconds = quiet_seconds;
  return options;
}

report::ProgressLineOptions job_line(std::string job, long long log_every) {
  report::ProgressLineOptions options;
  options.job = std::move(job);
  options.terminal = isatty(fileno(stderr));
  options.log_every = log_every;
  return options;
}

int cancelled(const std::string& what) {
  std::cerr << "tripack: cancelled: interrupted; " << what << "\n";
  return kCancelledExit;
}

void claim_ending(const Context& context) {
  if (!context.cancel || context.cancel->claim_ending()) return;
  for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
}

std::string tool_version() {
  return "tripack " TRIPACK_VERSION;
}

JobContext job_context(const Context& context, ProgressFn progress) {
  return {context.cancel, std::move(progress), tool_version()};
}

}  // namespace tripack::commands
