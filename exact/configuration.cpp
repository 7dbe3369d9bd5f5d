#include "exact/configuration.hpp"

#include <flint/fmpq_mat.h>
#include <flint/fmpz_poly.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>

#include "exact/flint_tools.hpp"
#include "exact/number_field.hpp"
#include "exact/tower.hpp"

namespace tripack::exact {

namespace {

using flint::Arb;
using flint::Fmpq;
using flint::FmpqPoly;
using flint::FmpzPoly;

using Balls = std::vector<std::unique_ptr<Arb>>;

Balls powers_of(const arb_t x, int count, slong prec) {
  Balls out;
  for (int i = 0; i < count; ++i) {
    out.push_back(std::make_unique<Arb>());
    arb_pow_ui(out.back()->value, x, static_cast<ulong>(i), prec);
  }
  return out;
}

// The value as a rational combination of a basis: value = -(c_1 b_1 + c_2 b_2 + ...) / c_0 from
// the integer relation among [value, b_1, b_2, ...]. basis(pass, prec) gives the basis balls of D
// digits (pass 0) or 2D (pass 1). The relation is looked for from 100, 200, 400, ... digits up to
// min(D, largest) (most coordinates need far fewer than D, and LLL's cost grows with the digits),
// and taken when it vanishes at the 2D-digit values (doubled precision: a relation fitted to fewer
// digits that is not a true one misses by about 10^-(its digits) there). No "few digits" rule
// beyond that: every element found is verified exactly afterwards (the identities in K), so a
// spurious relation can only fail, never prove.
//
// `values` are candidates tried in turn at each number of digits (each a D-digit and a 2D-digit
// ball): the value itself, and the value times P'(d), whose coefficients in the basis d^a are far
// smaller (docs/exact.md, "Coordinates"). The result names the candidate that gave it.
struct Combination {
  std::size_t candidate = 0;
  std::vector<std::string> coefficients;
};
using Candidates = std::vector<std::array<const arb_struct*, 2>>;

// `reduced`: the basis's reduced rows kept across calls with the same basis (flint::ReducedBasis),
// or none: each relation found by one LLL of its own.
std::optional<Combination> combination_of(const Candidates& values,
                                          const std::function<Balls(int, slong)>& basis, int digits,
                                          int largest, flint::ReducedBasis* reduced = nullptr) {
  const slong prec = flint::bits_for(digits), prec2 = flint::bits_for(2 * digits);
  const Balls balls = basis(0, prec), balls2 = basis(1, prec2);
  std::vector<int> ladder;
  for (int use = 100; use < std::min(digits, largest); use *= 2) ladder.push_back(use);
  if (largest >= digits) ladder.push_back(digits);
  std::optional<std::vector<std::string>> found;
  std::size_t which = 0;
  Arb sum, term;
  flint::Fmpz c;
  for (int use : ladder) {
    for (std::size_t v = 0; v < values.size() && !found; ++v) {
      std::vector<const arb_struct*> row{values[v][0]};
      for (const auto& b : balls) row.push_back(b->value);
      const int scale = use - 10;
      double used = 0;
      auto relation = reduced ? reduced->relation(values[v][0], {row.begin() + 1, row.end()}, scale,
                                                  flint::bits_for(use), used)
                              : flint::integer_relation(row, scale, flint::bits_for(use), used);
      if (!relation || relation->front() == "0" || used > 0.9 * scale) continue;
      arb_zero(sum.value);
      for (std::size_t i = 0; i < relation->size(); ++i) {
        fmpz_set_str(c.value, (*relation)[i].c_str(), 10);
        arb_mul_fmpz(term.value, i == 0 ? values[v][1] : balls2[i - 1]->value, c.value, prec2);
        arb_add(sum.value, sum.value, term.value, prec2);
      }
      if (!arb_contains_zero(sum.value)) continue;
      if (relation->front()[0] == '-')  // sign: c_0 > 0
        for (auto& e : *relation) e = e[0] == '-' ? e.substr(1) : (e == "0" ? e : "-" + e);
      found = relation;
      which = v;
    }
    if (found) break;
  }
  if (!found) return std::nullopt;
  const auto& coefficients = *found;
  std::vector<std::string> combination;
  Fmpq q;
  flint::Fmpz numerator, denominator;
  fmpz_set_str(denominator.value, coefficients[0].c_str(), 10);
  for (std::size_t i = 1; i < coefficients.size(); ++i) {
    fmpz_set_str(numerator.value, coefficients[i].c_str(), 10);
    fmpz_neg(numerator.value, numerator.value);
    fmpq_set_fmpz_frac(q.value, numerator.value, denominator.value);
    char* text = fmpq_get_str(nullptr, 10, q.value);
    combination.emplace_back(text);
    flint_free(text);
  }
  return Combination{which, std::move(combination)};
}

// The value as an element of Q(t): a combination of 1, t, ..., t^(k-1).
std::optional<RationalPolynomial> express_in_field(const arb_t value, const arb_t value2,
                                                   const arb_t t, const arb_t t2, int k, int digits,
                                                   int largest) {
  const auto combination = combination_of(
      {{value, value2}}, [&](int pass, slong prec) { return powers_of(pass ? t2 : t, k, prec); },
      digits, largest);
  if (!combination) return std::nullopt;
  return RationalPolynomial{combination->coefficients};
}

void decimal_to_fmpq(fmpq_t out, std::string text, int keep_digits) {
  // "0.1234...", "-0.5", "1", or with an exponent; fixed notation is what the polish writes.
  if (text.find_first_of("eE") != std::string::npos)
    throw std::invalid_argument("decimal_to_fmpq: fixed notation expected: " + text.substr(0, 30));
  bool negative = !text.empty() && text[0] == '-';
  if (negative || (!text.empty() && text[0] == '+')) text.erase(0, 1);
  const auto dot = text.find('.');
  std::string integer = dot == std::string::npos ? text : text.substr(0, dot);
  std::string fraction = dot == std::string::npos ? "" : text.substr(dot + 1);
  if (static_cast<int>(fraction.size()) > keep_digits)
    fraction.resize(static_cast<std::size_t>(keep_digits));
  flint::Fmpz numerator, denominator;
  const std::string digits = (integer.empty() ? "0" : integer) + fraction;
  if (fmpz_set_str(numerator.value, digits.c_str(), 10) != 0)
    throw std::invalid_argument("not a decimal: " + text.substr(0, 30));
  if (negative) fmpz_neg(numerator.value, numerator.value);
  fmpz_set_ui(denominator.value, 10);
  fmpz_pow_ui(denominator.value, denominator.value, fraction.size());
  fmpq_set_fmpz_frac(out, numerator.value, denominator.value);
}

double upper_bound(const arb_t x) {
  Arb a;
  arb_abs(a.value, x);
  arf_t bound;
  arf_init(bound);
  arb_get_ubound_arf(bound, a.value, 64);
  const double out = arf_get_d(bound, ARF_RND_UP);
  arf_clear(bound);
  return out;
}

double lower_bound(const arb_t x) {
  arf_t bound;
  arf_init(bound);
  arb_get_lbound_arf(bound, x, 64);
  const double out = arf_get_d(bound, ARF_RND_DOWN);
  arf_clear(bound);
  return out;
}

// The norm of d + j sqrt 3 over Q: N(x) = A^2 - 3 B^2 where P(x - j s) = A(x) + s B(x), s^2 = 3;
// its roots are d' +- j sqrt 3 over the roots d' of P. Primitive, positive leading coefficient.
void norm_polynomial(fmpz_poly_t out, const fmpz_poly_t p, int j) {
  FmpzPoly a, b, na, nb, x, term, acc_a, acc_b;
  fmpz_poly_one(a.value);  // (x - j s)^0
  fmpz_poly_set_coeff_si(x.value, 1, 1);
  for (slong k = 0; k <= fmpz_poly_degree(p); ++k) {
    const fmpz* c = fmpz_poly_get_coeff_ptr(p, k);
    if (c) {
      fmpz_poly_scalar_mul_fmpz(term.value, a.value, c);
      fmpz_poly_add(acc_a.value, acc_a.value, term.value);
      fmpz_poly_scalar_mul_fmpz(term.value, b.value, c);
      fmpz_poly_add(acc_b.value, acc_b.value, term.value);
    }
    // (A + s B)(x - j s) = (A x - 3 j B) + s (B x - j A)
    fmpz_poly_mul(na.value, a.value, x.value);
    fmpz_poly_scalar_mul_si(term.value, b.value, 3 * j);
    fmpz_poly_sub(na.value, na.value, term.value);
    fmpz_poly_mul(nb.value, b.value, x.value);
    fmpz_poly_scalar_mul_si(term.value, a.value, j);
    fmpz_poly_sub(nb.value, nb.value, term.value);
    fmpz_poly_swap(a.value, na.value);
    fmpz_poly_swap(b.value, nb.value);
  }
  fmpz_poly_sqr(out, acc_a.value);
  fmpz_poly_sqr(term.value, acc_b.value);
  fmpz_poly_scalar_mul_si(term.value, term.value, 3);
  fmpz_poly_sub(out, out, term.value);
  fmpz_poly_primitive_part(out, out);
  if (fmpz_sgn(fmpz_poly_lead(out)) < 0) fmpz_poly_neg(out, out);
}

bool irreducible(const fmpz_poly_t f) {
  fmpz_poly_factor_t factors;
  fmpz_poly_factor_init(factors);
  fmpz_poly_factor(factors, f);
  const bool one = factors->num == 1 && factors->exp[0] == 1;
  fmpz_poly_factor_clear(factors);
  return one;
}

// The tower's coordinates -> the power basis of t = d + j sqrt 3: the inverse of the matrix whose
// column i holds t^i's tower coordinates.
class BasisChange {
 public:
  BasisChange(const Tower& tower) : size_(2 * tower.m()) {
    fmpq_mat_init(to_t_, size_, size_);
    fmpq_mat_t powers;
    fmpq_mat_init(powers, size_, size_);
    TowerElement power;
    fmpq_poly_one(power.a.value);
    for (int i = 0; i < size_; ++i) {
      for (int r = 0; r < size_; ++r) tower.coordinate(fmpq_mat_entry(powers, r, i), power, r);
      tower.times_theta(power, power);
    }
    ok_ = fmpq_mat_inv(to_t_, powers) != 0;
    fmpq_mat_clear(powers);
  }
  ~BasisChange() { fmpq_mat_clear(to_t_); }
  BasisChange(const BasisChange&) = delete;
  BasisChange& operator=(const BasisChange&) = delete;
  bool ok() const { return ok_; }
  // The element with tower coordinates v (size 2m) as a polynomial in t.
  RationalPolynomial in_t(const std::vector<std::string>& v) const {
    fmpq_mat_t column, result;
    fmpq_mat_init(column, size_, 1);
    fmpq_mat_init(result, size_, 1);
    for (int r = 0; r < size_; ++r)
      fmpq_set_str(fmpq_mat_entry(column, r, 0), v[static_cast<std::size_t>(r)].c_str(), 10);
    fmpq_mat_mul(result, to_t_, column);
    FmpqPoly poly;
    for (int r = 0; r < size_; ++r)
      fmpq_poly_set_coeff_fmpq(poly.value, r, fmpq_mat_entry(result, r, 0));
    fmpq_mat_clear(column);
    fmpq_mat_clear(result);
    return flint::strings_from_fmpq_poly(poly.value);
  }

