#include "exact/lll.hpp"

#include <fplll.h>

namespace tripack::exact {

void reduce_rows(fmpz_mat_t lattice) {
  const slong rows = fmpz_mat_nrows(lattice), cols = fmpz_mat_ncols(lattice);
  fplll::ZZ_mat<mpz_t> basis(static_cast<int>(rows), static_cast<int>(cols));
  for (slong i = 0; i < rows; ++i)
    for (slong j = 0; j < cols; ++j)
      fmpz_get_mpz(basis[static_cast<int>(i)][static_cast<int>(j)].get_data(),
                   fmpz_mat_entry(lattice, i, j));
  fplll::lll_reduction(basis);
  for (slong i = 0; i < rows; ++i)
    for (slong j = 0; j < cols; ++j)
      fmpz_set_mpz(fmpz_mat_entry(lattice, i, j),
                   basis[static_cast<int>(i)][static_cast<int>(j)].get_data());
}

}  // namespace tripack::exact
