#include "analysis/openmp_regions.hpp"

#include <omp.h>

namespace tripack {

void run_openmp_regions_on_this_thread() {
  omp_set_max_active_levels(0);
}

}  // namespace tripack