 private:
  int size_;
  fmpq_mat_t to_t_;
  bool ok_ = false;
};

// The disks in breadth-first order along the bonds, from each component's first disk: a
// coordinate is first looked for as a bonded neighbour's plus a small difference.
std::vector<int> breadth_first_order(int n, const std::vector<std::vector<int>>& neighbours) {
  std::vector<int> order;
  std::vector<char> seen(static_cast<std::size_t>(n), 0);
  for (int root = 0; root < n; ++root) {
    if (seen[static_cast<std::size_t>(root)]) continue;
    seen[static_cast<std::size_t>(root)] = 1;
    for (std::size_t tail = (order.push_back(root), order.size() - 1); tail < order.size(); ++tail)
      for (int j : neighbours[static_cast<std::size_t>(order[tail])])
        if (!seen[static_cast<std::size_t>(j)]) {
          seen[static_cast<std::size_t>(j)] = 1;
          order.push_back(j);
        }
  }
  return order;
}

// Every coordinate as an element of the current field (rattlers: rationals).
using FoundCoordinates = std::vector<std::array<RationalPolynomial, 2>>;

// t0 isolated far more narrowly than d's interval, so that d_in_K(t0), a root of P (checked
// exactly below), is proven to be the root in d's interval. Empty, or why not.
std::string isolate_embedding(ExactConfiguration& out, const arb_t t2, int digits, slong prec2) {
  FmpzPoly kpoly;
  flint::poly_from_strings(kpoly.value, out.field.coefficients);
  const auto narrow = flint::isolate_root(kpoly.value, t2, 2 * digits - 30, prec2);
  if (!narrow) {
    return "the field's root could not be isolated";
  }
  out.embedding = *narrow;
  return "";
}

// Exact: P(d) = 0 and sqrt3^2 = 3 in K. Empty, or why not.
std::string check_field_identities(const ExactConfiguration& out, const flint::Field& field,
                                   const MinimalPolynomial& d_poly) {
  const int m = d_poly.polynomial.degree();
  FmpqPoly dk, value, power, term, s3;
  field.set(dk.value, out.d_in_field);
  fmpq_poly_zero(value.value);
  fmpq_poly_one(power.value);
  Fmpq c;
  for (slong i = 0; i <= m; ++i) {
    fmpq_set_str(c.value, d_poly.polynomial.coefficients[static_cast<std::size_t>(i)].c_str(), 10);
    fmpq_poly_scalar_mul_fmpq(term.value, power.value, c.value);
    fmpq_poly_add(value.value, value.value, term.value);
    field.mul(power.value, power.value, dk.value);
  }
  if (!field.is_zero(value.value)) {
    return "P(d) is not 0 in the field";
  }
  field.set(s3.value, out.sqrt3_in_field);
  field.mul(s3.value, s3.value, s3.value);
  Fmpq three;
  fmpq_set_si(three.value, 3, 1);
  fmpq_poly_sub_fmpq(s3.value, s3.value, three.value);
  if (!field.is_zero(s3.value)) {
    return "sqrt(3)^2 is not 3 in the field";
  }
  return "";
}

// Every bond as an identity in K. Empty, or why not.
std::string check_bonds_exact(const ExactConfiguration& out, const flint::Field& field,
                              const ConfigurationInput& in, const std::set<int>& rattlers) {
  FmpqPoly dk, s3, xa, ya, xb, yb, dx, dy, e, f;
  field.set(dk.value, out.d_in_field);
  field.set(s3.value, out.sqrt3_in_field);
  for (const Bond& b : in.bonds) {
    if (rattlers.count(b.a) || (!b.is_wall() && rattlers.count(b.b))) {
      return fmt::format("a bond of rattler {}", b.a + 1);
    }
    field.set(xa.value, out.points[static_cast<std::size_t>(b.a)][0]);
    field.set(ya.value, out.points[static_cast<std::size_t>(b.a)][1]);
    if (b.is_wall()) {
      switch (b.side()) {
        case Side::Bottom:
          fmpq_poly_set(e.value, ya.value);
          break;
        case Side::Left:  // sqrt3 x - y
          field.mul(e.value, s3.value, xa.value);
          fmpq_poly_sub(e.value, e.value, ya.value);
          break;
        case Side::Right:  // sqrt3 (1 - x) - y
          fmpq_poly_one(f.value);
          fmpq_poly_sub(f.value, f.value, xa.value);
          field.mul(e.value, s3.value, f.value);
          fmpq_poly_sub(e.value, e.value, ya.value);
          break;
      }
    } else {
      field.set(xb.value, out.points[static_cast<std::size_t>(b.b)][0]);
      field.set(yb.value, out.points[static_cast<std::size_t>(b.b)][1]);
      fmpq_poly_sub(dx.value, xa.value, xb.value);
      fmpq_poly_sub(dy.value, ya.value, yb.value);
      field.mul(e.value, dx.value, dx.value);
      field.mul(f.value, dy.value, dy.value);
      fmpq_poly_add(e.value, e.value, f.value);
      field.mul(f.value, dk.value, dk.value);
      fmpq_poly_sub(e.value, e.value, f.value);
    }
    if (!field.is_zero(e.value)) {
      return b.is_wall()
                 ? fmt::format("the wall bond of point {} is not exact in the field", b.a + 1)
                 : fmt::format("the bond {}-{} is not exact in the field", b.a + 1, b.b + 1);
    }
  }
  return "";
}

// At the real embedding, in ball arithmetic: sqrt3 > 0 there, d in P's interval, the exact
// points near the given ones, every non-bond strictly apart, every centre inside; the offset and
// margin go to `out`. Empty, or why not.
std::string check_at_embedding(ExactConfiguration& out, const ConfigurationInput& in,
                               const MinimalPolynomial& d_poly, slong prec2) {
  Arb t0;
  flint::ball_of(t0.value, out.embedding, prec2);
  auto evaluate = [&](arb_t result, const RationalPolynomial& element) {
    FmpqPoly q;
    flint::fmpq_poly_from_strings(q.value, element.coefficients);
    flint::ArbPoly a;
    arb_poly_set_fmpq_poly(a.value, q.value, prec2);
    arb_poly_evaluate(result, a.value, t0.value, prec2);
  };
  Arb dv, sv, interval;
  evaluate(dv.value, out.d_in_field);
  evaluate(sv.value, out.sqrt3_in_field);
  flint::ball_of(interval.value, d_poly.root, prec2);
  if (!arb_is_positive(sv.value) || !arb_contains(interval.value, dv.value)) {
    return "the embedding does not give +sqrt(3) and d in its interval";
  }
  std::vector<std::array<std::unique_ptr<Arb>, 2>> at(static_cast<std::size_t>(in.n));
  Arb given, diff;
  for (int i = 0; i < in.n; ++i)
    for (int c = 0; c < 2; ++c) {
      auto& slot = at[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)];
      slot = std::make_unique<Arb>();
      evaluate(slot->value, out.points[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)]);
      flint::set_decimal(given.value,
                         in.given[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)], 30,
                         prec2);
      arb_get_mid_arb(given.value, given.value);  // the given point itself, exactly
      arb_sub(diff.value, slot->value, given.value, prec2);
      out.largest_offset = std::max(out.largest_offset, upper_bound(diff.value));
    }
  std::set<std::pair<int, int>> bonded;
  for (const Bond& b : in.bonds) bonded.insert({b.a, b.b});
  out.smallest_margin = INFINITY;
  Arb dx, dy, r, dd;
  arb_mul(dd.value, dv.value, dv.value, prec2);
  for (int i = 0; i < in.n; ++i) {
    const auto& xi = at[static_cast<std::size_t>(i)];
    for (int j = i + 1; j < in.n; ++j) {
      if (bonded.count({i, j})) continue;
      const auto& xj = at[static_cast<std::size_t>(j)];
      arb_sub(dx.value, xi[0]->value, xj[0]->value, prec2);
      arb_sub(dy.value, xi[1]->value, xj[1]->value, prec2);
      arb_mul(dx.value, dx.value, dx.value, prec2);
      arb_addmul(dx.value, dy.value, dy.value, prec2);
      arb_sub(r.value, dx.value, dd.value, prec2);  // |pi - pj|^2 - d^2
      if (!arb_is_positive(r.value)) {
        return fmt::format("points {} and {} are not proven farther apart than d", i + 1, j + 1);
      }
      arb_div(r.value, r.value, dd.value, prec2);
      out.smallest_margin = std::min(out.smallest_margin, lower_bound(r.value) / 2);
    }
    for (const Side side : kSides) {
      if (bonded.count({i, -1 - static_cast<int>(side)})) continue;
      if (side == Side::Bottom) {
        arb_set(r.value, xi[1]->value);
      } else {
        arb_one(dx.value);
        if (side == Side::Left)
          arb_set(dx.value, xi[0]->value);
        else
          arb_sub(dx.value, dx.value, xi[0]->value, prec2);
        arb_mul(r.value, sv.value, dx.value, prec2);
        arb_sub(r.value, r.value, xi[1]->value, prec2);
      }
      if (!arb_is_positive(r.value)) {
        return fmt::format("point {} is not proven inside the {} side", i + 1, side_name(side));
      }
      arb_div(r.value, r.value, dv.value, prec2);
      out.smallest_margin = std::min(out.smallest_margin, lower_bound(r.value));
    }
  }
  if (!(out.largest_offset < 1e-25)) {
    return fmt::format("the exact points lie {:.2g} from the given ones (10^-25 asked)",
                       out.largest_offset);
  }
  return "";
}

