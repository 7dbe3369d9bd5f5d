#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "report/described.hpp"

namespace tripack::report {

namespace {

void write_value(std::ostream& out, const Tree& value, const std::string& indent) {
  if (value.is_object()) {
    for (const auto& [key, item] : value.items()) {
      out << indent << key << ":";
      if (item.is_structured()) {
        out << "\n";
        write_value(out, item, indent + "  ");
      } else {
        out << " " << (item.is_string() ? item.get<std::string>() : item.dump()) << "\n";
      }
    }
  } else if (value.is_array()) {
    for (const auto& item : value) {
      if (item.is_structured()) {
        out << indent << "-\n";
        write_value(out, item, indent + "  ");
      } else {
        out << indent << "- " << (item.is_string() ? item.get<std::string>() : item.dump()) << "\n";
      }
    }
  } else {
    out << indent << (value.is_string() ? value.get<std::string>() : value.dump()) << "\n";
  }
}

}  // namespace

// Text: the result's title, then "name: value" lines, nested fields indented.
void write_text_tree(std::ostream& out, const Tree& description) {
  Tree fields = description;
  if (fields.is_object() && fields.contains("result") && fields["result"].is_string()) {
    out << fields["result"].get<std::string>() << "\n";
    fields.erase("result");
    write_value(out, fields, "  ");
  } else {
    write_value(out, fields, "");
  }
}

}  // namespace tripack::report
