// core/geometry, core/conventions, core/neighbours.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "core/conventions.hpp"
#include "core/geometry.hpp"
#include "core/neighbours.hpp"

namespace tripack {
namespace {

TEST(Geometry, WallDistancesVanishOnTheSidesAndArePositiveInside) {
  const long double s = 1;
  // Vertices lie on two sides each.
  EXPECT_EQ(wall_distance(Vec2L{0, 0}, Side::Bottom, s), 0);
  EXPECT_EQ(wall_distance(Vec2L{0, 0}, Side::Left, s), 0);
  EXPECT_NEAR(wall_distance(Vec2L{1, 0}, Side::Right, s), 0, 1e-18);
  const Vec2L apex{0.5L, kSqrt3 / 2};
  EXPECT_NEAR(wall_distance(apex, Side::Left, s), 0, 1e-18);
  EXPECT_NEAR(wall_distance(apex, Side::Right, s), 0, 1e-18);
  // The centroid is at distance 1/(2 sqrt3) (the inradius) from all three sides.
  const Vec2L c{0.5L, 1 / (2 * kSqrt3)};
  for (Side side : kSides) EXPECT_NEAR(wall_distance(c, side, s), 1 / (2 * kSqrt3), 1e-18);
}

TEST(Geometry, WallNormalIsTheGradientOfWallDistance) {
  const Vec2L p{0.3L, 0.2L};
  const long double h = 1e-7L;
  for (Side side : kSides) {
    const auto nrm = wall_normal<long double>(side);
    const long double gx =
        (wall_distance(Vec2L{p.x + h, p.y}, side, 1.0L) - wall_distance(p, side, 1.0L)) / h;
    const long double gy =
        (wall_distance(Vec2L{p.x, p.y + h}, side, 1.0L) - wall_distance(p, side, 1.0L)) / h;
    EXPECT_NEAR(gx, nrm.x, 1e-9);  // the distance is affine: only rounding in the quotient
    EXPECT_NEAR(gy, nrm.y, 1e-9);
    EXPECT_NEAR(norm(nrm), 1, 1e-18);
  }
}

TEST(Conventions, RadiusAndSideRoundTrip) {
  for (long double d : {1.0L, 0.5L, 0.179396908611866L, 1e-3L}) {
    EXPECT_NEAR(d_from_radius(radius_from_d(d)) / d, 1, 1e-17);
    EXPECT_NEAR(d_from_side(side_from_d(d)) / d, 1, 1e-17);
    for (auto c : {Convention::UnitTriangle, Convention::Radius, Convention::UnitDiskSide})
      EXPECT_NEAR(to_d(from_d(d, c), c) / d, 1, 1e-17);
  }
}

TEST(Conventions, ThreeCirclesClosedForm) {
  // Three circles in the unit triangle (d = 1) have radius (sqrt3 - 1)/4 (Melissen 1993);
  // three unit circles need a triangle of side 2 + 2 sqrt3.
  EXPECT_NEAR(radius_from_d(1), (kSqrt3 - 1) / 4, 1e-18);
  EXPECT_NEAR(side_from_d(1), 2 + 2 * kSqrt3, 1e-17);
}

TEST(Conventions, ParseNames) {
  EXPECT_EQ(parse_convention("radius"), Convention::Radius);
  EXPECT_EQ(parse_convention("unit-disk-side"), Convention::UnitDiskSide);
  EXPECT_EQ(parse_convention("unit-triangle"), Convention::UnitTriangle);
  EXPECT_FALSE(parse_convention("diameter").has_value());
}

TEST(Oler, BoundIsMetByTriangularNumbers) {
  // t(Delta(k)) = k - 1 exactly: 8 Delta(k) + 1 = (2k+1)^2 (Oler 1961).
  for (long long k = 1; k <= 2000; ++k)
    EXPECT_EQ(oler_bound(triangular(k)), static_cast<long double>(k - 1));
  EXPECT_NEAR(oler_delta(22, 5.574232063070546558L), 0.4221647152455112L, 1e-15);
}

TEST(Neighbours, CellGridFindsTheBruteForcePairs) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(0, 10);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<Vec2> pts(400);
    for (auto& p : pts) p = {u(rng), u(rng) * 0.3};
    const double r = 0.7;
    std::set<std::pair<int, int>> grid, brute;
    for_each_pair_within(pts, r, [&](int i, int j, double) { grid.insert({i, j}); });
    for (int i = 0; i < 400; ++i)
      for (int j = i + 1; j < 400; ++j)
        if (norm(pts[i] - pts[j]) <= r) brute.insert({i, j});
    EXPECT_EQ(grid, brute);
  }
}

TEST(Neighbours, FindContactsSeesPairsAndWalls) {
  // Delta(2) in disk units: three mutually touching disks, each on two sides.
  const std::vector<Vec2L> pts{{0, 0}, {1, 0}, {0.5L, kSqrt3 / 2}};
  const auto bonds = find_contacts(pts, 1.0L, 1e-12L);
  EXPECT_EQ(bonds.size(), 3u + 6u);
  std::vector<char> skip{0, 0, 1};
  EXPECT_EQ(find_contacts(pts, 1.0L, 1e-12L, skip).size(), 1u + 4u);
}

}  // namespace
}  // namespace tripack
