// How many ranks a launcher started this process among, from its environment alone (no MPI
// call, so a plain `tripack campaign` never initialises MPI).
#pragma once

#include <cstdlib>
#include <string>

namespace tripack {

inline int ranks_from_environment() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* value = std::getenv(name)) {
      try {
        const int size = std::stoi(value);
        if (size >= 1) return size;
      } catch (const std::exception&) {
      }
    }
  return 1;
}

}  // namespace tripack
