#include <ostream>

#include "core/io.hpp"
#include "report/description.hpp"

namespace tripack::report {

// CSV (RFC 4180): the result's table (report/description.hpp, result_table), a header then its
// lines.
void write_csv(std::ostream& out, const Description& description) {
  const ResultTable table = result_table(description);
  csv_row(out, table.header);
  for (const auto& line : table.lines) csv_row(out, line);
}

}  // namespace tripack::report
