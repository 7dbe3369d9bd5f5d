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

// The rank and the pivot columns, from the first prime where every pivot is a unit (from the best
// of three primes when the rank there is below the row count).
struct KernelShape {
  // The pivot columns' minor is a unit modulo a prime, so nonzero over K: rank >= `rank`, proven.
  // With kernel vectors verified for every free column it is the rank over K exactly.
  int rank = 0;
  std::vector<int> pivot_columns;  // the leftmost independent columns, increasing
  int primes = 0;                  // primes eliminated modulo
  std::string reason;              // set when no prime gave a usable elimination
};

// Kernel vectors (A v = 0 over K, each verified exactly), each given by its values at the free
// columns (the columns not in `pivot_columns`, increasing): rationals "p/q".
struct KernelVectors {
  std::vector<std::vector<RationalPolynomial>> vectors;  // empty when `reason` is set
  int primes = 0;
  std::string reason;
};

// The whole reduced basis: one vector per free column f (1 there, 0 at the other free columns).
struct FieldKernel {
  KernelShape shape;
  std::vector<std::vector<RationalPolynomial>> basis;
  int primes = 0;      // primes eliminated modulo for the basis
  std::string reason;  // why no verified basis (empty on success)
};

// The columns that are not pivots, increasing: a kernel vector is fixed by its values there.
std::vector<int> free_columns(const std::vector<int>& pivot_columns, int columns);

// `rows`: the matrix's rows, every entry an element of K (a rational polynomial, reduced modulo
// K(t) or not). `field`: K(t), irreducible over Q.
KernelShape kernel_shape(const std::vector<std::vector<RationalPolynomial>>& rows,
                         const IntegerPolynomial& field);
KernelVectors kernel_vectors(const std::vector<std::vector<RationalPolynomial>>& rows,
                             const IntegerPolynomial& field, const KernelShape& shape,
                             const std::vector<std::vector<std::string>>& free_values);
FieldKernel kernel_over_field(const std::vector<std::vector<RationalPolynomial>>& rows,
                              const IntegerPolynomial& field);

}  // namespace tripack::exact
