// Coordinate files of a packing, in the format its extension names (core/io.hpp): .txt, .csv,
// .json, or .pck / .records (the record tables' "i x y" with d, r, S in the header). A record
// table carries the requested digits: from the MPFR polish when it ran, else long double (21 at
// most).
#pragma once

#include <string>

#include "core/packing.hpp"
#include "polish/polish_mp.hpp"

namespace tripack::report {

// `label` (t22a) goes into a record table's header.
void write_packing_file(const std::string& path, const Pattern& pattern, int digits,
                        const MultiprecisionPolish* high_precision = nullptr,
                        const std::string& label = "");

}  // namespace tripack::report
