// FLINT's LLL for bench/lll/compare.cpp.
#include <flint/fmpz_lll.h>
#include <flint/fmpz_mat.h>
void flint_reduce(fmpz_mat_t a) {
  fmpz_lll_t c;
  fmpz_lll_context_init_default(c);
  fmpz_lll(a, nullptr, c);
}