// d and sqrt(3) as balls of D digits (d, s) and of 2D digits (d2, s2): the two passes of
// combination_of. p: d's minimal polynomial P, of degree m.
struct Generators {
  Generators(const ConfigurationInput& in, const MinimalPolynomial& d_poly)
      : digits(in.digits),
        prec(flint::bits_for(digits)),
        prec2(flint::bits_for(2 * digits)),
        m(d_poly.polynomial.degree()) {
    flint::set_decimal(d2.value, in.d, 2 * digits, prec2);
    flint::round_ball(d.value, d2.value, digits);
    arb_sqrt_ui(s2.value, 3, prec2);
    arb_sqrt_ui(s.value, 3, prec);
    flint::poly_from_strings(p.value, d_poly.polynomial.coefficients);
  }
  const int digits;
  const slong prec, prec2;
  const int m;
  Arb d2, d, s2, s;
  FmpzPoly p;
};

// The field K0 = Q(d, sqrt 3): its generator t (balls of D and 2D digits) and degree k (0 when
// none was found). When K0 is not Q(d), the tower Q(d)(sqrt 3) in which its elements are looked
// for, and the exact change from the tower's basis to t's powers.
struct BaseField {
  Arb t, t2;
  int k = 0;
  std::unique_ptr<Tower> tower;
  std::unique_ptr<BasisChange> to_t;
};

