// polish/polish_mp: the bond system polished in MPFR, checked against closed forms evaluated in
// MPFR (the C API: a light header, unlike the Boost wrappers).
#include <gtest/gtest.h>
#include <mpfr.h>

#include <limits>
#include <stdexcept>
#include <string>

#include "bond_systems.hpp"
#include "constructors/builders.hpp"
#include "pipeline/analyze.hpp"
#include "polish/polish_mp.hpp"

namespace tripack {
namespace {

// An MPFR number with guard digits beyond what the tests compare.
struct Num {
  mpfr_t v;
  explicit Num(int digits) { mpfr_init2(v, static_cast<mpfr_prec_t>(3.33 * (digits + 20))); }
  Num(const Num&) = delete;
  Num& operator=(const Num&) = delete;
  ~Num() { mpfr_clear(v); }
};

// |value - exact| <= 10^-(digits-1) |exact|: a correctly rounded `digits`-digit string is within
// 5 * 10^-digits relative.
void expect_close(const std::string& value, const Num& exact, int digits) {
  Num parsed(digits), diff(digits), bound(digits);
  ASSERT_EQ(mpfr_set_str(parsed.v, value.c_str(), 10, MPFR_RNDN), 0) << value;
  mpfr_sub(diff.v, parsed.v, exact.v, MPFR_RNDN);
  mpfr_set_si(bound.v, -(digits - 1), MPFR_RNDN);
  mpfr_exp10(bound.v, bound.v, MPFR_RNDN);
  mpfr_mul(bound.v, bound.v, exact.v, MPFR_RNDN);
  EXPECT_LE(mpfr_cmpabs(diff.v, bound.v), 0)
      << value << " differs from the closed form by " << mpfr_get_d(diff.v, MPFR_RNDN);
}

// The closed form of a number in (0.1, 1) as a `digits`-significant-digit string "0.ddd...".
std::string decimal(const Num& v, int digits) {
  mpfr_exp_t e = 0;
  char* raw = mpfr_get_str(nullptr, &e, 10, static_cast<std::size_t>(digits), v.v, MPFR_RNDN);
  std::string s = raw;
  mpfr_free_str(raw);
  EXPECT_EQ(e, 0);
  return "0." + s;
}

// GL1995 Sec.5: d(4Delta(k)) = 1/(2k - 2 + sqrt3).
void four_delta_closed_form(Num& d, long k) {
  mpfr_sqrt_ui(d.v, 3, MPFR_RNDN);
  mpfr_add_si(d.v, d.v, 2 * k - 2, MPFR_RNDN);
  mpfr_ui_div(d.v, 1, d.v, MPFR_RNDN);
}

// docs/classes.md "closed forms": d(t22a) = 5 sqrt3 / (20 sqrt3 + 7 + 2 sqrt11).
void t22a_closed_form(Num& d, int digits) {
  Num s3(digits), s11(digits), den(digits);
  mpfr_sqrt_ui(s3.v, 3, MPFR_RNDN);
  mpfr_sqrt_ui(s11.v, 11, MPFR_RNDN);
  mpfr_mul_ui(den.v, s3.v, 20, MPFR_RNDN);
  mpfr_add_ui(den.v, den.v, 7, MPFR_RNDN);
  mpfr_mul_2ui(s11.v, s11.v, 1, MPFR_RNDN);
  mpfr_add(den.v, den.v, s11.v, MPFR_RNDN);
  mpfr_mul_ui(d.v, s3.v, 5, MPFR_RNDN);
  mpfr_div(d.v, d.v, den.v, MPFR_RNDN);
}

TEST(Multiprecision, EvenRippleT22aTo50Digits) {
  const Pattern pat = build_chain_family({3, 1, 1});
  const auto mp = polish_multiprecision(pat.packing, pat.bonds, pat.rattlers, 50);
  ASSERT_TRUE(mp.converged);
  EXPECT_EQ(mp.digits, 50);
  EXPECT_LT(mp.log10_max_residual, -53);
  Num exact(50);
  t22a_closed_form(exact, 50);
  EXPECT_EQ(mp.d, decimal(exact, 50));  // every one of the 50 digits
  expect_close(mp.d, exact, 50);
  ASSERT_EQ(mp.points.size(), 22u);
  EXPECT_EQ(mp.points[0][0].size(), 52u);  // "0." and 50 decimals
}

TEST(Multiprecision, EvenRippleT22aTo30Digits) {
  const Pattern pat = build_chain_family({3, 1, 1});
  const auto mp = polish_multiprecision(pat.packing, pat.bonds, pat.rattlers, 30);
  ASSERT_TRUE(mp.converged);
  Num exact(30);
  t22a_closed_form(exact, 30);
  EXPECT_EQ(mp.d, decimal(exact, 30));
  EXPECT_EQ(mp.d.size(), 32u);
  // L = 1/d: 5.574..., 30 significant digits.
  EXPECT_EQ(mp.L.substr(0, 5), "5.574");
  EXPECT_EQ(mp.L.size(), 31u);
}

TEST(Multiprecision, FourDeltaTo100Digits) {
  for (long k = 1; k <= 10; ++k) {
    const Pattern pat = build_four_delta(k);
    const auto mp = polish_multiprecision(pat.packing, pat.bonds, pat.rattlers, 100);
    ASSERT_TRUE(mp.converged) << "k = " << k;
    Num exact(100);
    four_delta_closed_form(exact, k);
    expect_close(mp.d, exact, 100);
  }
}

TEST(Multiprecision, FourDeltaTo300Digits) {
  // GL1995 Sec.5: d(4Delta(3)) = 1/(4 + sqrt3). The residuals (~1e-300) are rescaled before they
  // meet the double factorization, which would otherwise underflow.
  const Pattern pat = build_four_delta(3);
  const auto mp = polish_multiprecision(pat.packing, pat.bonds, pat.rattlers, 300);
  ASSERT_TRUE(mp.converged);
  Num exact(300);
  four_delta_closed_form(exact, 3);
  expect_close(mp.d, exact, 300);
}

TEST(Multiprecision, D79MatchesThePaper) {
  // GL1995 Sec.5: d(79) = 0.0871159038791759 (even ripple k = 6). The paper rounds to 15
  // significant digits (the 16th is 5 and the expansion continues ...791758550...), so the
  // 50-digit string is compared after rounding to the paper's 15 digits.
  const Pattern pat = build_chain_family({6, 1, 1});
  const auto mp = polish_multiprecision(pat.packing, pat.bonds, pat.rattlers, 50);
  ASSERT_TRUE(mp.converged);
  EXPECT_EQ(mp.d.size(), 53u);  // "0.0" and 50 significant digits
  Num d(50);
  ASSERT_EQ(mpfr_set_str(d.v, mp.d.c_str(), 10, MPFR_RNDN), 0);
  mpfr_mul_ui(d.v, d.v, 10, MPFR_RNDN);  // into (0.1, 1) for decimal()
  EXPECT_EQ(decimal(d, 15), "0.871159038791759");
}

TEST(Multiprecision, RejectsDigitsOutOfRange) {
  const Pattern pat = build_four_delta(2);
  EXPECT_THROW(polish_multiprecision(pat.packing, pat.bonds, pat.rattlers, 0),
               std::invalid_argument);
  EXPECT_THROW(
      polish_multiprecision(pat.packing, pat.bonds, pat.rattlers, kMaxMultiprecisionDigits + 1),
      std::invalid_argument);
}

TEST(Multiprecision, InconsistentSystemDoesNotConverge) {
  // Three mutually touching disks cannot all sit on the floor.
  Packing p;
  p.points = {{0.3, 0.0}, {0.5, 0.0}, {0.4, 0.17}};
  p.d = 0.2;
  std::vector<Bond> bonds{Bond::pair(0, 1), Bond::pair(0, 2), Bond::pair(1, 2)};
  for (int i = 0; i < 3; ++i) bonds.push_back(Bond::wall(i, Side::Bottom));
  const auto mp = polish_multiprecision(p, bonds, {}, 30);
  EXPECT_FALSE(mp.converged);
  EXPECT_GT(mp.log10_max_residual, -5);
  EXPECT_TRUE(mp.d.empty());
  EXPECT_TRUE(mp.points.empty());
}

TEST(Multiprecision, InconsistencyBelowLongDoubleToleranceIsCaught) {
  // Disk 2 is held fixed (declared a rattler, yet bonded) 1e-15 disk units beyond where the chain
  // 0-1-2 along the floor from the corner can reach: the long double polish accepts that as its
  // rounding floor, the MPFR Newton cannot go below it and says so.
  Packing p;
  p.points = {{0.0, 0.0}, {0.25, 0.0}, {0.5L + 2.5e-16L, 0.0}};
  p.d = 0.25;
  const std::vector<Bond> bonds{Bond::pair(0, 1), Bond::pair(1, 2), Bond::wall(0, Side::Bottom),
                                Bond::wall(0, Side::Left), Bond::wall(1, Side::Bottom)};
  const auto mp = polish_multiprecision(p, bonds, {2}, 30);
  EXPECT_FALSE(mp.converged);
  EXPECT_GT(mp.log10_max_residual, -17);
  EXPECT_LT(mp.log10_max_residual, -15);
  EXPECT_TRUE(mp.d.empty());
}

TEST(Multiprecision, RankDeficientConsistentSystemsConverge) {
  // A floor pair plus a disk with no bonds (not declared a rattler): its column is empty, the
  // least-squares steps leave it alone, and the bonded pair is polished.
  const auto [p, bonds] = floor_pair_and_an_unbonded_disk();
  const auto mp = polish_multiprecision(p, bonds, {}, 40);
  ASSERT_TRUE(mp.converged);
  EXPECT_LT(mp.log10_max_residual, -43);
  // The pair lies on the floor at distance d: y to 40 decimals is zero.
  EXPECT_EQ(mp.points[1][1], "0." + std::string(40, '0'));
}

TEST(Multiprecision, RattlersKeepTheirStartCoordinates) {
  const Pattern pat = build_chain_family({3, 1, 1});
  const auto mp = polish_multiprecision(pat.packing, pat.bonds, pat.rattlers, 30);
  ASSERT_TRUE(mp.converged);
  for (int r : pat.rattlers) {
    const auto i = static_cast<std::size_t>(r);
    EXPECT_NEAR(std::stold(mp.points[i][0]), pat.packing.points[i].x, 1e-30L);
    EXPECT_NEAR(std::stold(mp.points[i][1]), pat.packing.points[i].y, 1e-30L);
  }
}

// A rattler in a cage only 1e-20 d wider than the disk: three neighbours at d (1 + 1e-20) from
// the cage's centre (0.5, 0.3), 40-digit coordinates (mpmath). Its long double place, 1e-15 off
// the centre, overlaps them (below long double's resolution); the MPFR centring must find the
// room: clearance 1e-20 d, every distance >= d to the 30 digits written.
TEST(Multiprecision, RattlersAreCentredInCagesNarrowerThanLongDouble) {
  MultiprecisionPolish mp;
  mp.digits = 30;
  mp.converged = true;
  mp.d = "0.100000000000000000000000000000";
  mp.L = "10.0000000000000000000000000000";
  mp.points = {{"0.5", "0.400000000000000000001"},
               {"0.4133974596215561353227616575209219430061", "0.2499999999999999999995"},
               {"0.5866025403784438646772383424790780569939", "0.2499999999999999999995"},
               {"0.500000000000001", "0.299999999999999"}};  // the rattler, 1.4e-15 off centre
  const double room = centre_rattlers_multiprecision(mp, {3});
  EXPECT_GT(room, 0.9e-20);
  EXPECT_LT(room, 1.1e-20);
  // Its new place, read back in long double (1e-19 absolute), is the cage's centre.
  EXPECT_NEAR(static_cast<double>(std::stold(mp.points[3][0]) - 0.5L), 0, 1e-18);
  EXPECT_NEAR(static_cast<double>(std::stold(mp.points[3][1]) - 0.3L), 0, 1e-18);
  EXPECT_EQ(mp.points[0][0], "0.5");  // the others untouched
  // Without rattlers (or an unconverged polish) nothing moves.
  EXPECT_EQ(centre_rattlers_multiprecision(mp, {}), std::numeric_limits<double>::infinity());
}

// An atlas packing (data/atlas), analysed in long double: its bonds and rattlers.
Pattern atlas_pattern(const std::string& label) {
  pipeline::AnalyzeRequest request;
  request.file = std::string(TRIPACK_SOURCE_DIR) + "/data/atlas/" + label + ".txt";
  const pipeline::FileAnalysis fa = pipeline::analyze_file(request);
  EXPECT_TRUE(fa.analysis.certified()) << label;
  return fa.analysis.pattern;
}

// docs/precision.md: precision on demand must not change a digit. The 2000-digit polish of t22a
// agrees with the 1000-digit one on the first 995 digits of d, L and every coordinate, and both
// agree with the closed form; Newton's quadratic convergence shows in the iteration count (the
// linear scheme before it took 132 at 2000 digits).
TEST(Multiprecision, T22aTo2000DigitsAgreesWith1000) {
  const Pattern pat = atlas_pattern("t22a");
  ASSERT_EQ(pat.packing.size(), 22u);
  const auto mp1 = polish_multiprecision(pat.packing, pat.bonds, pat.rattlers, 1000);
  const auto mp2 = polish_multiprecision(pat.packing, pat.bonds, pat.rattlers, 2000);
  ASSERT_TRUE(mp1.converged);
  ASSERT_TRUE(mp2.converged);
  EXPECT_LT(mp2.log10_max_residual, -2003);
  EXPECT_LE(mp2.iterations, 10);
  // d = 0.1793...: "0." and 995 significant digits.
  EXPECT_EQ(mp2.d.substr(0, 997), mp1.d.substr(0, 997));
  // Numerically: |a - b| <= 10^-995 |a| for d, L and the coordinates (which lie in [0, 1]: there
  // 995 decimals).
  auto expect_agree = [](const std::string& a, const std::string& b, bool relative) {
    Num x(2000), y(2000), bound(2000);
    ASSERT_EQ(mpfr_set_str(x.v, a.c_str(), 10, MPFR_RNDN), 0);
    ASSERT_EQ(mpfr_set_str(y.v, b.c_str(), 10, MPFR_RNDN), 0);
    mpfr_sub(y.v, y.v, x.v, MPFR_RNDN);
    mpfr_set_si(bound.v, -995, MPFR_RNDN);
    mpfr_exp10(bound.v, bound.v, MPFR_RNDN);
    if (relative) mpfr_mul(bound.v, bound.v, x.v, MPFR_RNDN);
    EXPECT_LE(mpfr_cmpabs(y.v, bound.v), 0) << a.substr(0, 20);
  };
  expect_agree(mp1.d, mp2.d, true);
  expect_agree(mp1.L, mp2.L, true);
  ASSERT_EQ(mp2.points.size(), 22u);
  for (std::size_t i = 0; i < 22; ++i)
    for (std::size_t c = 0; c < 2; ++c) expect_agree(mp1.points[i][c], mp2.points[i][c], false);
  Num exact(2000);
  t22a_closed_form(exact, 2000);
  expect_close(mp1.d, exact, 1000);
  expect_close(mp2.d, exact, 2000);
}

// GL1995's closed form for n = 13: d(13) is a root of 4x^4 - 144x^3 + 180x^2 - 72x + 9. The
// 3000-digit d of t13a, evaluated in MPFR at 3050 digits (not tripack's polish arithmetic),
// makes it vanish to better than 10^-2990 (|p'(d)| ~ 8.5, so the 3000th digit's rounding alone
// leaves ~4e-3000).
TEST(Multiprecision, T13aTo3000DigitsIsARootOfGL1995Quartic) {
  const Pattern pat = atlas_pattern("t13a");
  ASSERT_EQ(pat.packing.size(), 13u);
  const auto mp = polish_multiprecision(pat.packing, pat.bonds, pat.rattlers, 3000);
  ASSERT_TRUE(mp.converged);
  EXPECT_EQ(mp.d.substr(0, 12), "0.2518132366");
  EXPECT_EQ(mp.d.size(), 3002u);  // "0." and 3000 digits
  Num x(3050), p(3050), bound(3050);
  ASSERT_EQ(mpfr_set_str(x.v, mp.d.c_str(), 10, MPFR_RNDN), 0);
  mpfr_set_si(p.v, 4, MPFR_RNDN);  // Horner: (((4x - 144)x + 180)x - 72)x + 9
  for (long coefficient : {-144L, 180L, -72L, 9L}) {
    mpfr_mul(p.v, p.v, x.v, MPFR_RNDN);
    mpfr_add_si(p.v, p.v, coefficient, MPFR_RNDN);
  }
  mpfr_set_si(bound.v, -2990, MPFR_RNDN);
  mpfr_exp10(bound.v, bound.v, MPFR_RNDN);
  EXPECT_LT(mpfr_cmpabs(p.v, bound.v), 0) << "log10 |p(d)| = " << mpfr_get_d(p.v, MPFR_RNDN);
}

// Deep precision against a closed form: d(4Delta(3)) = 1/(4 + sqrt3) to 10,000 digits.
TEST(Multiprecision, FourDeltaTo10000Digits) {
  const Pattern pat = build_four_delta(3);
  const auto mp = polish_multiprecision(pat.packing, pat.bonds, pat.rattlers, 10000);
  ASSERT_TRUE(mp.converged);
  EXPECT_LE(mp.iterations, 12);
  Num exact(10000);
  four_delta_closed_form(exact, 3);
  expect_close(mp.d, exact, 10000);
}

TEST(Multiprecision, EvenRippleN254To50Digits) {
  // t254a (even ripple p = 11): the size the design targets (target under 5 s; ~10 ms measured).
  const Pattern pat = build_chain_family({11, 1, 1});
  ASSERT_EQ(pat.packing.size(), 254u);
  const auto mp = polish_multiprecision(pat.packing, pat.bonds, pat.rattlers, 50);
  ASSERT_TRUE(mp.converged);
  EXPECT_LT(mp.iterations, 10);
}

}  // namespace
}  // namespace tripack
