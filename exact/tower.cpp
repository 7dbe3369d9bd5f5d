#include "exact/tower.hpp"

#include <string>

namespace tripack::exact {

using flint::Fmpq;
using flint::FmpqPoly;
using flint::FmpzPoly;

Tower::Tower(const fmpz_poly_t p, int j) : j_(j) {
  fmpq_poly_set_fmpz_poly(p_.value, p);
  m_ = static_cast<int>(fmpz_poly_degree(p));
}

void Tower::times_theta(TowerElement& out, const TowerElement& x) const {
  FmpqPoly a, b, t;
  // (a + b s)(d + j s) = (a d + 3 j b) + (b d + j a) s
  fmpq_poly_shift_left(a.value, x.a.value, 1);
  fmpq_poly_scalar_mul_si(t.value, x.b.value, 3 * j_);
  fmpq_poly_add(a.value, a.value, t.value);
  fmpq_poly_shift_left(b.value, x.b.value, 1);
  fmpq_poly_scalar_mul_si(t.value, x.a.value, j_);
  fmpq_poly_add(b.value, b.value, t.value);
  fmpq_poly_rem(out.a.value, a.value, p_.value);
  fmpq_poly_rem(out.b.value, b.value, p_.value);
}

void Tower::coordinate(fmpq_t out, const TowerElement& x, int r) const {
  if (r < m_)
    fmpq_poly_get_coeff_fmpq(out, x.a.value, r);
  else
    fmpq_poly_get_coeff_fmpq(out, x.b.value, r - m_);
}

void Tower::from_power_basis(TowerElement& out, const fmpq_poly_t e) const {
  TowerElement acc;
  Fmpq c;
  FmpqPoly constant;
  for (slong k = fmpq_poly_degree(e); k >= 0; --k) {
    times_theta(acc, acc);
    fmpq_poly_get_coeff_fmpq(c.value, e, k);
    fmpq_poly_set_fmpq(constant.value, c.value);
    fmpq_poly_add(acc.a.value, acc.a.value, constant.value);
  }
  fmpq_poly_swap(out.a.value, acc.a.value);
  fmpq_poly_swap(out.b.value, acc.b.value);
}

std::optional<int> tower_generator(const IntegerPolynomial& p, const ExactConfiguration& c) {
  if (c.field.degree() != 2 * p.degree()) return std::nullopt;
  FmpqPoly t, d, s, u, js;
  fmpq_poly_set_coeff_si(t.value, 1, 1);
  flint::fmpq_poly_from_strings(d.value, c.d_in_field.coefficients);
  flint::fmpq_poly_from_strings(s.value, c.sqrt3_in_field.coefficients);
  fmpq_poly_sub(u.value, t.value, d.value);  // j sqrt 3 when t = d + j sqrt 3
  for (int j = 1; j <= 5; ++j) {
    fmpq_poly_scalar_mul_si(js.value, s.value, j);
    if (fmpq_poly_equal(js.value, u.value)) return j;
  }
  return std::nullopt;
}

std::vector<TowerForm> tower_forms(const IntegerPolynomial& p, int j,
                                   const std::vector<const RationalPolynomial*>& elements) {
  FmpzPoly pz;
  flint::poly_from_strings(pz.value, p.coefficients);
  const Tower tower(pz.value, j);
  std::vector<TowerForm> out;
  FmpqPoly e;
  for (const RationalPolynomial* element : elements) {
    flint::fmpq_poly_from_strings(e.value, element->coefficients);
    TowerElement x;
    tower.from_power_basis(x, e.value);
    out.push_back(
        {flint::strings_from_fmpq_poly(x.a.value), flint::strings_from_fmpq_poly(x.b.value)});
  }
  return out;
}

void make_primitive(std::vector<TowerForm>& elements) {
  flint::Fmpz numerators, denominators;  // gcd of the numerators, lcm of the denominators
  FmpqPoly part;
  Fmpq content;
  for (const TowerForm& e : elements)
    for (const RationalPolynomial* q : {&e.a, &e.b}) {
      flint::fmpq_poly_from_strings(part.value, q->coefficients);
      fmpq_poly_content(content.value, part.value);
      fmpz_gcd(numerators.value, numerators.value, fmpq_numref(content.value));
      if (!fmpq_is_zero(content.value)) {
        if (fmpz_is_zero(denominators.value)) fmpz_one(denominators.value);
        fmpz_lcm(denominators.value, denominators.value, fmpq_denref(content.value));
      }
    }
  if (fmpz_is_zero(numerators.value)) return;  // every element is 0
  Fmpq factor;                                 // lcm / gcd > 0
  fmpq_set_fmpz_frac(factor.value, denominators.value, numerators.value);
  for (TowerForm& e : elements)
    for (RationalPolynomial* q : {&e.a, &e.b}) {
      flint::fmpq_poly_from_strings(part.value, q->coefficients);
      fmpq_poly_scalar_mul_fmpq(part.value, part.value, factor.value);
      *q = flint::strings_from_fmpq_poly(part.value);
    }
}

namespace {

// q (not 0) as [negative, "c*(A)"]: c > 0 its content, A = +-q / c primitive integral; a constant
// is its rational, and `factor` ("s") is written between c and (A).
std::pair<bool, std::string> factored(const RationalPolynomial& q, const std::string& factor) {
  FmpqPoly poly, primitive;
  flint::fmpq_poly_from_strings(poly.value, q.coefficients);
  Fmpq content;
  fmpq_poly_content(content.value, poly.value);
  fmpq_poly_scalar_div_fmpq(primitive.value, poly.value, content.value);
  const bool negative =
      fmpz_sgn(fmpq_poly_numref(primitive.value) + fmpq_poly_degree(primitive.value)) < 0;
  if (negative) fmpq_poly_neg(primitive.value, primitive.value);
  char* content_text = fmpq_get_str(nullptr, 10, content.value);
  const std::string c(content_text);
  flint_free(content_text);
  std::string text;
  if (fmpq_poly_degree(primitive.value) == 0) {  // a constant: primitive = 1
    text = factor.empty() ? c : (c == "1" ? factor : c + "*" + factor);
  } else {
    FmpzPoly integral;
    fmpq_poly_get_numerator(integral.value, primitive.value);
    std::string head = c == "1" ? "" : c + "*";
    if (!factor.empty()) head += factor + "*";
    text = head + "(" + flint::strings_from_poly(integral.value).pari("x") + ")";
  }
  return {negative, text};
}

bool is_zero(const RationalPolynomial& q) {
  return q.coefficients.size() == 1 && q.coefficients[0] == "0";
}

}  // namespace

std::string tower_pari(const TowerForm& element) {
  if (is_zero(element.a) && is_zero(element.b)) return "0";
  std::string out;
  if (!is_zero(element.a)) {
    const auto [negative, text] = factored(element.a, "");
    out = (negative ? "-" : "") + text;
  }
  if (!is_zero(element.b)) {
    const auto [negative, text] = factored(element.b, "s");
    if (out.empty())
      out = (negative ? "-" : "") + text;
    else
      out += (negative ? " - " : " + ") + text;
  }
  return out;
}

}  // namespace tripack::exact