// K0 = Q(d) when an integer relation puts sqrt(3) there: out's field, embedding, d and sqrt 3 in
// it. False when there is none.
bool sqrt3_in_q_of_d(BaseField& k0, ExactConfiguration& out, const Generators& g,
                     const MinimalPolynomial& d_poly) {
  if (g.m <= 1) return false;
  const auto sqrt3 =
      express_in_field(g.s.value, g.s2.value, g.d.value, g.d2.value, g.m, g.digits, g.digits);
  if (!sqrt3) return false;
  out.field = d_poly.polynomial;
  out.embedding = d_poly.root;
  out.d_in_field = RationalPolynomial{{"0", "1"}};
  out.sqrt3_in_field = *sqrt3;
  arb_set(k0.t.value, g.d.value);
  arb_set(k0.t2.value, g.d2.value);
  k0.k = g.m;
  return true;
}

// K0 = Q(d, sqrt 3) of degree 2m, generated by t = d + j sqrt 3 for the first j whose norm
// polynomial (exact) is irreducible: out's field, d and sqrt 3 in it (their tower coordinates
// converted exactly to powers of t). k0.k stays 0 when no j <= 5 gives one.
void tower_field(BaseField& k0, ExactConfiguration& out, const Generators& g,
                 const MinimalPolynomial& d_poly) {
  const int m = g.m;
  for (int j = 1; j <= 5 && k0.k == 0; ++j) {
    FmpzPoly norm;
    norm_polynomial(norm.value, g.p.value, j);
    if (fmpz_poly_degree(norm.value) != 2 * m || !irreducible(norm.value)) continue;
    k0.tower = std::make_unique<Tower>(g.p.value, j);
    k0.to_t = std::make_unique<BasisChange>(*k0.tower);
    if (!k0.to_t->ok()) continue;
    arb_mul_ui(k0.t2.value, g.s2.value, static_cast<ulong>(j), g.prec2);
    arb_add(k0.t2.value, k0.t2.value, g.d2.value, g.prec2);
    flint::round_ball(k0.t.value, k0.t2.value, g.digits);
    out.field = flint::strings_from_poly(norm.value);
    out.embedding = d_poly.root;  // replaced by t0's interval later (isolate_embedding)
    std::vector<std::string> d_tower(static_cast<std::size_t>(2 * m), "0"), s_tower = d_tower;
    if (m == 1) {  // d rational: its tower coordinate is d itself
      FmpqPoly reduced, x;
      fmpq_poly_set_coeff_si(x.value, 1, 1);
      FmpqPoly pq;
      fmpq_poly_set_fmpz_poly(pq.value, g.p.value);
      fmpq_poly_rem(reduced.value, x.value, pq.value);
      d_tower[0] = flint::strings_from_fmpq_poly(reduced.value).coefficients[0];
    } else {
      d_tower[1] = "1";
    }
    s_tower[static_cast<std::size_t>(m)] = "1";
    out.d_in_field = k0.to_t->in_t(d_tower);
    out.sqrt3_in_field = k0.to_t->in_t(s_tower);
    k0.k = 2 * m;
  }
}

