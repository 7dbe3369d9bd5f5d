#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>
#include <string>

#include "core/io.hpp"
#include "report/described.hpp"

namespace tripack::report {

// CSV: a header of the top-level fields and one row of their values. A nested field has no
// column: the tree is refused whole rather than written without it.
void write_csv_tree(std::ostream& out, const Tree& description) {
  for (const auto& [key, value] : description.items())
    if (value.is_structured())
      throw std::invalid_argument("CSV cannot hold the nested field '" + key +
                                  "' of this result: use --output-format json");
  std::string header, row;
  bool first = true;
  for (const auto& [key, value] : description.items()) {
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
