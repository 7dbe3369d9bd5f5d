#include "report/description.hpp"

#include <algorithm>
#include <ostream>
#include <stdexcept>

namespace tripack::report {

// The writers, each in its file (report/writer_FORMAT.cpp).
void write_text(std::ostream& out, const Description& description);
void write_json(std::ostream& out, const Description& description);
void write_csv(std::ostream& out, const Description& description);
void write_text_fields(std::ostream& out, const Tree& fields, const std::string& indent);

const std::vector<OutputWriter>& output_writers() {
  static const std::vector<OutputWriter> writers{
      {"text", write_text},
      {"json", write_json},
      {"csv", write_csv},
  };
  return writers;
}

std::string output_format_names() {
  std::string names;
  for (const auto& w : output_writers()) names += (names.empty() ? "" : ", ") + w.format;
  return names;
}

void write_description(std::ostream& out, const Description& description,
                       const std::string& format) {
  for (const auto& w : output_writers())
    if (w.format == format) return w.write(out, description);
  throw std::invalid_argument("--output-format must be one of " + output_format_names() +
                              ", not '" + format + "'");
}

void write_fields_not_shown(std::ostream& out, const Description& description) {
  Tree rest = Tree::object();
  for (const auto& [key, value] : description.fields.items())
    if (std::find(description.shown_by_view.begin(), description.shown_by_view.end(), key) ==
        description.shown_by_view.end())
      rest[key] = value;
  write_text_fields(out, rest, "");
}

std::string scalar_text(const Tree& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_null()) return "";
  return value.dump(-1, ' ', false, Tree::error_handler_t::replace);
}

}  // namespace tripack::report