RationalPolynomial sum_of(const RationalPolynomial& a, const RationalPolynomial& b) {
  FmpqPoly x, y;
  flint::fmpq_poly_from_strings(x.value, a.coefficients);
  flint::fmpq_poly_from_strings(y.value, b.coefficients);
  fmpq_poly_add(x.value, x.value, y.value);
  return flint::strings_from_fmpq_poly(x.value);
}

// e(s) for s in Q[theta]/(field): Horner, reduced modulo the field at each step.
RationalPolynomial composed(const RationalPolynomial& e, const RationalPolynomial& s,
                            const IntegerPolynomial& field) {
  const flint::Field f(field);
  FmpqPoly acc, sp, term;
  f.set(sp.value, s);
  Fmpq c;
  for (std::size_t i = e.coefficients.size(); i-- > 0;) {
    f.mul(acc.value, acc.value, sp.value);
    fmpq_set_str(c.value, e.coefficients[i].c_str(), 10);
    fmpq_poly_set_fmpq(term.value, c.value);
    fmpq_poly_add(acc.value, acc.value, term.value);
  }
  return flint::strings_from_fmpq_poly(acc.value);
}

// Finds coordinates in K0 by integer relations, and in K0 or beyond it through their minimal
// polynomials (by_minimal_polynomial).
class CoordinateSearch {
 public:
  CoordinateSearch(const Generators& g, const BaseField& k0, const MinimalPolynomial& d_poly,
                   const IntegerPolynomial& k0_field)
      : g_(g), k0_(k0), q_of_d_(d_poly.polynomial), p_(d_poly.polynomial), k0_field_(k0_field) {
    // mu = P'(d): an element v of K0 is also looked for as v mu, whose coefficients in d^a (and
    // sqrt3 d^a) have far fewer digits (for an algebraic integer d, mu times the ring of integers
    // lies in Z[d]; t39a's x_1: 16 digits against 56, docs/exact.md), and then divided by mu
    // exactly in Q[d]/(P).
    if (g.m > 1) {
      FmpzPoly derivative;
      fmpz_poly_derivative(derivative.value, g.p.value);
      FmpqPoly dq;
      fmpq_poly_set_fmpz_poly(dq.value, derivative.value);
      scaled_ = q_of_d_.inverse(mu_inverse_.value, dq.value);
      arb_fmpz_poly_evaluate_arb(mu_.value, derivative.value, g.d.value, g.prec);
      arb_fmpz_poly_evaluate_arb(mu2_.value, derivative.value, g.d2.value, g.prec2);
    }
  }

  // v in K0, from at most `largest` digits. In the tower, Q(d) and sqrt3 Q(d) are tried first
  // (half the lattice dimension, so about half the digits and a sixteenth of LLL's time): along
  // lattice directions and walls, x is in Q(d) and y in sqrt3 Q(d); only the other coordinates
  // need the whole basis.
  std::optional<RationalPolynomial> in_k0(const arb_t v, const arb_t v2, int largest) {
    const int m = g_.m;
    for (int half = 0; k0_.tower && half < 2; ++half) {
      const auto c = combination_of(
          candidates(v, v2), [&](int pass, slong p) { return k0_basis(pass, p, half); }, g_.digits,
          largest, &k0_half_[half]);
      if (!c) continue;
      std::vector<std::string> e(static_cast<std::size_t>(2 * m), "0");
      std::copy(c->coefficients.begin(), c->coefficients.end(),
                e.begin() + static_cast<std::ptrdiff_t>(half * m));
      return k0_of(c->candidate == 1 ? unscaled(e) : e);
    }
    const auto c = combination_of(
        candidates(v, v2), [&](int pass, slong p) { return k0_basis(pass, p); }, g_.digits, largest,
        &k0_full_);
    if (!c) return std::nullopt;
    return k0_of(c->candidate == 1 ? unscaled(c->coefficients) : c->coefficients);
  }

