// The writers of described results (core/described.hpp), one per output format, in one table: a
// new output format is its writer's file plus one line in described_writers().
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "core/described.hpp"

namespace tripack::report {

struct DescribedWriter {
  std::string format;  // "text", "json", "csv"
  void (*write)(std::ostream& out, const Described& result);
};
const std::vector<DescribedWriter>& described_writers();

// The writer of `format`; throws std::invalid_argument for a format no writer has.
void write_described(std::ostream& out, const Described& result, const std::string& format);

}  // namespace tripack::report
