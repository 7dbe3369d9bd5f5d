// Lattice reduction for integer relations: fplll's LLL wrapper (L^2 with floating-point
// Gram-Schmidt at adaptive precision). On the knapsack lattices of docs/exact.md (an identity
// block beside one column of 1,000s of digits) it took 21 s where FLINT's fmpz_lll took 106 s at
// degree 64 and 4,000 digits, and the same time at degree 24 and 1,500 (docs/performance.md).
#pragma once

#include <flint/fmpz_mat.h>

namespace tripack::exact {

// LLL-reduces the rows of `lattice` in place (delta 0.99, eta 0.51).
void reduce_rows(fmpz_mat_t lattice);

}  // namespace tripack::exact