  // v in the current field K as a root of its minimal polynomial over Q (PARI's nfroots), for a
  // coordinate whose coefficients in K0's basis have more digits than a relation can find at D
  // digits (t126a's x_51: 108 digits in d's powers, its minimal polynomial over Q 33;
  // docs/exact.md, "Coordinates"). The smallest field first: Q(d) (also for v / sqrt 3 in the
  // tower), then K0, then K beyond K0. When v's minimal polynomial has no root in K, K becomes
  // K(v) = K[w]/(f), f its irreducible factor over K that vanishes at v (PARI's nffactor and
  // rnfequation), and `extended` is set: the elements found before are then `mapped` into it.
  std::optional<RationalPolynomial> by_minimal_polynomial(const arb_t v2, bool& extended) {
    extended = false;
    const int m = g_.m;
    // Degree <= [K:Q] when v is in K; up to twice that (at least 16) for a v outside it.
    const auto minimal =
        minimal_polynomial_of(v2, std::min(std::max(2 * degree(), 16), kLargestDegree));
    if (!minimal) return std::nullopt;
    if (minimal->degree() <= m) {
      if (const auto r = matching_root(v2, p_, g_.d2.value, *minimal)) return in_q_of_d(*r, 0);
    }
    if (k0_.tower) {
      Arb scaled;
      arb_div(scaled.value, v2, g_.s2.value, g_.prec2);
      if (const auto over = minimal_polynomial_of(scaled.value, m)) {
        if (const auto r = matching_root(scaled.value, p_, g_.d2.value, *over))
          return in_q_of_d(*r, 1);
      }
      if (minimal->degree() <= k0_.k) {
        if (const auto r = matching_root(v2, k0_field_, k0_.t2.value, *minimal))
          return to_current(*r);
      }
    }
    if (beyond_) {
      if (const auto r = matching_root(v2, beyond_->field, beyond_->theta2.value, *minimal))
        return r;
    }
    return extend_by_factor(v2, *minimal, extended);
  }

  // Beyond K0 (by_minimal_polynomial): the current field, an element of K0 in it, an element of
  // the field before the last extension in it.
  bool beyond() const { return beyond_ != nullptr; }
  const IntegerPolynomial& beyond_field() const { return beyond_->field; }
  const arb_struct* beyond_theta2() const { return beyond_->theta2.value; }
  RationalPolynomial to_current(const RationalPolynomial& e) const {
    return beyond_ ? composed(e, beyond_->t, beyond_->field) : e;
  }
  RationalPolynomial mapped(const RationalPolynomial& e) const {
    return composed(e, last_map_, beyond_->field);
  }

 private:
  // K0's search basis (the tower's d^a, sqrt3 d^a, or t's powers). In the tower, `part` 0 gives
  // only d^a (Q(d)), 1 only sqrt3 d^a, -1 both.
  Balls k0_basis(int pass, slong p, int part = -1) const {
    const int m = g_.m;
    if (!k0_.tower) return powers_of(pass ? k0_.t2.value : k0_.t.value, k0_.k, p);
    Balls basis = powers_of(pass ? g_.d2.value : g_.d.value, m, p);
    if (part == 0) return basis;
    for (int i = 0; i < m; ++i) {
      basis.push_back(std::make_unique<Arb>());
      arb_mul(basis.back()->value, basis[static_cast<std::size_t>(i)]->value,
              pass ? g_.s2.value : g_.s.value, p);
    }
    if (part == 1) basis.erase(basis.begin(), basis.begin() + m);
    return basis;
  }

  // Coefficients in k0_basis as an element of K0 (a polynomial in t).
  RationalPolynomial k0_of(std::vector<std::string> coefficients) const {
    return k0_.tower ? k0_.to_t->in_t(coefficients) : RationalPolynomial{std::move(coefficients)};
  }

  // The K0 coefficients of v from those of v mu (tower: a_0..a_{m-1}, b_0..b_{m-1} in d; else
  // the powers of t = d).
  std::vector<std::string> unscaled(std::vector<std::string> coefficients) const {
    const int m = g_.m;
    const std::size_t parts = coefficients.size() / static_cast<std::size_t>(m);
    std::vector<std::string> out;
    for (std::size_t part = 0; part < parts; ++part) {
      const auto first = coefficients.begin() + static_cast<std::ptrdiff_t>(part * m);
      FmpqPoly a;
      flint::fmpq_poly_from_strings(a.value, {first, first + m});
      q_of_d_.mul(a.value, a.value, mu_inverse_.value);
      auto c = flint::strings_from_fmpq_poly(a.value).coefficients;
      c.resize(static_cast<std::size_t>(m), "0");
      out.insert(out.end(), c.begin(), c.end());
    }
    return out;
  }

  // The minimal polynomial over Q of v (degree <= `largest`), found from 250, 500, ... up to D
  // digits and confirmed from twice as many.
  std::optional<IntegerPolynomial> minimal_polynomial_of(const arb_t v2, int largest) const {
    for (int use = std::min(250, g_.digits);; use = std::min(2 * use, g_.digits)) {
      const auto found = flint::minimal_polynomial_of_ball(v2, use, largest);
      if (found.found) return found.polynomial;
      if (use == g_.digits) return std::nullopt;
    }
  }

  // The root in Q[t]/(field) of `minimal` whose value at the generator's ball t2 is v: the only
  // one whose ball meets v's.
  std::optional<RationalPolynomial> matching_root(const arb_t v2, const IntegerPolynomial& field,
                                                  const arb_t t2,
                                                  const IntegerPolynomial& minimal) const {
    std::vector<RationalPolynomial> roots;
    try {
      roots = pari::roots_in_field(field, minimal);
    } catch (const pari::Error&) {
      return std::nullopt;
    }
    std::optional<RationalPolynomial> match;
    Arb value;
    for (const auto& root : roots) {
      value_at(value.value, root, t2);
      arb_sub(value.value, value.value, v2, g_.prec2);
      if (!arb_contains_zero(value.value)) continue;
      if (match) return std::nullopt;  // two roots meet v: not decided
      match = root;
    }
    return match;
  }

