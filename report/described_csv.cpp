#include <ostream>

#include "core/io.hpp"
#include "report/described.hpp"

namespace tripack::report {

// CSV: a header of the field names, one row of values.
void write_described_csv(std::ostream& out, const Described& result) {
  std::string header, row;
  for (std::size_t i = 0; i < result.fields.size(); ++i) {
    if (i > 0) {
      header += ',';
      row += ',';
    }
    header += csv_field(result.fields[i].name);
    row += csv_field(result.fields[i].value);
  }
  out << header << "\n" << row << "\n";
}

}  // namespace tripack::report
