// FLINT and Arb for exact/*.cpp only (private to exact/): owning wrappers and the shared steps
// (a decimal value as a ball, an integer relation by LLL, exact polynomial signs).
#pragma once

#include <arb.h>
#include <arb_fmpz_poly.h>
#include <arb_poly.h>
#include <flint/fmpq.h>
#include <flint/fmpq_poly.h>
#include <flint/fmpz.h>
#include <flint/fmpz_lll.h>
#include <flint/fmpz_mat.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpz_poly_factor.h>
#include <flint/fmpz_vec.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "exact/algebraic.hpp"

namespace tripack::exact::flint {

// Owning wrappers: construction inits, destruction clears; not copyable.
#define TRIPACK_FLINT_WRAPPER(Name, type, init, clear) \
  struct Name {                                        \
    type value;                                        \
    Name() { init(value); }                            \
    ~Name() { clear(value); }                          \
    Name(const Name&) = delete;                        \
    Name& operator=(const Name&) = delete;             \
  };
TRIPACK_FLINT_WRAPPER(Fmpz, fmpz_t, fmpz_init, fmpz_clear)
TRIPACK_FLINT_WRAPPER(Fmpq, fmpq_t, fmpq_init, fmpq_clear)
TRIPACK_FLINT_WRAPPER(FmpzPoly, fmpz_poly_t, fmpz_poly_init, fmpz_poly_clear)
TRIPACK_FLINT_WRAPPER(FmpqPoly, fmpq_poly_t, fmpq_poly_init, fmpq_poly_clear)
TRIPACK_FLINT_WRAPPER(Arb, arb_t, arb_init, arb_clear)
TRIPACK_FLINT_WRAPPER(ArbPoly, arb_poly_t, arb_poly_init, arb_poly_clear)
#undef TRIPACK_FLINT_WRAPPER

// The number field K = Q[t]/(K(t)) (K irreducible): elements are rational polynomials reduced
// modulo K(t); arithmetic is exact.
class Field {
 public:
  explicit Field(const IntegerPolynomial& k);
  void set(fmpq_poly_t out, const RationalPolynomial& a) const;  // a reduced
  void mul(fmpq_poly_t out, const fmpq_poly_t a, const fmpq_poly_t b) const;
  // out = 1 / a; false when a is 0.
  bool inverse(fmpq_poly_t out, const fmpq_poly_t a) const;
  bool is_zero(const fmpq_poly_t a) const;
  // The value at the embedding: the ball of a evaluated on the ball t0.
  static void evaluate(arb_t out, const fmpq_poly_t a, const arb_t t0, slong prec);

 private:
  FmpqPoly modulus_;
};

// Working precision in bits for `digits` decimal digits (with guard bits).
slong bits_for(int digits);

// x = the decimal `text`, a ball whose radius covers a rounding at `digits` significant digits.
void set_decimal(arb_t x, const std::string& text, int digits, slong prec);

// An integer relation c_0 v_0 + ... + c_{k-1} v_{k-1} ~ 0 among the balls `values` (their
// midpoints scaled by 10^scale_digits and rounded, then LLL): the first reduced row. None when
// that row is 0. `relation_digits` gets k * log10(max |c_i|).
std::optional<std::vector<std::string>> integer_relation(
    const std::vector<const arb_struct*>& values, int scale_digits, slong prec,
    double& relation_digits);

// Integer relations of many values against one basis (a packing's coordinates against 1, d, ...,
// d^(m-1)): the basis rows [I | round(10^scale b)] are LLL-reduced once per scale, and each
// value's row is added after them, so that LLL only reduces that row (the same lattice as
// integer_relation's: [U | U b] = U [I | b], U unimodular). At degree 64 and 4,000 digits, 21 s
// per coordinate became 0.8 s after 19 s once (docs/performance.md, "Exact d(n)").
class ReducedBasis {
 public:
  ReducedBasis() = default;
  ReducedBasis(const ReducedBasis&) = delete;
  ReducedBasis& operator=(const ReducedBasis&) = delete;
  ~ReducedBasis() { clear(); }
  // As integer_relation on {value} followed by `basis`; `basis` must be the same numbers at
  // every call (the cache is by scale only).
  std::optional<std::vector<std::string>> relation(const arb_struct* value,
                                                   const std::vector<const arb_struct*>& basis,
                                                   int scale_digits, slong prec,
                                                   double& relation_digits);
  void clear();  // the basis changed

 private:
  std::vector<std::pair<int, fmpz_mat_struct>> reduced_;  // by scale: m x (m + 1) rows
};

void poly_from_strings(fmpz_poly_t poly, const std::vector<std::string>& coefficients);
IntegerPolynomial strings_from_poly(const fmpz_poly_t poly);
void fmpq_poly_from_strings(fmpq_poly_t poly, const std::vector<std::string>& coefficients);
RationalPolynomial strings_from_fmpq_poly(const fmpq_poly_t poly);

// An isolating interval of width ~2 * 10^-width_digits around the ball x for the squarefree
// polynomial f, or none when the signs or the derivative do not prove it.
std::optional<IsolatedRoot> isolate_root(const fmpz_poly_t f, const arb_t x, int width_digits,
                                         slong prec);

// minimal_polynomial (exact/algebraic.hpp) of the ball x2, known to 2 * digits digits.
MinimalPolynomial minimal_polynomial_of_ball(const arb_t x2, int digits, int max_degree);

// x rounded to `digits` significant digits, its radius widened to cover that rounding.
void round_ball(arb_t x, const arb_t x2, int digits);

// The ball [low, high] of an isolated root.
void ball_of(arb_t x, const IsolatedRoot& root, slong prec);

}  // namespace tripack::exact::flint
