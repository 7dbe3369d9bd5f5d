// Lattice reduction for integer relations: fplll's LLL wrapper (L^2 with floating-point
// Gram-Schmidt at adaptive precision). For the knapsack lattices of docs/exact.md (a identity
// block beside one column of 1,000s of digits) it is about 50x faster than FLINT's fmpz_lll at
// degree 64 and 4,000 digits (docs/performance.md), which decides how far the exact atlas gets.
#pragma once

#include <flint/fmpz_mat.h>

namespace tripack::exact {

// LLL-reduces the rows of `lattice` in place (delta 0.99, eta 0.51).
void reduce_rows(fmpz_mat_t lattice);

}  // namespace tripack::exact
