// The table formats of the data directory (docs/formats.md "The atlas files"), beside the
// packing-file formats: atlas.csv, atlas-gaps.csv and atlas-exact.csv. The one place their
// columns are named, their lines written (RFC 4180 fields) and their rows read back; the jobs
// fill and interpret the fields.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace tripack {

struct TableFormat {
  std::string what;                  // in errors: "atlas table"
  std::string file;                  // its name in the data directory: "atlas.csv"
  std::vector<std::string> columns;  // the header, in order
};

const TableFormat& atlas_table_format();        // atlas.csv
const TableFormat& atlas_gaps_table_format();   // atlas-gaps.csv
const TableFormat& exact_atlas_table_format();  // atlas-exact.csv

// One line of fields, with its line break.
std::string table_line(const std::vector<std::string>& fields);
std::string table_header(const TableFormat& format);  // table_line of the columns

// RFC 4180 fields of one CSV line (no line breaks inside fields: these tables write none).
std::vector<std::string> split_csv(const std::string& line);

struct TableRow {
  long long line = 0;  // in the file, for errors
  std::vector<std::string> fields;
};
// The rows of `csv`, whose header must be the format's, each with as many fields as columns;
// blank lines are skipped. Throws a one-line std::runtime_error naming the file and line (or
// "cannot read the WHAT FILE"); a missing file gives no rows when `missing_is_empty`.
std::vector<TableRow> read_table(const std::filesystem::path& csv, const TableFormat& format,
                                 bool missing_is_empty = false);

}  // namespace tripack
