// What the commands share: the output options (--json, --csv, --points) and diagrams (--svg,
// --png, --pdf), printing a result whole, progress lines, the output directory, and how a
// cancelled job ends.
#pragma once

#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands/command.hpp"
#include "constructors/catalogue.hpp"
#include "core/packing.hpp"
#include "report/progress_line.hpp"
#include "report/render.hpp"

namespace tripack::commands {

Catalogue load_catalogue(const Context& context);

// --output-format NAME (--json and --csv are its aliases) / --points: how the result is printed.
struct Output {
  std::string name;     // a writer of report/description.hpp's table; empty: text
  bool points = false;  // JSON: with coordinates
  void declare(OptionList& o, bool with_points = false);
  // Two different formats asked for (--json --csv) are an error, not a silent choice.
  void choose(const std::string& format, const std::string& given_as);
  std::string format_name() const { return name.empty() ? "text" : name; }
};

// --svg FILE / --png FILE / --pdf FILE: a diagram of the result's packing (report/diagram.hpp).
struct Diagrams {
  std::string svg, png, pdf;
  bool forces = false;  // bond forces of the stress certificate as line widths
  void declare(OptionList& o);
  void draw(const Pattern& pattern, const std::string& label,
            const std::vector<long double>& forces) const;
};

// A command whose options are its request's and the output format's.
template <class Request, bool kWithPoints = false>
class RequestCommand : public Command {
 protected:
  Request request;
  Output out;

 public:
  void declare(OptionList& o) override {
    request.declare(o);
    out.declare(o, kWithPoints);
  }
};

// Rendered into a buffer first, so that a formatting failure cannot leave half a result: then the
// text rendering (which cannot fail on content) is printed instead, and the error reported.
template <class Result>
void print_result(const Result& result, const Output& out) {
  std::ostringstream buffer;
  try {
    report::render(buffer, result, out.format_name(), {out.points});
  } catch (const std::exception& e) {
    std::ostringstream text;
    report::render(text, result, "text", {out.points});
    std::cout << text.str() << std::flush;
    throw std::runtime_error(std::string("could not format the result (printed as text): ") +
                             e.what());
  }
  std::cout << buffer.str() << std::flush;
}

// The progress line of a command whose result goes to stdout: on a terminal, and only when the
// result is text. Stages reported after quiet_seconds.
report::ProgressLineOptions terminal_line(std::string job, const Output& out,
                                          double quiet_seconds = 0);
// A long job's progress: redrawn on a terminal; in a log, every `log_every`-th item.
report::ProgressLineOptions job_line(std::string job, long long log_every);

// How every cancelled long job ends: one line "tripack: cancelled: interrupted; WHAT" on stderr
// and exit kCancelledExit.
int cancelled(const std::string& what);
// A one-item job's computation has ended (CommandInfo::one_item_lost): claims the ending, or, when
// the signal thread has claimed it, waits for that thread to end the process (it writes nothing).
void claim_ending(const Context& context);

// "tripack VERSION": what the database records as the tool of a run.
std::string tool_version();

// A long job's context (core/progress.hpp): the command's cancel token, `progress`, the version.
JobContext job_context(const Context& context, ProgressFn progress = {});

}  // namespace tripack::commands
