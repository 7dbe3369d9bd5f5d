#include "exact/algebraic.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "exact/flint_tools.hpp"

namespace tripack::exact {

namespace {

using flint::Arb;
using flint::FmpqPoly;
using flint::FmpzPoly;

// "c*v^k" terms, highest power first, in PARI/GP syntax.
std::string pari_of(const std::vector<std::string>& coefficients, const std::string& variable) {
  std::string out;
  for (std::size_t i = coefficients.size(); i-- > 0;) {
    std::string c = coefficients[i];
    if (c == "0") continue;
    const bool negative = c[0] == '-';
    if (negative) c.erase(0, 1);
    const std::string power = i == 0 ? "" : (i == 1 ? variable : fmt::format("{}^{}", variable, i));
    std::string term;
    if (power.empty())
      term = c;
    else if (c == "1")
      term = power;
    else
      term = fmt::format("{}*{}", c, power);
    if (out.empty())
      out = negative ? fmt::format("-{}", term) : term;
    else
      out += fmt::format(" {} {}", negative ? '-' : '+', term);
  }
  return out.empty() ? std::string("0") : out;
}

// Primitive, leading coefficient > 0.
void normalise(fmpz_poly_t f) {
  fmpz_poly_primitive_part(f, f);
  if (fmpz_sgn(fmpz_poly_lead(f)) < 0) fmpz_poly_neg(f, f);
}

// The powers 1, x, ..., x^degree of the ball x.
struct Powers {
  std::vector<std::unique_ptr<Arb>> balls;
  Powers(const arb_t x, int degree, slong prec) {
    for (int i = 0; i <= degree; ++i) {
      balls.push_back(std::make_unique<Arb>());
      arb_pow_ui(balls.back()->value, x, static_cast<ulong>(i), prec);
    }
  }
  std::vector<const arb_struct*> pointers() const {
    std::vector<const arb_struct*> out;
    for (const auto& b : balls) out.push_back(b->value);
    return out;
  }
};

// The irreducible factor of the relation's polynomial that vanishes at x (its value's ball
// contains 0 while every other factor's excludes it); false when not exactly one does.
bool vanishing_factor(fmpz_poly_t out, const std::vector<std::string>& relation, const arb_t x,
                      slong prec) {
  FmpzPoly poly;
  flint::poly_from_strings(poly.value, relation);
  if (fmpz_poly_degree(poly.value) < 1) return false;
  fmpz_poly_factor_t factors;
  fmpz_poly_factor_init(factors);
  fmpz_poly_factor(factors, poly.value);
  int vanishing = 0;
  Arb value;
  for (slong i = 0; i < factors->num; ++i) {
    arb_fmpz_poly_evaluate_arb(value.value, factors->p + i, x, prec);
    if (arb_contains_zero(value.value)) {
      ++vanishing;
      fmpz_poly_set(out, factors->p + i);
    }
  }
  fmpz_poly_factor_clear(factors);
  if (vanishing != 1) return false;
  normalise(out);
  return true;
}

std::vector<int> lattice_degrees(int max_degree) {
  std::vector<int> degrees{1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128};
  std::erase_if(degrees, [&](int m) { return m > max_degree; });
  if (degrees.empty() || degrees.back() != max_degree) degrees.push_back(max_degree);
  return degrees;
}

}  // namespace

std::string IntegerPolynomial::pari(const std::string& variable) const {
  return pari_of(coefficients, variable);
}

int IntegerPolynomial::height_digits() const {
  std::size_t digits = 0;
  for (const auto& c : coefficients) digits = std::max(digits, c.size() - (c[0] == '-'));
  return static_cast<int>(digits);
}

std::string RationalPolynomial::pari(const std::string& variable) const {
  // Over the common denominator, "(N(t))/D": the coordinates and stresses of a large field share
  // most of their denominators, which written per coefficient were half of a certificate.
  FmpqPoly q;
  flint::fmpq_poly_from_strings(q.value, coefficients);
  if (fmpz_is_one(fmpq_poly_denref(q.value))) return pari_of(coefficients, variable);
  FmpzPoly numerator;
  fmpq_poly_get_numerator(numerator.value, q.value);
  const std::string over =
      pari_of(flint::strings_from_poly(numerator.value).coefficients, variable);
  char* den = fmpz_get_str(nullptr, 10, fmpq_poly_denref(q.value));
  std::string out = fmt::format("({})/{}", over, den);
  flint_free(den);
  return out;
}

MinimalPolynomial minimal_polynomial(const std::string& value, int digits, int max_degree) {
  if (digits < 20) throw std::invalid_argument("minimal_polynomial: at least 20 digits");
  if (max_degree < 1) throw std::invalid_argument("minimal_polynomial: max_degree >= 1");
  Arb x2;
  flint::set_decimal(x2.value, value, 2 * digits, flint::bits_for(2 * digits));
  return flint::minimal_polynomial_of_ball(x2.value, digits, max_degree);
}

void flint::round_ball(arb_t x, const arb_t x2, int digits) {
  const slong prec = bits_for(digits);
  arb_set_round(x, x2, prec);
  Arb unit, size;
  arb_set_str(unit.value, fmt::format("1e-{}", digits - 1).c_str(), prec);
  arb_abs(size.value, x);
  arb_mul(unit.value, unit.value, size.value, prec);
  arb_add_error(x, unit.value);
}

MinimalPolynomial flint::minimal_polynomial_of_ball(const arb_t x2, int digits, int max_degree) {
  MinimalPolynomial result;
  const int doubled = 2 * digits;
  const slong prec = flint::bits_for(digits), prec2 = flint::bits_for(doubled);
  // The first D digits: the value rounded there (the ball's radius covers it).
  Arb x;
  round_ball(x.value, x2, digits);
  const int scale = digits - 10;
  FmpzPoly factor;
  for (int m : lattice_degrees(max_degree)) {
    const Powers powers(x.value, m, prec);
    double used = 0;
    const auto relation = flint::integer_relation(powers.pointers(), scale, prec, used);
    // A relation that uses (nearly) all the digits is what LLL returns when there is none.
    if (!relation || used > 0.9 * scale) continue;
    // Doubled precision: the factor vanishes at the value to 2D digits (its ball contains 0, the
    // other factors' balls exclude it). A relation fitted to D digits that is not a true one
    // misses by about 10^-D there.
    if (!vanishing_factor(factor.value, *relation, x2, prec2)) continue;
    const int degree = static_cast<int>(fmpz_poly_degree(factor.value));
    // Irreducible over Q: the factorisation of the factor has one factor of multiplicity 1.
    fmpz_poly_factor_t check;
    fmpz_poly_factor_init(check);
    fmpz_poly_factor(check, factor.value);
    const bool irreducible = check->num == 1 && check->exp[0] == 1;
    fmpz_poly_factor_clear(check);
    if (!irreducible) continue;
    const auto root = flint::isolate_root(factor.value, x2, std::min(digits / 2, 200), prec2);
    if (!root) {
      result.reason = "the root could not be isolated";
      return result;
    }
    result.found = true;
    result.polynomial = flint::strings_from_poly(factor.value);
    result.root = *root;
    result.lattice_degree = m;
    result.digits = digits;
    result.confirmed_digits = doubled;
    result.relation_digits = (degree + 1.0) * result.polynomial.height_digits();
    return result;
  }
  result.reason = fmt::format("no relation of degree <= {} at {} digits", max_degree, digits);
  return result;
}

}  // namespace tripack::exact
