#include <ostream>

#include "core/io.hpp"
#include "report/described.hpp"

namespace tripack::report {

// CSV: a header of the field names, one row of values.
void write_described_csv(std::ostream& out, const Described& result) {
  std::string header, row;
  for (const auto& f : result.fields) {
    header += (header.empty() ? "" : ",") + csv_field(f.name);
    row += (row.empty() ? "" : ",") + csv_field(f.value);
  }
  out << header << "\n" << row << "\n";
}

}  // namespace tripack::report
