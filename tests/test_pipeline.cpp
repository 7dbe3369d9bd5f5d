// app/pipeline: analyze(build) for every class, conventions and input validation.
#include <gtest/gtest.h>

#include <cmath>

#include "app/pipeline.hpp"
#include "constructors/catalogue.hpp"
#include "constructors/registry.hpp"
#include "core/io.hpp"

namespace tripack::app {
namespace {

const Catalogue& catalogue() {
  static const Catalogue c = Catalogue::load(TRIPACK_DEFAULT_CATALOGUE);
  return c;
}

TEST(Pipeline, AnalyzeOfBuildFindsTheBuildersBondsAndCertifiesEveryClass) {
  // Every class and variant, k = 1..8 (matrix p = 1..3): bonds and rattlers from the geometry
  // alone equal the builder's, the packing is jammed and carries a strictly positive stress.
  // (Delta(k)-1 with its corner removed is jammed too: the LP test finds no motion.)
  int cases = 0;
  for (const auto& c : catalogue().classes()) {
    for (long p = c.has_p ? 1 : 0; p <= (c.has_p ? 3 : 0); ++p) {
      for (long k = c.k_min; k <= 8 && (!c.k_max || k <= c.k_max); ++k) {
        auto variants = catalogue().variants_at(c, k);
        if (variants.empty()) variants.push_back("");
        for (const auto& v : variants) {
          const std::string what =
              c.id + " k=" + std::to_string(k) + " p=" + std::to_string(p) + " " + v;
          const Pattern built = build_pattern(catalogue(), {c.id, k, p, v});
          const Analysis a = analyze_packing(built.packing, {});
          EXPECT_EQ(a.pattern.bonds, built.bonds) << what;
          EXPECT_EQ(a.pattern.rattlers, built.rattlers) << what;
          EXPECT_TRUE(a.rigidity.rigid) << what;
          EXPECT_TRUE(a.stress.strictly_positive) << what;
          EXPECT_TRUE(a.certified()) << what << ": " << a.status();
          EXPECT_LT(std::fabs(a.pattern.packing.d / built.packing.d - 1), 1e-15L) << what;
          ++cases;
        }
      }
    }
  }
  EXPECT_GT(cases, 90);
}

TEST(Pipeline, MultiprecisionDigits) {
  // CONSTRUCTIONS: d(22) = 5 sqrt3 / (20 sqrt3 + 7 + 2 sqrt11) =
  // 0.17939690861186597956121884705073659574141764618876... (50 digits, mpmath).
  const Pattern built = build_pattern(catalogue(), {"even-ripple", 3, 0, ""});
  const Analysis a = analyze_packing(built.packing, {50});
  EXPECT_EQ(a.d_string(50), "0.17939690861186597956121884705073659574141764618876");
}

TEST(Pipeline, ConventionsMapBackToTheUnitTriangle) {
  const Pattern built = build_pattern(catalogue(), {"even-ripple", 3, 0, ""});
  const long double d = built.packing.d;
  // Radius convention: circles of radius r in the side-1 container; their centres fill the
  // triangle inset by r: offset (sqrt3 r, r), side 1 - 2 sqrt3 r (SPEC §1).
  const long double r = radius_from_d(d);
  std::vector<Vec2L> circles;
  for (const auto& p : built.packing.points)
    circles.push_back(Vec2L{kSqrt3 * r, r} + p * (1 - 2 * kSqrt3 * r));
  const Packing back = packing_from_points(circles, Convention::Radius, 22);
  EXPECT_NEAR(back.d, d, 1e-17L);
  for (std::size_t i = 0; i < circles.size(); ++i)
    EXPECT_NEAR(norm(back.points[i] - built.packing.points[i]), 0, 1e-17L);
  // Unit-disk-side: unit circles in a triangle of side S = 2/d + 2 sqrt3; same centres, scaled.
  std::vector<Vec2L> unit;
  for (const auto& p : built.packing.points) unit.push_back(Vec2L{kSqrt3, 1} + p / d);
  const Packing back2 = packing_from_points(unit, Convention::UnitDiskSide, std::nullopt);
  EXPECT_NEAR(back2.d, d, 1e-17L);
  EXPECT_NEAR(side_from_d(back2.d), 2 / d + 2 * kSqrt3, 1e-14L);
}

TEST(Pipeline, BadPointSetsAreRejectedWithOneLine) {
  auto rejects = [](std::vector<Vec2L> pts, std::optional<long long> n, const std::string& needle) {
    try {
      packing_from_points(std::move(pts), Convention::UnitTriangle, n);
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "accepted: " << needle;
  };
  rejects({{0.1L, 0.1L}, {0.5L, 0.2L}}, 3, "expected 3 points");
  rejects({{0.1L, 0.1L}}, std::nullopt, "at least 2");
  rejects({{0.1L, 0.1L}, {0.9L, 0.9L}}, std::nullopt, "outside");
  rejects({{0.1L, 0.1L}, {0.5L, -1e-6L}}, std::nullopt, "outside");
  rejects({{0.3L, 0.1L}, {0.3L, 0.1L}, {0.5L, 0.2L}}, std::nullopt, "coincide");
}

}  // namespace
}  // namespace tripack::app