  void value_at(arb_t out, const RationalPolynomial& e, const arb_t t2) const {
    FmpqPoly q;
    flint::fmpq_poly_from_strings(q.value, e.coefficients);
    flint::Field::evaluate(out, q.value, t2, g_.prec2);
  }

  // r in Q(d) (P's powers) as an element of the current field, times sqrt 3 when `part` is 1.
  RationalPolynomial in_q_of_d(const RationalPolynomial& r, int part) const {
    if (!k0_.tower) return to_current(r);
    const int m = g_.m;
    std::vector<std::string> e(static_cast<std::size_t>(2 * m), "0");
    std::copy(r.coefficients.begin(), r.coefficients.end(),
              e.begin() + static_cast<std::ptrdiff_t>(part * m));
    return to_current(k0_of(e));
  }

  // K(v) = K[w]/(f) for the irreducible factor f over the current field K of v's minimal
  // polynomial that vanishes at v; v = w there.
  std::optional<RationalPolynomial> extend_by_factor(const arb_t v2,
                                                     const IntegerPolynomial& minimal,
                                                     bool& extended) {
    const IntegerPolynomial& field = beyond_ ? beyond_->field : k0_field_;
    const arb_struct* theta2 = beyond_ ? beyond_->theta2.value : k0_.t2.value;
    std::vector<std::vector<RationalPolynomial>> factors;
    try {
      factors = pari::factors_over_field(field, minimal);
    } catch (const pari::Error&) {
      return std::nullopt;
    }
    const std::vector<RationalPolynomial>* vanishing = nullptr;
    Arb value, c;
    for (const auto& f : factors) {
      arb_zero(value.value);  // f(v) by Horner, its coefficients at the generator's ball
      for (std::size_t i = f.size(); i-- > 0;) {
        arb_mul(value.value, value.value, v2, g_.prec2);
        value_at(c.value, f[i], theta2);
        arb_add(value.value, value.value, c.value, g_.prec2);
      }
      if (!arb_contains_zero(value.value)) continue;
      if (vanishing) return std::nullopt;  // two factors vanish at v: not decided
      vanishing = &f;
    }
    if (!vanishing || vanishing->size() < 3) return std::nullopt;
    const int next_degree = degree() * static_cast<int>(vanishing->size() - 1);
    if (next_degree > kLargestField) return std::nullopt;
    pari::Extension e;
    try {
      e = pari::extend_field(field, *vanishing);
    } catch (const pari::Error&) {
      return std::nullopt;
    }
    auto next = std::make_unique<Beyond>();
    next->field = e.field;
    flint::Fmpz shift;
    fmpz_set_str(shift.value, e.shift.c_str(), 10);
    arb_mul_fmpz(next->theta2.value, theta2, shift.value, g_.prec2);  // theta = w + shift t
    arb_add(next->theta2.value, next->theta2.value, v2, g_.prec2);
    next->t = beyond_ ? composed(beyond_->t, e.t, e.field) : e.t;
    last_map_ = e.t;
    beyond_ = std::move(next);
    extended = true;
    return e.w;
  }

  int degree() const { return beyond_ ? beyond_->field.degree() : k0_.k; }

  // The candidates for v: itself, and v mu when P'(d) is invertible (always, P irreducible).
  Candidates candidates(const arb_t v, const arb_t v2) {
    Candidates c{{v, v2}};
    if (scaled_) {
      arb_mul(vm_.value, v, mu_.value, g_.prec);
      arb_mul(vm2_.value, v2, mu2_.value, g_.prec2);
      c.push_back({vm_.value, vm2_.value});
    }
    return c;
  }

  const Generators& g_;
  const BaseField& k0_;
  const flint::Field q_of_d_;
  const IntegerPolynomial p_, k0_field_;  // P, and K0's polynomial in t
  // Minimal polynomials of coordinates up to this degree; fields beyond K0 up to this one.
  static constexpr int kLargestDegree = 128, kLargestField = 256;
  // Beyond K0: the current field, its generator's ball (2D digits) and K0's t in it.
  struct Beyond {
    IntegerPolynomial field;
    Arb theta2;
    RationalPolynomial t;
  };
  std::unique_ptr<Beyond> beyond_;
  RationalPolynomial last_map_;  // the generator before the last extension, in the current field
  FmpqPoly mu_inverse_;
  Arb mu_, mu2_;
  bool scaled_ = false;
  Arb vm_, vm2_;  // v mu, the second candidate
  // Each basis's reduced rows, kept for every coordinate looked for against it: Q(d) and
  // sqrt3 Q(d) in the tower, and the whole K0.
  flint::ReducedBasis k0_half_[2], k0_full_;
};

// A rattler's coordinate: its given centred place, as a rational of 40 digits.
RationalPolynomial rattler_coordinate(const std::string& text) {
  Fmpq q;
  decimal_to_fmpq(q.value, text, 40);
  char* qt = fmpq_get_str(nullptr, 10, q.value);
  RationalPolynomial e{{qt}};
  flint_free(qt);
  return e;
}

