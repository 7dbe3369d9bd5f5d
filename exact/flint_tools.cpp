#include "exact/flint_tools.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "exact/lll.hpp"

namespace tripack::exact::flint {

namespace {

// FLINT's strings are malloc'ed: freed by flint_free.
std::string take_string(char* text) {
  std::string s(text);
  flint_free(text);
  return s;
}

void power_of_ten(fmpz_t out, ulong exponent) {
  fmpz_set_ui(out, 10);
  fmpz_pow_ui(out, out, exponent);
}

}  // namespace

slong bits_for(int digits) {
  return static_cast<slong>(std::ceil(digits * 3.3219280948873623)) + 64;
}

void set_decimal(arb_t x, const std::string& text, int digits, slong prec) {
  if (text.empty() || arb_set_str(x, text.c_str(), prec) != 0)
    throw std::invalid_argument("not a decimal number: '" + text.substr(0, 40) + "'");
  Arb error;
  const std::string unit = "1e-" + std::to_string(std::max(1, digits - 1));
  arb_set_str(error.value, unit.c_str(), prec);
  Arb size;
  arb_abs(size.value, x);
  arb_mul(error.value, error.value, size.value, prec);
  arb_add_error(x, error.value);
}

namespace {

// round(10^scale_digits * value).
void scaled_integer(fmpz_t out, const arb_struct* value, int scale_digits, slong prec) {
  Fmpz scale;
  power_of_ten(scale.value, static_cast<ulong>(scale_digits));
  Arb scaled;
  arb_mul_fmpz(scaled.value, value, scale.value, prec);
  arf_get_fmpz(out, arb_midref(scaled.value), ARF_RND_NEAR);
}

// Initialises `lattice` to [I | round(10^scale_digits * values)], k x (k + 1).
void knapsack_lattice(fmpz_mat_t lattice, const std::vector<const arb_struct*>& values,
                      int scale_digits, slong prec) {
  const auto k = static_cast<slong>(values.size());
  fmpz_mat_init(lattice, k, k + 1);
  for (slong i = 0; i < k; ++i) {
    fmpz_one(fmpz_mat_entry(lattice, i, i));
    scaled_integer(fmpz_mat_entry(lattice, i, k), values[static_cast<std::size_t>(i)], scale_digits,
                   prec);
  }
}

// The relation in the first row of a reduced lattice of k rows (identity part first); clears it.
std::optional<std::vector<std::string>> first_row_relation(fmpz_mat_t lattice, slong k,
                                                           double& relation_digits) {
  std::vector<std::string> coefficients;
  bool zero = true;
  Fmpz height;
  for (slong i = 0; i < k; ++i) {
    const fmpz* c = fmpz_mat_entry(lattice, 0, i);
    zero = zero && fmpz_is_zero(c);
    if (fmpz_cmpabs(c, height.value) > 0) fmpz_abs(height.value, c);
    coefficients.push_back(take_string(fmpz_get_str(nullptr, 10, c)));
  }
  fmpz_mat_clear(lattice);
  if (zero) return std::nullopt;
  relation_digits =
      static_cast<double>(k) *
      (fmpz_is_zero(height.value) ? 0.0 : static_cast<double>(fmpz_sizeinbase(height.value, 10)));
  return coefficients;
}

}  // namespace

std::optional<std::vector<std::string>> integer_relation(
    const std::vector<const arb_struct*>& values, int scale_digits, slong prec,
    double& relation_digits) {
  const auto k = static_cast<slong>(values.size());
  fmpz_mat_t lattice;
  knapsack_lattice(lattice, values, scale_digits, prec);
  reduce_rows(lattice);
  return first_row_relation(lattice, k, relation_digits);
}

std::optional<std::vector<std::string>> ReducedBasis::relation(
    const arb_struct* value, const std::vector<const arb_struct*>& basis, int scale_digits,
    slong prec, double& relation_digits) {
  const auto m = static_cast<slong>(basis.size()), k = m + 1;
  fmpz_mat_struct* rows = nullptr;
  for (auto& [digits, reduced] : reduced_)
    if (digits == scale_digits) rows = &reduced;
  if (!rows) {
    reduced_.emplace_back(scale_digits, fmpz_mat_struct{});
    rows = &reduced_.back().second;
    knapsack_lattice(rows, basis, scale_digits, prec);
    reduce_rows(rows);
  }
  // The reduced basis rows (their identity part in columns 1..m), then the value's row.
  fmpz_mat_t lattice;
  fmpz_mat_init(lattice, k, k + 1);
  for (slong i = 0; i < m; ++i)
    for (slong j = 0; j <= m; ++j)
      fmpz_set(fmpz_mat_entry(lattice, i, j + 1), fmpz_mat_entry(rows, i, j));
  fmpz_one(fmpz_mat_entry(lattice, m, 0));
  scaled_integer(fmpz_mat_entry(lattice, m, k), value, scale_digits, prec);
  reduce_rows(lattice);
  return first_row_relation(lattice, k, relation_digits);
}

void ReducedBasis::clear() {
  for (auto& [digits, reduced] : reduced_) fmpz_mat_clear(&reduced);
  reduced_.clear();
}

void poly_from_strings(fmpz_poly_t poly, const std::vector<std::string>& coefficients) {
  fmpz_poly_zero(poly);
  Fmpz c;
  for (std::size_t i = 0; i < coefficients.size(); ++i) {
    if (fmpz_set_str(c.value, coefficients[i].c_str(), 10) != 0)
      throw std::invalid_argument("not an integer: " + coefficients[i]);
    fmpz_poly_set_coeff_fmpz(poly, static_cast<slong>(i), c.value);
  }
}

IntegerPolynomial strings_from_poly(const fmpz_poly_t poly) {
  IntegerPolynomial out;
  for (slong i = 0; i < fmpz_poly_length(poly); ++i)
    out.coefficients.push_back(
        take_string(fmpz_get_str(nullptr, 10, fmpz_poly_get_coeff_ptr(poly, i))));
  if (out.coefficients.empty()) out.coefficients.push_back("0");
  return out;
}

void fmpq_poly_from_strings(fmpq_poly_t poly, const std::vector<std::string>& coefficients) {
  fmpq_poly_zero(poly);
  Fmpq c;
  for (std::size_t i = 0; i < coefficients.size(); ++i) {
    if (fmpq_set_str(c.value, coefficients[i].c_str(), 10) != 0)
      throw std::invalid_argument("not a rational: " + coefficients[i]);
    fmpq_poly_set_coeff_fmpq(poly, static_cast<slong>(i), c.value);
  }
}

RationalPolynomial strings_from_fmpq_poly(const fmpq_poly_t poly) {
  RationalPolynomial out;
  Fmpq c;
  for (slong i = 0; i < fmpq_poly_length(poly); ++i) {
    fmpq_poly_get_coeff_fmpq(c.value, poly, i);
    out.coefficients.push_back(take_string(fmpq_get_str(nullptr, 10, c.value)));
  }
  if (out.coefficients.empty()) out.coefficients.push_back("0");
  return out;
}

std::optional<IsolatedRoot> isolate_root(const fmpz_poly_t f, const arb_t x, int width_digits,
                                         slong prec) {
  // centre = round(x * 10^E) / 10^E, E = width_digits + 5; the ends 10^-width_digits away.
  const int exponent = width_digits + 5;
  Fmpz denominator, centre, step;
  power_of_ten(denominator.value, static_cast<ulong>(exponent));
  power_of_ten(step.value, 5);
  Arb scaled;
  arb_mul_fmpz(scaled.value, x, denominator.value, prec);
  arf_get_fmpz(centre.value, arb_midref(scaled.value), ARF_RND_NEAR);
  Fmpq low, high;
  fmpz_sub(fmpq_numref(low.value), centre.value, step.value);
  fmpz_set(fmpq_denref(low.value), denominator.value);
  fmpq_canonicalise(low.value);
  fmpz_add(fmpq_numref(high.value), centre.value, step.value);
  fmpz_set(fmpq_denref(high.value), denominator.value);
  fmpq_canonicalise(high.value);
  // Exact signs at both ends.
  Fmpq at_low, at_high;
  fmpz_poly_evaluate_fmpq(at_low.value, f, low.value);
  fmpz_poly_evaluate_fmpq(at_high.value, f, high.value);
  if (fmpq_sgn(at_low.value) * fmpq_sgn(at_high.value) >= 0) return std::nullopt;
  // f' excludes 0 on [low, high]: f is monotone there, so exactly one root.
  Arb interval, end;
  arb_set_fmpq(interval.value, low.value, prec);
  arb_set_fmpq(end.value, high.value, prec);
  arb_union(interval.value, interval.value, end.value, prec);
  FmpzPoly derivative;
  fmpz_poly_derivative(derivative.value, f);
  Arb slope;
  arb_fmpz_poly_evaluate_arb(slope.value, derivative.value, interval.value, prec);
  if (arb_contains_zero(slope.value)) return std::nullopt;
  return IsolatedRoot{take_string(fmpq_get_str(nullptr, 10, low.value)),
                      take_string(fmpq_get_str(nullptr, 10, high.value))};
}

Field::Field(const IntegerPolynomial& k) {
  fmpq_poly_from_strings(modulus_.value, k.coefficients);
}

void Field::set(fmpq_poly_t out, const RationalPolynomial& a) const {
  fmpq_poly_from_strings(out, a.coefficients);
  fmpq_poly_rem(out, out, modulus_.value);
}

void Field::mul(fmpq_poly_t out, const fmpq_poly_t a, const fmpq_poly_t b) const {
  fmpq_poly_mul(out, a, b);
  fmpq_poly_rem(out, out, modulus_.value);
}

bool Field::inverse(fmpq_poly_t out, const fmpq_poly_t a) const {
  if (is_zero(a)) return false;
  FmpqPoly g, t;
  fmpq_poly_xgcd(g.value, out, t.value, a, modulus_.value);  // out a + t K = g, g = 1 (monic)
  if (!fmpq_poly_is_one(g.value)) return false;
  fmpq_poly_rem(out, out, modulus_.value);
  return true;
}

bool Field::is_zero(const fmpq_poly_t a) const {
  FmpqPoly r;
  fmpq_poly_rem(r.value, a, modulus_.value);
  return fmpq_poly_is_zero(r.value);
}

void Field::evaluate(arb_t out, const fmpq_poly_t a, const arb_t t0, slong prec) {
  ArbPoly ball;
  arb_poly_set_fmpq_poly(ball.value, a, prec);
  arb_poly_evaluate(out, ball.value, t0, prec);
}

void ball_of(arb_t x, const IsolatedRoot& root, slong prec) {
  Fmpq low, high;
  fmpq_set_str(low.value, root.low.c_str(), 10);
  fmpq_set_str(high.value, root.high.c_str(), 10);
  Arb end;
  arb_set_fmpq(x, low.value, prec);
  arb_set_fmpq(end.value, high.value, prec);
  arb_union(x, x, end.value, prec);
}

}  // namespace tripack::exact::flint
