#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "core/io.hpp"
#include "report/described.hpp"

namespace tripack::report {

// CSV: a header of the top-level scalar fields and one row of their values (nested fields are
// left to the other formats).
void write_csv_tree(std::ostream& out, const Tree& description) {
  std::string header, row;
  bool first = true;
  for (const auto& [key, value] : description.items()) {
    if (value.is_structured()) continue;
    if (!first) {
      header += ',';
      row += ',';
    }
    first = false;
    header += csv_field(key);
    row += csv_field(value.is_string() ? value.get<std::string>() : value.dump());
  }
  out << header << "\n" << row << "\n";
}

}  // namespace tripack::report
