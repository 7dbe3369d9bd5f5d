// Coordinates files of a packing, in the format its extension names (core/io.hpp): .txt, .csv,
// .json, or .pck / .records (the record tables' "i x y" with d, r, S in the header). A record
// table carries the requested digits: from the MPFR polish when it ran, else long double (21 at
// most).
#pragma once

#include <iosfwd>
#include <string>

#include "core/io.hpp"
#include "core/packing.hpp"
#include "polish/polish_mp.hpp"

namespace tripack::report {

// `label` (t22a) goes into a record table's header.
void write_packing_file(const std::string& path, const Pattern& pattern, int digits,
                        const MultiprecisionPolish* high_precision = nullptr,
                        const std::string& label = "");

// One packing in `format` on a stream, in a convention (core/io.hpp's WriteOptions): the
// coordinates with `digits` significant digits (at most 21), d, L, r and S with `d_digits`;
// the label in every format's header. `tripack db export` writes through this.
void write_packing(std::ostream& out, const Pattern& pattern, FileFormat format,
                   const WriteOptions& options);

// The format's name on the command line (txt, csv, json, records) and its file extension (.txt,
// .csv, .json, .pck); parse_file_format accepts "pck" for records too.
std::optional<FileFormat> parse_file_format(const std::string& name);
std::string file_extension(FileFormat format);

}  // namespace tripack::report
