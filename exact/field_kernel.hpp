// The kernel of a matrix over a number field K = Q[t]/(K(t)), by elimination modulo word-size
// primes and rational reconstruction (docs/exact.md, statement (II)). Gauss-Jordan over K itself
// swells the rationals and takes an extended gcd of degree [K:Q] per pivot: over t18a's field of
// degree 128 it had not finished after 40 CPU-minutes. Modulo a prime p the elimination runs in
// F_p[t]/(K(t)) with fixed-size numbers; the kernel's coefficients are recovered by the Chinese
// remainder theorem and rational reconstruction from as many primes as their height needs, and
// then verified exactly over K. Plain strings at the interface, as exact/algebraic.hpp.
#pragma once

#include <string>
#include <vector>

#include "exact/algebraic.hpp"

namespace tripack::exact {

struct FieldKernel {
  // The rank modulo the best prime seen, with every pivot a unit of F_p[t]/(K(t)): the pivot
  // columns' minor is then nonzero over K, so rank >= `rank`, proven. With `basis` verified it is
  // the rank over K exactly (B - rank independent vectors lie in the kernel).
  int rank = 0;
  std::vector<int> pivot_columns;  // the leftmost independent columns, increasing
  // One vector per free column f (1 there, 0 at the other free columns), each verified A v = 0
  // exactly over K; empty when `reason` is set.
  std::vector<std::vector<RationalPolynomial>> basis;
  int primes = 0;      // primes eliminated modulo
  std::string reason;  // why no verified basis (empty on success)
};

// `rows`: the matrix's rows, every entry an element of K (a rational polynomial, reduced modulo
// K(t) or not). `field`: K(t), irreducible over Q. With `require_full_row_rank`, a matrix whose
// rank modulo three primes is below its row count stops there, with `reason` set.
FieldKernel kernel_over_field(const std::vector<std::vector<RationalPolynomial>>& rows,
                              const IntegerPolynomial& field, bool require_full_row_rank);

}  // namespace tripack::exact
