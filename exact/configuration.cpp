#include "exact/configuration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>

#include "exact/flint_tools.hpp"

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

// The value as an element of Q(t): value = -(c_1 + c_2 t + ...) / c_0 from the relation among
// [value, 1, t, ..., t^(k-1)], found at D digits and found again (the same, up to sign) at 2D.
std::optional<RationalPolynomial> express_in_field(const arb_t value, const arb_t value2,
                                                   const arb_t t, const arb_t t2, int k,
                                                   int digits) {
  const slong prec = flint::bits_for(digits), prec2 = flint::bits_for(2 * digits);
  std::vector<std::vector<std::string>> relations;
  for (int pass = 0; pass < 2; ++pass) {
    const Balls powers = powers_of(pass ? t2 : t, k, pass ? prec2 : prec);
    std::vector<const arb_struct*> values{pass ? value2 : value};
    for (const auto& p : powers) values.push_back(p->value);
    const int scale = (pass ? 2 * digits : digits) - 10;
    double used = 0;
    auto relation = flint::integer_relation(values, scale, pass ? prec2 : prec, used);
    if (!relation || relation->front() == "0" || used > 0.5 * scale) return std::nullopt;
    if (relation->front()[0] == '-')  // sign: c_0 > 0
      for (auto& c : *relation) c = c[0] == '-' ? c.substr(1) : (c == "0" ? c : "-" + c);
    relations.push_back(*relation);
  }
  if (relations[0] != relations[1]) return std::nullopt;
  const auto& c = relations[0];
  RationalPolynomial element;
  Fmpq q;
  flint::Fmpz numerator, denominator;
  fmpz_set_str(denominator.value, c[0].c_str(), 10);
  for (std::size_t i = 1; i < c.size(); ++i) {
    fmpz_set_str(numerator.value, c[i].c_str(), 10);
    fmpz_neg(numerator.value, numerator.value);
    fmpq_set_fmpz_frac(q.value, numerator.value, denominator.value);
    char* text = fmpq_get_str(nullptr, 10, q.value);
    element.coefficients.emplace_back(text);
    flint_free(text);
  }
  return element;
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
  if (static_cast<int>(fraction.size()) > keep_digits) fraction.resize(static_cast<std::size_t>(keep_digits));
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

}  // namespace

