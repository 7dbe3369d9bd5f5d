#include "report/packing_file.hpp"

#include <algorithm>
#include <fstream>
#include <ostream>

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

void write_packing(std::ostream& out, const Pattern& pattern, FileFormat format,
                   const WriteOptions& options) {
  switch (format) {
    case FileFormat::Text:
      return write_text(out, pattern, options);
    case FileFormat::Csv:
      return write_csv(out, pattern, options);
    case FileFormat::Json:
      return write_json(out, pattern, options);
    case FileFormat::Records: {
      RecordsTable table = records_table(pattern, options.digits, options.convention);
      table.label = options.label;
      const int d_digits = std::clamp(options.d_digits, 1, 21);
      const long double d = pattern.packing.d;
      table.d = format_significant(d, d_digits);
      table.r = format_significant(radius_from_d(d), d_digits);
      table.S = format_significant(side_from_d(d), d_digits);
      table.L = format_significant(1 / d, d_digits);
      return write_records(out, table);
    }
  }
}

std::optional<FileFormat> parse_file_format(const std::string& name) {
  if (name == "txt") return FileFormat::Text;
  if (name == "csv") return FileFormat::Csv;
  if (name == "json") return FileFormat::Json;
  if (name == "records" || name == "pck") return FileFormat::Records;
  return std::nullopt;
}

std::string file_extension(FileFormat format) {
  switch (format) {
    case FileFormat::Text:
      return ".txt";
    case FileFormat::Csv:
      return ".csv";
    case FileFormat::Json:
      return ".json";
    case FileFormat::Records:
      return ".pck";
  }
  return ".txt";
}

}  // namespace tripack::report
