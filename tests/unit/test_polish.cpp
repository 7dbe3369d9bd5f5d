// polish/polish: Newton / Gauss-Newton on the bond system.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bond_systems.hpp"
#include "constructors/builders.hpp"
#include "polish/polish.hpp"

namespace tripack {
namespace {

void perturb(Packing& p, long double amplitude, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<long double> u(-amplitude, amplitude);
  for (auto& x : p.points) x = {x.x + u(rng), x.y + u(rng)};
  p.d *= 1 + u(rng);
}

TEST(Polish, RecoversFourDeltaFromANoisyStart) {
  // GL1995 Sec.5: d(4Delta(k)) = 1/(2k - 2 + sqrt3).
  for (long k : {1, 2, 3, 6}) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      Pattern pat = build_four_delta(k);
      perturb(pat.packing, 1e-5L * pat.packing.d, seed);
      const auto rep = polish_bond_system(pat.packing, pat.bonds, pat.rattlers);
      EXPECT_TRUE(rep.converged);
      EXPECT_EQ(rep.rank, rep.unknowns);  // rigid: full column rank
      // Long double residuals: d to double rounding (1.1e-16) and better.
      EXPECT_NEAR(pat.packing.d * (2 * k - 2 + std::sqrt(3.0L)), 1.0L, 1e-17L);
    }
  }
}

TEST(Polish, OverDeterminedSystemsReachTheRoundingFloor) {
  Pattern pat = build_chain_family({3, 1, 1});  // t22a: 41 unknowns, 47 equations
  perturb(pat.packing, 1e-7, 7);
  const auto rep = polish_bond_system(pat.packing, pat.bonds, pat.rattlers);
  EXPECT_TRUE(rep.converged);
  EXPECT_EQ(rep.unknowns, 41);
  EXPECT_EQ(rep.equations, 47);
  EXPECT_EQ(rep.rank, 41);
  EXPECT_LT(rep.max_residual, 1e-17L);
}

TEST(Polish, RankDeficientSystemsStillConverge) {
  // Under-determined but consistent: a floor pair and a disk with no bonds at all. (Delta(k)-1 is
  // floppy only with unilateral contacts; as a bar framework it is rigid, see test below.)
  auto [p, bonds] = floor_pair_and_an_unbonded_disk();
  const auto rep = polish_bond_system(p, bonds, {});
  EXPECT_TRUE(rep.converged);
  EXPECT_EQ(rep.unknowns, 7);
  EXPECT_EQ(rep.rank, 3);
  EXPECT_NEAR(p.points[1].y, 0, 1e-18L);
  EXPECT_NEAR(norm(p.points[0] - p.points[1]) / p.d, 1, 1e-17L);
}

TEST(Polish, HexagonalMinusOneIsABarRigidFramework) {
  // Removing the corner leaves every remaining disk with >= 2 independent equality constraints:
  // full column rank, and the polish keeps d = 1/(k-1).
  Pattern pat = build_hexagonal_minus_one(5);
  perturb(pat.packing, 1e-9, 3);
  const auto rep = polish_bond_system(pat.packing, pat.bonds, pat.rattlers);
  EXPECT_TRUE(rep.converged);
  EXPECT_EQ(rep.rank, rep.unknowns);
  EXPECT_NEAR(pat.packing.d, 0.25L, 1e-18L);
}

TEST(Polish, RattlersAreNotMoved) {
  Pattern pat = build_chain_family({3, 1, 1});
  const auto before = pat.packing.points;
  polish_bond_system(pat.packing, pat.bonds, pat.rattlers);
  for (int r : pat.rattlers)
    EXPECT_EQ(pat.packing.points[static_cast<std::size_t>(r)], before[static_cast<std::size_t>(r)]);
}

TEST(Polish, InconsistentSystemIsReportedNotConverged) {
  // Three mutually touching disks cannot all lie on the floor.
  Packing p;
  p.points = {{0.1, 0.0}, {0.4, 0.0}, {0.25, 0.2}};
  p.d = 0.3;
  std::vector<Bond> bonds{Bond::pair(0, 1),
                          Bond::pair(1, 2),
                          Bond::pair(0, 2),
                          Bond::wall(0, Side::Bottom),
                          Bond::wall(1, Side::Bottom),
                          Bond::wall(2, Side::Bottom)};
  const auto rep = polish_bond_system(p, bonds, {});
  EXPECT_FALSE(rep.converged);
  EXPECT_GT(rep.max_residual, 1e-3L);
}

TEST(Polish, RejectsBondsToMissingDisks) {
  Packing p;
  p.points = {{0.1, 0.0}};
  p.d = 0.3;
  EXPECT_THROW(polish_bond_system(p, {Bond::pair(0, 5)}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace tripack
