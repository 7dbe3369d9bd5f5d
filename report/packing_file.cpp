#include "report/packing_file.hpp"

#include <fstream>

#include "core/io.hpp"

namespace tripack::report {

void write_packing_file(const std::string& path, const Pattern& pattern, int digits,
                        const MultiprecisionPolish* high_precision, const std::string& label) {
  if (format_from_path(path) != FileFormat::Records) return write_pattern(path, pattern);
  RecordsTable table = records_table(pattern, std::max(digits, 17));
  table.label = label;
  if (high_precision && high_precision->converged && digits > 18) {
    table.d = high_precision->d;
    table.L = high_precision->L;
    table.r = radius_or_side_from_d(high_precision->d, true, digits);
    table.S = radius_or_side_from_d(high_precision->d, false, digits);
    // Rattlers are not unknowns of the polish: their start coordinates are kept (see
    // MultiprecisionPolish::points).
    for (std::size_t i = 0; i < table.points.size() && i < high_precision->points.size(); ++i)
      table.points[i] = {high_precision->points[i][0], high_precision->points[i][1]};
  }
  std::ofstream out(path);
  if (!out) throw InputError("cannot open '" + path + "' for writing");
  write_records(out, table);
  if (!out) throw InputError("failed writing '" + path + "'");
}

}  // namespace tripack::report
