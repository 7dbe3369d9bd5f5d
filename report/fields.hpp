// What every renderer shares: high-precision numbers as 17-digit decimal strings (a double
// round-trips; SPEC §9), RFC 4180 CSV quoting, and writing a file whole or failing in one line.
#pragma once

#include <filesystem>
#include <string>

#include "core/io.hpp"

namespace tripack::report {

inline std::string decimal17(long double v) {
  return format_significant(v, 17);
}

// The field as is, or quoted (with doubled quotes) when it holds a comma, quote or line break, so
// plain names stay plain.
inline std::string csv_field(const std::string& field) {
  if (field.find_first_of(",\"\n\r") == std::string::npos) return field;
  std::string q = "\"";
  for (char c : field) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

// Writes `bytes` to `path` (replacing it); throws "cannot write PATH: reason" on failure.
void write_file(const std::filesystem::path& path, const std::string& bytes);

}  // namespace tripack::report
