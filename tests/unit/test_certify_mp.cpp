// The multiprecision certificate (docs/certified.md, "The multiprecision certificate"): where
// double precision cannot resolve a packing's margins, bonds, rigidity and stress decided on a
// configuration polished in MPFR.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "analysis/certify.hpp"
#include "core/points.hpp"
#include "formats/formats.hpp"
#include "pipeline/analyze.hpp"
#include "pipeline/build.hpp"
#include "polish/polish_mp.hpp"

namespace tripack {
namespace {

using pipeline::AnalysisOptions;
using pipeline::analyze_packing;

Packing built(const std::string& name) {
  const std::string file = std::string(TRIPACK_TEST_DATA) + "/certify_mp/" + name;
  return packing_from_points(read_packing_file(file), std::nullopt, std::nullopt).packing;
}

// The certificate's own margins, each against the error it was measured with.
void expect_resolved(const pipeline::Analysis& a, const char* what) {
  ASSERT_TRUE(a.precise) << what;
  const auto& p = *a.precise;
  ASSERT_TRUE(p.certified) << what << ": " << a.status();
  EXPECT_TRUE(a.certified()) << what;
  // Digits from the smallest gap double precision saw: 40 to 58 (precise_digits).
  EXPECT_GE(p.digits, 40);
  EXPECT_LE(p.digits, 58);
  // The bonds close to the working precision: their largest |gap| (measured in MPFR) is at the
  // 10^-digits floor (10^-digits over d = 1/17 or 1/18, so 18 x 10^-digits; 100x for the last
  // digits).
  EXPECT_LT(p.identification.gaps.bond_floor, 100 * std::pow(10.0L, -p.digits)) << what;
  // The smallest non-bond gap is open by far more than the floor: 20 orders (the stage demands
  // half the digits, > 20 orders at 40+ digits).
  EXPECT_GT(p.smallest_gap, 0) << what;
  EXPECT_GT(p.smallest_gap, 1e20L * p.gap_floor) << what;
  // Rigid: the smallest eigenvalue of G^T G is bounded below with its measured error at most
  // half the shifted bound (multiprecision_certificate).
  const auto& c = p.certificate;
  EXPECT_TRUE(c.rigid) << what;
  EXPECT_GT(c.min_eigenvalue, 0) << what;
  EXPECT_LE(c.eigenvalue_error, c.min_eigenvalue) << what;
  // Strictly positive: the smallest force stands a million times above the bound on its
  // distance to an exact self-stress, which the balance in MPFR makes tiny (< 1e-30 here).
  EXPECT_TRUE(c.strictly_positive) << what;
  EXPECT_GT(c.stress.min_force, 1e6L * c.force_error) << what;
  EXPECT_LT(c.force_error, 1e-30L) << what;
  EXPECT_EQ(a.stress.forces.size(), a.pattern.bonds.size()) << what;
  // Pair forces sum to 1.
  long double pairs = 0;
  for (std::size_t b = 0; b < a.pattern.bonds.size(); ++b)
    if (!a.pattern.bonds[b].is_wall()) pairs += a.stress.forces[b];
  EXPECT_NEAR(static_cast<double>(pairs), 1.0, 1e-15) << what;
}

TEST(CertifyMultiprecision, N188DoublePrecisionDeclinesAndMultiprecisionCertifies) {
  // build --n 188 (vacancy-segment k=17 p=2): the lattice Delta(19) less 2 disks, its rows
  // slipping by ~1e-11 relative. Double precision cannot tell its bonds from its near contacts.
  const Packing start = built("t188-built.txt");
  ASSERT_EQ(start.size(), 188u);
  AnalysisOptions double_only;
  double_only.multiprecision_certificate = false;
  const auto d = analyze_packing(start, double_only);
  EXPECT_FALSE(d.certified()) << d.status();
  EXPECT_FALSE(d.precise);

  const auto a = analyze_packing(start, {});
  expect_resolved(a, "n = 188");
  EXPECT_EQ(a.pattern.rattlers.size(), 0u);
  // Denser than the lattice Delta(19) (d = 1/18) by the slip, and never below the start.
  EXPECT_GT(a.pattern.packing.d, 1.0L / 18 * (1 + 1e-12L));
  EXPECT_GE(a.pattern.packing.d, start.d);
  // The certified d does not depend on the digits: polished again at twice the digits, it
  // agrees to every digit of the first but the last two (the guard digits absorb the rest).
  const auto& p = *a.precise;
  const MultiprecisionPolish twice =
      polish_multiprecision(a.pattern.packing, a.pattern.bonds, a.pattern.rattlers, 2 * p.digits);
  ASSERT_TRUE(twice.converged);
  const auto digits = static_cast<std::size_t>(p.digits - 2);
  EXPECT_EQ(twice.d.substr(0, digits), p.identification.polish.d.substr(0, digits));
}

TEST(CertifyMultiprecision, N169DropsTheFalseContactTheWidestRuleKeeps) {
  // build --n 169 (Delta(18) less 2): a true contact starts 1.9e-10 d open while the false one,
  // 27-44, is 8.9e-11 d open; the multiprecision certificate still finds the bonds and certifies.
  const auto a = analyze_packing(built("t169-built.txt"), {});
  expect_resolved(a, "n = 169");
  EXPECT_FALSE(
      std::binary_search(a.pattern.bonds.begin(), a.pattern.bonds.end(), Bond::pair(27, 44)));
}

TEST(CertifyMultiprecision, ABuildWhoseBondsTheMultiprecisionPathIdentifiedIsVerified) {
  // The builder's pattern (here every disk a rattler, no bond list) differs from the certified
  // geometry's; the geometry's bonds are trusted, the builder's must all be contacts of it (none
  // here) and its d the certified one (pipeline/build.cpp, BuildResult::verified).
  pipeline::BuildResult b;
  b.pattern.packing = built("t188-built.txt");
  for (int i = 0; i < 188; ++i) b.pattern.rattlers.push_back(i);
  AnalysisOptions options;
  options.reference_bonds = b.pattern.bonds;
  options.reference_rattlers = b.pattern.rattlers;
  b.analysis = analyze_packing(b.pattern.packing, options);
  ASSERT_TRUE(b.analysis->precise);
  EXPECT_FALSE(b.bonds_match());
  EXPECT_EQ(b.analysis->precise->reference_open, 0);
  EXPECT_TRUE(b.verified()) << b.analysis->status();
  // The catalogue's expected counts apply to the certified bonds.
  b.bonds_expected = static_cast<long long>(b.analysis->pattern.bonds.size()) + 1;
  EXPECT_FALSE(b.verified());
  b.bonds_expected = static_cast<long long>(b.analysis->pattern.bonds.size());
  EXPECT_TRUE(b.verified());
  // A builder bond open at the certified configuration (a gap of ~1 d) is a claim that fails.
  b.pattern.bonds = {Bond::pair(0, 100)};
  options.reference_bonds = b.pattern.bonds;
  b.analysis = analyze_packing(b.pattern.packing, options);
  ASSERT_TRUE(b.analysis->precise);
  EXPECT_EQ(b.analysis->precise->reference_open, 1);
  EXPECT_FALSE(b.verified());
}

TEST(CertifyMultiprecision, AResolvedDoublePrecisionCertificateDoesNotRunIt) {
  // t22a's double-precision margins are resolved by orders of magnitude: no multiprecision stage.
  const std::string file = std::string(TRIPACK_TEST_DATA) + "/layouts/t22a.pck";
  const auto a = analyze_packing(
      packing_from_points(read_packing_file(file), std::nullopt, std::nullopt).packing, {});
  EXPECT_TRUE(a.certified()) << a.status();
  EXPECT_FALSE(a.precise);
}

}  // namespace
}  // namespace tripack
