// The table formats of the data directory (docs/formats.md "The atlas files"), beside the
// packing-file formats: atlas.csv, atlas-gaps.csv and atlas-exact.csv. The one place their
// columns are named, their lines written (RFC 4180 fields) and their rows read back; the jobs
// fill and interpret the fields.
#pragma once

#include <filesystem>
#include <functional>
#include <set>
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

struct TableRecord {
  long long line = 0;  // in the file, for errors
  std::vector<std::string> fields;
};
// The rows of `csv`, whose header must be the format's, each with as many fields as columns;
// blank lines are skipped. Throws a one-line std::runtime_error naming the file and line (or
// "cannot read the WHAT FILE"); a missing file gives no rows when `missing_is_empty`.
std::vector<TableRecord> read_table(const std::filesystem::path& csv, const TableFormat& format,
                                    bool missing_is_empty = false);

// The keys (column `key_column`) of the rows `counts` accepts (every row when empty): what a
// resumed job has already done (runner/runner.hpp, skip_done). A missing file has none.
std::set<std::string> keys_in_table(const std::filesystem::path& csv, const TableFormat& format,
                                    std::size_t key_column,
                                    const std::function<bool(const TableRecord&)>& counts = {});

// Rewrites the table with one row per key, the last appended winning (a row run again is
// appended after its old one), in the order of `order` (keys not in it last, as they were);
// through a temporary file renamed over the old one.
void sort_table(const std::filesystem::path& csv, const TableFormat& format, std::size_t key_column,
                const std::vector<std::string>& order);

}  // namespace tripack
