#include <fmt/format.h>

#include <ostream>
#include <string>

#include "report/description.hpp"

namespace tripack::report {

namespace {

bool all_scalars(const Tree& array) {
  for (const auto& item : array)
    if (item.is_structured()) return false;
  return true;
}

std::string joined(const Tree& array) {
  std::string text;
  for (const auto& item : array) {
    if (!text.empty()) text += ' ';
    text += scalar_text(item);
  }
  return text;
}

}  // namespace

// "name value" lines (names in a column of 10, as the results' own views print them); a list of
// scalars on one line; an object or a list of objects indented below its name.
void write_text_fields(std::ostream& out, const Tree& fields, const std::string& indent) {
  for (const auto& [key, value] : fields.items()) {
    if (value.is_object()) {
      out << indent << key << "\n";
      write_text_fields(out, value, indent + "  ");
    } else if (value.is_array() && !all_scalars(value)) {
      out << indent << key << "\n";
      std::size_t i = 0;
      for (const auto& item : value) {
        if (item.is_structured()) {
          out << indent << "  [" << i++ << "]\n";
          write_text_fields(out, item.is_object() ? item : Tree{{"items", item}}, indent + "    ");
        } else {
          out << indent << "  [" << i++ << "] " << scalar_text(item) << "\n";
        }
      }
    } else {
      out << fmt::format("{}{:<10} {}\n", indent, key,
                         value.is_array() ? joined(value) : scalar_text(value));
    }
  }
}

// Text, for a result without a view of its own: every field by name.
void write_text(std::ostream& out, const Description& description) {
  write_text_fields(out, description.fields, "");
}

}  // namespace tripack::report