ExactConfiguration prove_existence(const ConfigurationInput& in, const MinimalPolynomial& d_poly) {
  ExactConfiguration out;
  if (!d_poly.found) {
    out.reason = "no minimal polynomial of d";
    return out;
  }
  const int digits = in.digits;
  const slong prec = flint::bits_for(digits), prec2 = flint::bits_for(2 * digits);
  const int m = d_poly.polynomial.degree();
  Arb d2, d, s2, s;
  flint::set_decimal(d2.value, in.d, 2 * digits, prec2);
  flint::round_ball(d.value, d2.value, digits);
  arb_sqrt_ui(s2.value, 3, prec2);
  arb_sqrt_ui(s.value, 3, prec);
  FmpzPoly p;
  flint::poly_from_strings(p.value, d_poly.polynomial.coefficients);

  // The field: Q(d) when it holds sqrt(3), else Q(d + j sqrt(3)) of degree 2m.
  Arb t, t2;
  int k = 0;
  std::optional<RationalPolynomial> sqrt3;
  if (m > 1) sqrt3 = express_in_field(s.value, s2.value, d.value, d2.value, m, digits);
  if (sqrt3) {
    out.field = d_poly.polynomial;
    out.embedding = d_poly.root;
    out.d_in_field = RationalPolynomial{{"0", "1"}};
    out.sqrt3_in_field = *sqrt3;
    arb_set(t.value, d.value);
    arb_set(t2.value, d2.value);
    k = m;
  } else {
    for (int j = 1; j <= 5 && k == 0; ++j) {
      arb_mul_ui(t2.value, s2.value, static_cast<ulong>(j), prec2);
      arb_add(t2.value, t2.value, d2.value, prec2);
      const MinimalPolynomial theta =
          flint::minimal_polynomial_of_ball(t2.value, digits, 2 * m);
      if (!theta.found || theta.polynomial.degree() != 2 * m) continue;
      flint::round_ball(t.value, t2.value, digits);
      const auto d_in = express_in_field(d.value, d2.value, t.value, t2.value, 2 * m, digits);
      if (!d_in) continue;
      out.field = theta.polynomial;
      out.embedding = theta.root;
      out.d_in_field = *d_in;
      // sqrt(3) = (t - d) / j.
      FmpqPoly tpoly, dpoly;
      flint::fmpq_poly_from_strings(tpoly.value, {"0", "1"});
      flint::fmpq_poly_from_strings(dpoly.value, d_in->coefficients);
      fmpq_poly_sub(tpoly.value, tpoly.value, dpoly.value);
      fmpq_poly_scalar_div_si(tpoly.value, tpoly.value, j);
      out.sqrt3_in_field = flint::strings_from_fmpq_poly(tpoly.value);
      k = 2 * m;
    }
  }
  if (k == 0) {
    out.reason = fmt::format("no field Q(d, sqrt 3) of degree <= {} found at {} digits", 2 * m, digits);
    return out;
  }
  // t0 isolated far more narrowly than d's interval, so that d_in_K(t0), a root of P (checked
  // exactly below), is proven to be the root in d's interval.
  {
    FmpzPoly kpoly;
    flint::poly_from_strings(kpoly.value, out.field.coefficients);
    const auto narrow = flint::isolate_root(kpoly.value, t2.value, 2 * digits - 30, prec2);
    if (!narrow) {
      out.reason = "the field's root could not be isolated";
      return out;
    }
    out.embedding = *narrow;
  }
  const flint::Field field(out.field);
  // Exact: P(d) = 0 and sqrt3^2 = 3 in K.
  {
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
      out.reason = "P(d) is not 0 in the field";
      return out;
    }
    field.set(s3.value, out.sqrt3_in_field);
    field.mul(s3.value, s3.value, s3.value);
    Fmpq three;
    fmpq_set_si(three.value, 3, 1);
    fmpq_poly_sub_fmpq(s3.value, s3.value, three.value);
    if (!field.is_zero(s3.value)) {
      out.reason = "sqrt(3)^2 is not 3 in the field";
      return out;
    }
  }

  // Every non-rattler coordinate in K; rattlers at their given centred place (40 digits).
  const std::set<int> rattlers(in.rattlers.begin(), in.rattlers.end());
  out.points.resize(static_cast<std::size_t>(in.n));
  for (int i = 0; i < in.n; ++i)
    for (int c = 0; c < 2; ++c) {
      const std::string& text = in.points[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)];
      if (rattlers.count(i)) {
        Fmpq q;
        decimal_to_fmpq(q.value, text, 40);
        char* qt = fmpq_get_str(nullptr, 10, q.value);
        out.points[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)] = RationalPolynomial{{qt}};
        flint_free(qt);
        continue;
      }
      Arb v2, v;
      flint::set_decimal(v2.value, text, 2 * digits, prec2);
      flint::round_ball(v.value, v2.value, digits);
      const auto element = express_in_field(v.value, v2.value, t.value, t2.value, k, digits);
      if (!element) {
        out.reason = fmt::format("coordinate {} of point {} is not in the field of degree {} at {} digits",
                                 c == 0 ? "x" : "y", i + 1, k, digits);
        return out;
      }
      out.points[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)] = *element;
    }

  // Every bond as an identity in K.
  {
    FmpqPoly dk, s3, xa, ya, xb, yb, dx, dy, e, f;
    field.set(dk.value, out.d_in_field);
    field.set(s3.value, out.sqrt3_in_field);
    for (const Bond& b : in.bonds) {
      if (rattlers.count(b.a) || (!b.is_wall() && rattlers.count(b.b))) {
        out.reason = fmt::format("a bond of rattler {}", b.a + 1);
        return out;
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
        out.reason = b.is_wall() ? fmt::format("the wall bond of point {} is not exact in the field", b.a + 1)
                                 : fmt::format("the bond {}-{} is not exact in the field", b.a + 1, b.b + 1);
        return out;
      }
    }
  }

  // At the real embedding, in ball arithmetic: sqrt3 > 0 there, d in P's interval, the exact
  // points near the given ones, every non-bond strictly apart, every centre inside.
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
    out.reason = "the embedding does not give +sqrt(3) and d in its interval";
    return out;
  }
  std::vector<std::array<std::unique_ptr<Arb>, 2>> at(static_cast<std::size_t>(in.n));
  Arb given, diff;
  for (int i = 0; i < in.n; ++i)
    for (int c = 0; c < 2; ++c) {
      auto& slot = at[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)];
      slot = std::make_unique<Arb>();
      evaluate(slot->value, out.points[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)]);
      flint::set_decimal(given.value,
                         in.given[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)], 30, prec2);
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
        out.reason = fmt::format("points {} and {} are not proven farther apart than d", i + 1, j + 1);
        return out;
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
        out.reason = fmt::format("point {} is not proven inside the {} side", i + 1, side_name(side));
        return out;
      }
      arb_div(r.value, r.value, dv.value, prec2);
      out.smallest_margin = std::min(out.smallest_margin, lower_bound(r.value));
    }
  }
  if (!(out.largest_offset < 1e-25)) {
    out.reason = fmt::format("the exact points lie {:.2g} from the given ones (10^-25 asked)", out.largest_offset);
    return out;
  }
  out.proven = true;
  return out;
}

}  // namespace tripack::exact