// Every coordinate in K (K0, or a field beyond it once a coordinate needs one), rattlers at their
// given centred place. The disks are taken in breadth-first order along the bonds, and a
// coordinate is first looked for as a bonded neighbour's plus a difference in K0 found from at
// most 200 digits: in lattice-like packings most differences are d/2, sqrt(3) d/2 and the like,
// of small height, while the coordinates themselves may need 1,000s of digits (FLINT's LLL time
// grows with them). Then by a relation in K0's basis, then through the coordinate's minimal
// polynomial. Empty, or why not.
std::string find_coordinates(FoundCoordinates& found, CoordinateSearch& search,
                             const ConfigurationInput& in, const Generators& g,
                             const std::set<int>& rattlers, int k) {
  std::vector<std::vector<int>> neighbours(static_cast<std::size_t>(in.n));
  for (const Bond& b : in.bonds)
    if (!b.is_wall()) {
      neighbours[static_cast<std::size_t>(b.a)].push_back(b.b);
      neighbours[static_cast<std::size_t>(b.b)].push_back(b.a);
    }
  // The found coordinates' balls (D and 2D digits), for their neighbours' differences.
  std::vector<std::array<std::unique_ptr<Arb>, 4>> balls(static_cast<std::size_t>(in.n));
  for (int i : breadth_first_order(in.n, neighbours))
    for (int c = 0; c < 2; ++c) {
      const auto iu = static_cast<std::size_t>(i), cu = static_cast<std::size_t>(c);
      const std::string& text = in.points[iu][cu];
      if (rattlers.count(i)) {
        found[iu][cu] = rattler_coordinate(text);
        continue;
      }
      auto v = std::make_unique<Arb>(), v2 = std::make_unique<Arb>();
      flint::set_decimal(v2->value, text, 2 * g.digits, g.prec2);
      flint::round_ball(v->value, v2->value, g.digits);
      std::optional<RationalPolynomial> element;
      Arb diff, diff2;
      for (int j : neighbours[iu]) {
        const auto& known = balls[static_cast<std::size_t>(j)];
        if (!known[2 * cu]) continue;
        arb_sub(diff.value, v->value, known[2 * cu]->value, g.prec);
        arb_sub(diff2.value, v2->value, known[2 * cu + 1]->value, g.prec2);
        const auto difference = search.in_k0(diff.value, diff2.value, 200);
        if (!difference) continue;
        element = sum_of(found[static_cast<std::size_t>(j)][cu], search.to_current(*difference));
        break;
      }
      if (!element) {
        if (const auto a = search.in_k0(v->value, v2->value, g.digits))
          element = search.to_current(*a);
      }
      if (!element) {
        bool extended = false;
        element = search.by_minimal_polynomial(v2->value, extended);
        for (std::size_t p = 0; extended && p < found.size(); ++p)  // K grew: map what is in it
          for (std::size_t q = 0; q < 2; ++q)
            if (balls[p][2 * q]) found[p][q] = search.mapped(found[p][q]);
      }
      if (!element) {
        return fmt::format(
            "coordinate {} of point {} is in neither the field of degree {} nor an extension of "
            "it{} at {} digits",
            c == 0 ? "x" : "y", i + 1, k, search.beyond() ? " (the one found)" : "", g.digits);
      }
      found[iu][cu] = *element;
      balls[iu][2 * cu] = std::move(v);
      balls[iu][2 * cu + 1] = std::move(v2);
    }
  return "";
}

// The proof's steps once every point is in K: t's interval isolated, the field's identities, the
// bonds exact, and the strict inequalities at the embedding. Empty, or the first reason.
std::string check_proof(ExactConfiguration& out, const ConfigurationInput& in,
                        const MinimalPolynomial& d_poly, const std::set<int>& rattlers,
                        const arb_t t2, int digits, slong prec2) {
  if (std::string why = isolate_embedding(out, t2, digits, prec2); !why.empty()) return why;
  const flint::Field field(out.field);
  std::string why = check_field_identities(out, field, d_poly);
  if (why.empty()) why = check_bonds_exact(out, field, in, rattlers);
  if (why.empty()) why = check_at_embedding(out, in, d_poly, prec2);
  return why;
}

}  // namespace

ExactConfiguration prove_existence(const ConfigurationInput& in, const MinimalPolynomial& d_poly) {
  ExactConfiguration out;
  if (!d_poly.found) {
    out.reason = "no minimal polynomial of d";
    return out;
  }
  const Generators g(in, d_poly);

  // The field: Q(d) when an integer relation puts sqrt(3) there; else Q(d, sqrt 3) of degree 2m,
  // generated by t = d + j sqrt 3: elements are found in the tower basis d^a, sqrt3 d^a (small
  // coefficients) and converted exactly to powers of t.
  BaseField k0;
  if (!sqrt3_in_q_of_d(k0, out, g, d_poly)) tower_field(k0, out, g, d_poly);
  if (k0.k == 0) {
    out.reason =
        fmt::format("no field Q(d, sqrt 3) of degree <= {} found at {} digits", 2 * g.m, g.digits);
    return out;
  }

  // Every non-rattler coordinate in K0, or in a field beyond it (CoordinateSearch).
  const std::set<int> rattlers(in.rattlers.begin(), in.rattlers.end());
  CoordinateSearch search(g, k0, d_poly, out.field);
  FoundCoordinates found(static_cast<std::size_t>(in.n));
  if (std::string why = find_coordinates(found, search, in, g, rattlers, k0.k); !why.empty()) {
    out.reason = why;
    return out;
  }
  // Every element is in the current field: K0, or the field beyond it that a coordinate needed.
  out.points = found;
  const arb_struct* t2 = k0.t2.value;
  if (search.beyond()) {
    FmpzPoly kpoly;  // irreducible by construction (rnfequation of an irreducible factor): checked
    flint::poly_from_strings(kpoly.value, search.beyond_field().coefficients);
    if (!irreducible(kpoly.value)) {
      out.reason = "the extended field's polynomial is not irreducible";
      return out;
    }
    out.d_in_field = search.to_current(out.d_in_field);
    out.sqrt3_in_field = search.to_current(out.sqrt3_in_field);
    out.field = search.beyond_field();
    t2 = search.beyond_theta2();
  }

  // Then the proof's steps, each a reason when it fails.
  if (std::string why = check_proof(out, in, d_poly, rattlers, t2, g.digits, g.prec2);
      !why.empty()) {
    out.reason = why;
    return out;
  }
  out.proven = true;
  return out;
}

}  // namespace tripack::exact
