// Printing a result: its family's View (report/results/) describes it once; the chosen format's
// writer (report/description.hpp) renders the description. A result a person reads also has a text
// view of its own, in its family file; its fields the view does not print follow it by name.
#pragma once

#include <ostream>
#include <string>

#include "report/description.hpp"

namespace tripack::report {

// Specialised once per result type in its family file (report/results/NAME.hpp):
//   static Description describe(const Result&, const DescribeOptions&);
//   static void text(std::ostream&, const Result&);   // optional: the hand-made text view
template <class Result>
struct View;

template <class Result>
void render(std::ostream& out, const Result& result, const std::string& format,
            const DescribeOptions& options = {}) {
  const Description description = View<Result>::describe(result, options);
  if constexpr (requires { View<Result>::text(out, result); }) {
    if (format == "text") {
      View<Result>::text(out, result);
      write_fields_not_shown(out, description);
      return;
    }
  }
  write_description(out, description, format);
}

// An error as a result: {"error": message} in the chosen format (text: nothing; stderr has it).
inline void render_error(std::ostream& out, const std::string& message, const std::string& format) {
  if (format == "text") return;
  Description error;
  error.fields["error"] = message;
  write_description(out, error, format);
}

}  // namespace tripack::report
