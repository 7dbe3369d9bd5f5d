// A campaign's work unit and how a finished one travels between MPI ranks: the worker rank sends
// its RunRecord to rank 0, the only writer, as one JSON text (long doubles as 21-digit strings,
// so the packing rank 0 stores is the one the worker found, digit for digit).
#pragma once

#include <cstdint>
#include <string>

#include "store/results_db.hpp"

namespace tripack::jobs {

struct WorkUnit {
  long long n = 0;
  std::uint64_t seed = 0;
};

std::string encode_run(const store::RunRecord& run);
// Throws std::runtime_error for a text that encode_run did not write.
store::RunRecord decode_run(const std::string& text);

}  // namespace tripack::jobs
