// What every renderer shares: high-precision numbers as 17-digit decimal strings (a double
// round-trips; docs/formats.md), RFC 4180 CSV quoting (core/io.hpp csv_field), and writing a file
// whole or failing in one line.
#pragma once

#include <filesystem>
#include <string>

#include "core/io.hpp"

namespace tripack::report {

inline std::string decimal17(long double v) {
  return format_significant(v, 17);
}

}  // namespace tripack::report
