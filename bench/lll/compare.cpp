// One integer-relation lattice (identity | powers of a number scaled to D digits, one integer per
// line of /tmp/col.txt), reduced by fplll and by FLINT's fmpz_lll in one run (docs/performance.md
// "Exact d(n)"). Not part of the build:
//   g++ -O2 -o /tmp/lllbench bench/lll/compare.cpp bench/lll/flint_reduce.cpp -lfplll -lflint
//   -lmpfr -lgmp
// (flint_reduce.cpp is apart because fplll's and FLINT's LLL headers define the same macros.)
#include <flint/fmpz_mat.h>
void flint_reduce(fmpz_mat_t a);
#include <fplll.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>
int main() {
  std::ifstream in("/tmp/col.txt");
  std::vector<std::string> col;
  std::string s;
  while (in >> s) col.push_back(s);
  long k = col.size();
  for (int which = 1; which >= 0; --which) {
    fmpz_mat_t a;
    fmpz_mat_init(a, k, k + 1);
    for (long i = 0; i < k; ++i) {
      fmpz_one(fmpz_mat_entry(a, i, i));
      fmpz_set_str(fmpz_mat_entry(a, i, k), col[i].c_str(), 10);
    }
    auto t = std::chrono::steady_clock::now();
    if (which == 0)
      flint_reduce(a);
    else {
      fplll::ZZ_mat<mpz_t> b(k, k + 1);
      for (long i = 0; i < k; ++i)
        for (long j = 0; j <= k; ++j) fmpz_get_mpz(b[i][j].get_data(), fmpz_mat_entry(a, i, j));
      fplll::lll_reduction(b);
      for (long i = 0; i < k; ++i)
        for (long j = 0; j <= k; ++j) fmpz_set_mpz(fmpz_mat_entry(a, i, j), b[i][j].get_data());
    }
    double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    char* c0 = fmpz_get_str(nullptr, 10, fmpz_mat_entry(a, 0, 0));
    std::printf("%s: %.2f s, first row starts %.30s\n", which ? "fplll" : "FLINT fmpz_lll", sec,
                c0);
    fmpz_mat_clear(a);
  }
}
