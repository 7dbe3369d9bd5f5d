// exact/algebraic.hpp: minimal polynomials of numbers whose polynomials are known in closed form,
// the values computed here with MPFR (not with tripack's code).
#include <gtest/gtest.h>
#include <mpfr.h>

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "exact/algebraic.hpp"
#include "exact/configuration.hpp"

namespace tripack::exact {
namespace {

// MPFR value -> fixed-notation decimal with `digits` significant digits.
std::string decimal(mpfr_t x, int digits) {
  char* text = nullptr;
  mpfr_asprintf(&text, "%.*Re", digits - 1, x);
  std::string s(text);
  mpfr_free_str(text);
  return s;
}

// (a + sqrt(3)) ^ -1 to `digits` digits: d of 4Delta(k) with a = 2k - 2 (docs/classes.md).
std::string four_delta_d(long a, int digits) {
  mpfr_t x;
  mpfr_init2(x, static_cast<mpfr_prec_t>(digits * 3.33 + 64));
  mpfr_sqrt_ui(x, 3, MPFR_RNDN);
  mpfr_add_si(x, x, a, MPFR_RNDN);
  mpfr_ui_div(x, 1, x, MPFR_RNDN);
  const std::string s = decimal(x, digits);
  mpfr_clear(x);
  return s;
}

// MPFR value -> fixed notation with `decimals` digits after the point.
std::string fixed_decimal(mpfr_t x, int decimals) {
  char* text = nullptr;
  mpfr_asprintf(&text, "%.*Rf", decimals, x);
  std::string s(text);
  mpfr_free_str(text);
  return s;
}

// Disk 1 in the bottom-left corner, disk 2 at (x, y) at distance d = 1/2 from it.
ConfigurationInput corner_pair(const std::string& x, const std::string& y, int digits) {
  ConfigurationInput in;
  in.n = 2;
  in.bonds = {Bond::pair(0, 1), Bond::wall(0, Side::Bottom), Bond::wall(0, Side::Left)};
  in.d = "0.5";
  in.points = {{"0", "0"}, {x, y}};
  in.given = {{"0", "0"}, {x.substr(0, 32), y.substr(0, 32)}};
  in.digits = digits;
  return in;
}

// d = 1/2: P = 2x - 1.
MinimalPolynomial one_half() {
  MinimalPolynomial p;
  p.found = true;
  p.polynomial.coefficients = {"-1", "2"};
  p.root = {"49/100", "51/100"};
  return p;
}

// Two disks on the bottom side at (a, 0) and (b, 0) = (a + d, 0).
ConfigurationInput bottom_pair(const std::string& d, const std::string& a, const std::string& b,
                               int digits) {
  ConfigurationInput in;
  in.n = 2;
  in.bonds = {Bond::pair(0, 1), Bond::wall(0, Side::Bottom), Bond::wall(1, Side::Bottom)};
  in.d = d;
  in.points = {{a, "0"}, {b, "0"}};
  in.given = {{a.substr(0, 34), "0"}, {b.substr(0, 34), "0"}};
  in.digits = digits;
  return in;
}

TEST(ExactAlgebraic, SquareRootOfTwoAndTheGoldenRatio) {
  mpfr_t x;
  mpfr_init2(x, 600);
  mpfr_sqrt_ui(x, 2, MPFR_RNDN);
  const MinimalPolynomial sqrt2 = minimal_polynomial(decimal(x, 160), 80, 12);
  ASSERT_TRUE(sqrt2.found) << sqrt2.reason;
  EXPECT_EQ(sqrt2.polynomial.pari(), "x^2 - 2");
  mpfr_sqrt_ui(x, 5, MPFR_RNDN);
  mpfr_add_ui(x, x, 1, MPFR_RNDN);
  mpfr_div_ui(x, x, 2, MPFR_RNDN);
  const MinimalPolynomial phi = minimal_polynomial(decimal(x, 160), 80, 12);
  ASSERT_TRUE(phi.found);
  EXPECT_EQ(phi.polynomial.pari(), "x^2 - x - 1");
  mpfr_clear(x);
}

TEST(ExactAlgebraic, FourDeltaClosedFormForKUpTo50) {
  // d(4Delta(k)) = 1/(2k - 2 + sqrt 3): (1 - a d)^2 = 3 d^2, so P = (a^2 - 3) x^2 - 2a x + 1 with
  // a = 2k - 2, made primitive with a positive leading coefficient (k = 1: 3x^2 - 1).
  for (long k = 1; k <= 50; ++k) {
    const long a = 2 * k - 2;
    const MinimalPolynomial p = minimal_polynomial(four_delta_d(a, 120), 60, 8);
    ASSERT_TRUE(p.found) << "k = " << k << ": " << p.reason;
    const long lead = a * a - 3, middle = -2 * a, constant = 1;
    const long sign = lead < 0 ? -1 : 1;
    const IntegerPolynomial expected{{std::to_string(sign * constant),
                                      std::to_string(sign * middle), std::to_string(sign * lead)}};
    EXPECT_EQ(p.polynomial.pari(), expected.pari()) << "k = " << k;
  }
}

TEST(ExactAlgebraic, TheRootIntervalHoldsTheValue) {
  const std::string d = four_delta_d(4, 120);  // k = 3
  const MinimalPolynomial p = minimal_polynomial(d, 60, 8);
  ASSERT_TRUE(p.found);
  // low < d < high, compared in MPFR at 600 bits (the interval is ~1e-30 wide).
  auto value_of = [](mpfr_t out, const std::string& q) {
    const auto slash = q.find('/');
    mpfr_t denominator;
    mpfr_init2(denominator, 600);
    mpfr_set_str(out, q.substr(0, slash).c_str(), 10, MPFR_RNDN);
    mpfr_set_str(denominator, q.substr(slash + 1).c_str(), 10, MPFR_RNDN);
    mpfr_div(out, out, denominator, MPFR_RNDN);
    mpfr_clear(denominator);
  };
  mpfr_t low, high, value;
  mpfr_inits2(600, low, high, value, static_cast<mpfr_ptr>(nullptr));
  value_of(low, p.root.low);
  value_of(high, p.root.high);
  mpfr_set_str(value, d.c_str(), 10, MPFR_RNDN);
  EXPECT_LT(mpfr_cmp(low, value), 0);
  EXPECT_GT(mpfr_cmp(high, value), 0);
  mpfr_sub(high, high, low, MPFR_RNDN);
  EXPECT_LT(mpfr_get_d(high, MPFR_RNDN), 1e-25);  // about 2 * 10^-(digits / 2)
  mpfr_clears(low, high, value, static_cast<mpfr_ptr>(nullptr));
  EXPECT_EQ(p.digits, 60);
  EXPECT_EQ(p.confirmed_digits, 120);
}

TEST(ExactAlgebraic, NoRelationForPiAtLowDegree) {
  // pi is transcendental: no relation may be accepted, whatever LLL returns at 60 digits.
  mpfr_t x;
  mpfr_init2(x, 600);
  mpfr_const_pi(x, MPFR_RNDN);
  const MinimalPolynomial p = minimal_polynomial(decimal(x, 120), 60, 12);
  mpfr_clear(x);
  EXPECT_FALSE(p.found) << p.polynomial.pari();
}

TEST(ExactAlgebraic, BadInputIsRefused) {
  EXPECT_THROW(minimal_polynomial("abc", 60, 4), std::invalid_argument);
  EXPECT_THROW(minimal_polynomial("0.5", 10, 4), std::invalid_argument);
}

// Two disks, d = 1/2: A at the corner (0,0) on the bottom and left walls, B at distance d on
// the 45-degree line, B = (sqrt2/4, sqrt2/4). B's coordinates are outside Q(d, sqrt3) = Q(sqrt3):
// statement (I) needs the quadratic extension Q(sqrt3)(w), w = sqrt2/4, w^2 = 1/8, a field of
// degree 4 (its polynomial checked irreducible).
TEST(ExactConfiguration, CoordinatesOutsideQdSqrt3GetAQuadraticExtension) {
  const int digits = 120;
  mpfr_t x;
  mpfr_init2(x, 1000);
  mpfr_sqrt_ui(x, 2, MPFR_RNDN);
  mpfr_div_ui(x, x, 4, MPFR_RNDN);
  const std::string b = decimal(x, 2 * digits);
  mpfr_clear(x);
  // fixed notation: "3.535...e-01" -> "0.3535..."
  const auto e = b.find('e');
  const std::string mantissa = b.substr(0, e);
  const std::string fixed = "0." + mantissa.substr(0, 1) + mantissa.substr(2);
  const ExactConfiguration c = prove_existence(corner_pair(fixed, fixed, digits), one_half());
  ASSERT_TRUE(c.proven) << c.reason;
  EXPECT_EQ(c.field.degree(), 4);  // [Q(sqrt3, sqrt2) : Q]
  EXPECT_LT(c.largest_offset, 1e-25);
}

// Disk 1 on the bottom-left corner, disk 2 at distance d = 1/2 from it at (a, b): a = 2^(1/3) / 4
// (degree 3) and b = sqrt(1/4 - a^2) (degree 6: (4 - 16 b^2)^3 = 4). Neither is in Q(d, sqrt 3)
// = Q(sqrt 3) nor in a quadratic extension of it: K grows twice, by a's cubic and then by b's
// quadratic factor over Q(sqrt 3, a), to Q(sqrt 3, b) of degree 12 (docs/exact.md, "A general
// number field").
TEST(ExactConfiguration, CoordinatesBeyondAQuadraticExtensionGetTheirOwnField) {
  const int digits = 120;
  mpfr_t a, b;
  mpfr_inits2(1000, a, b, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_ui(a, 2, MPFR_RNDN);
  mpfr_cbrt(a, a, MPFR_RNDN);
  mpfr_div_ui(a, a, 4, MPFR_RNDN);
  mpfr_sqr(b, a, MPFR_RNDN);
  mpfr_ui_sub(b, 1, b, MPFR_RNDN);
  mpfr_sub_d(b, b, 0.75, MPFR_RNDN);  // 1/4 - a^2
  mpfr_sqrt(b, b, MPFR_RNDN);
  const std::string a_text = fixed_decimal(a, 2 * digits), b_text = fixed_decimal(b, 2 * digits);
  mpfr_clears(a, b, static_cast<mpfr_ptr>(nullptr));
  const ExactConfiguration c = prove_existence(corner_pair(a_text, b_text, digits), one_half());
  ASSERT_TRUE(c.proven) << c.reason;
  EXPECT_EQ(c.field.degree(), 12);
  EXPECT_LT(c.largest_offset, 1e-25);
}

// Two disks on the bottom side, A = (a, 0) and B = (a + d, 0), with d = 1/(5 + 3^(1/11)) (P below,
// degree 11: (1 - 5x)^11 - 3x^11 divided by its content, from y = 1/x - 5, y^11 = 3; irreducible by
// Eisenstein at 3) and a = -(1 + d) / (2^20 P'(d)). In the tower basis d^i, sqrt3 d^i, a's integer
// relation has ~20-digit coefficients (PARI: the numerators of (1 + d)/P'(d) mod P), so 24 of
// them need ~480 digits; a P'(d) = -(1 + d)/2^20 needs ~150. From D = 300 digits statement (I)
// is proven only by looking for a P'(d) (docs/exact.md, "Coordinates").
TEST(ExactConfiguration, ACoordinateWithALargeDenominatorIsFoundAsItsMultipleByPPrime) {
  const int digits = 300;
  const mpfr_prec_t bits = 4000;
  mpfr_t y, d, slope, a, term;
  for (mpfr_ptr v : {y, d, slope, a, term}) mpfr_init2(v, bits);
  mpfr_set_ui(y, 3, MPFR_RNDN);
  mpfr_rootn_ui(y, y, 11, MPFR_RNDN);
  mpfr_add_ui(y, y, 5, MPFR_RNDN);
  mpfr_ui_div(d, 1, y, MPFR_RNDN);
  const std::vector<long> p = {1,       -55,       1375,     -20625,     206250,    -1443750,
                               7218750, -25781250, 64453125, -107421875, 107421875, -48828128};
  mpfr_set_ui(slope, 0, MPFR_RNDN);  // P'(d) by Horner
  for (std::size_t i = p.size() - 1; i >= 1; --i) {
    mpfr_mul(slope, slope, d, MPFR_RNDN);
    mpfr_add_si(slope, slope, p[i] * static_cast<long>(i), MPFR_RNDN);
  }
  mpfr_add_ui(a, d, 1, MPFR_RNDN);
  mpfr_div(a, a, slope, MPFR_RNDN);
  mpfr_div_2ui(a, a, 20, MPFR_RNDN);
  mpfr_neg(a, a, MPFR_RNDN);
  mpfr_add(term, a, d, MPFR_RNDN);
  const std::string d_text = fixed_decimal(d, 2 * digits), a_text = fixed_decimal(a, 2 * digits),
                    b_text = fixed_decimal(term, 2 * digits);
  for (mpfr_ptr v : {y, d, slope, a, term}) mpfr_clear(v);
  ASSERT_GT(std::stod(a_text), 0.3);  // both centres well inside the bottom side
  ASSERT_LT(std::stod(b_text), 0.7);
  MinimalPolynomial poly;
  poly.found = true;
  for (long c : p) poly.polynomial.coefficients.push_back(std::to_string(c));
  poly.root = {"1637/10000", "1639/10000"};  // P's only real root (y^11 = 3 has one)
  const ExactConfiguration c = prove_existence(bottom_pair(d_text, a_text, b_text, digits), poly);
  ASSERT_TRUE(c.proven) << c.reason;
  EXPECT_EQ(c.field.degree(), 22);  // Q(d, sqrt3): sqrt3 is not in Q(d), of odd degree
  EXPECT_LT(c.largest_offset, 1e-25);
}

// Two disks on the bottom side at A = (a, 0) and B = (a + d, 0), with y = 3^(1/11),
// d = 3/10 + y / M, M = 10^12 (P = 10^121 (10x - 3)^11 - 3, irreducible: the minimal polynomial
// of y moved and scaled) and a = y^5 / 4 = M^5 (d - 3/10)^5 / 4. Every relation that writes a in
// the field's bases (d^i; d^i, sqrt3 d^i; also a P'(d), again M^5 times a polynomial in
// d - 3/10) has coefficients of about 60 digits, while LLL at D = 300 digits among 12 or more
// numbers finds nothing taller than about 10^25; a's minimal polynomial over Q, 4^11 x^11 - 3^5,
// needs about 100 digits. So from D = 300 digits a is found only as the root of that polynomial
// in Q(d) (PARI's nfroots; docs/exact.md, "Coordinates").
TEST(ExactConfiguration, ACoordinateOfLargeHeightIsFoundAsARootOfItsMinimalPolynomial) {
  const int digits = 300;
  const mpfr_prec_t bits = 4000;
  mpfr_t y, d, a, b;
  for (mpfr_ptr v : {y, d, a, b}) mpfr_init2(v, bits);
  mpfr_set_ui(y, 3, MPFR_RNDN);
  mpfr_rootn_ui(y, y, 11, MPFR_RNDN);
  mpfr_pow_ui(a, y, 5, MPFR_RNDN);
  mpfr_div_ui(a, a, 4, MPFR_RNDN);
  mpfr_div_ui(d, y, 1000000, MPFR_RNDN);
  mpfr_div_ui(d, d, 1000000, MPFR_RNDN);
  mpfr_set_ui(b, 3, MPFR_RNDN);
  mpfr_div_ui(b, b, 10, MPFR_RNDN);
  mpfr_add(d, d, b, MPFR_RNDN);
  mpfr_add(b, a, d, MPFR_RNDN);
  const std::string d_text = fixed_decimal(d, 2 * digits), a_text = fixed_decimal(a, 2 * digits),
                    b_text = fixed_decimal(b, 2 * digits);
  for (mpfr_ptr v : {y, d, a, b}) mpfr_clear(v);
  ASSERT_GT(std::stod(a_text), 0.3);
  ASSERT_LT(std::stod(b_text), 0.8);
  MinimalPolynomial poly;
  poly.found = true;
  // x^k: 10^121 C(11, k) 10^k (-3)^(11 - k), and -3 more at k = 0.
  mpz_t coefficient, t;
  mpz_inits(coefficient, t, nullptr);
  for (unsigned long k = 0; k <= 11; ++k) {
    mpz_bin_uiui(coefficient, 11, k);
    mpz_ui_pow_ui(t, 10, 121 + k);
    mpz_mul(coefficient, coefficient, t);
    mpz_ui_pow_ui(t, 3, 11 - k);
    mpz_mul(coefficient, coefficient, t);
    if ((11 - k) % 2) mpz_neg(coefficient, coefficient);
    if (k == 0) mpz_sub_ui(coefficient, coefficient, 3);
    char* text = mpz_get_str(nullptr, 10, coefficient);
    poly.polynomial.coefficients.push_back(text);
    void (*release)(void*, std::size_t);
    mp_get_memory_functions(nullptr, nullptr, &release);
    release(text, std::strlen(text) + 1);
  }
  mpz_clears(coefficient, t, nullptr);
  poly.root = {"3000000000011/10000000000000", "3000000000012/10000000000000"};  // y = 1.10503..
  const ExactConfiguration c = prove_existence(bottom_pair(d_text, a_text, b_text, digits), poly);
  ASSERT_TRUE(c.proven) << c.reason;
  EXPECT_EQ(c.field.degree(), 22);  // Q(d, sqrt3)
  EXPECT_LT(c.largest_offset, 1e-25);
}

}  // namespace
}  // namespace tripack::exact
