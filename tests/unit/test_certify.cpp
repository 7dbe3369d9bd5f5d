// analysis/bonds and analysis/certify: rattlers, rigidity LP, stress certificate, hard cases.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "analysis/bonds.hpp"
#include "analysis/certify.hpp"
#include "constructors/builders.hpp"
#include "polish/polish.hpp"

namespace tripack {
namespace {

TEST(Rattlers, BuilderRattlersAreFoundAndBondsKept) {
  for (const Pattern& pat : {build_chain_family({3, 1, 1}), build_chain_family({6, 1, 1}),
                             build_twin(3, 0), build_odd_ripple_depressed(7)}) {
    std::vector<Bond> bonds = pat.bonds;
    EXPECT_EQ(find_rattlers(pat.packing, bonds), pat.rattlers);
    EXPECT_EQ(bonds, pat.bonds);
  }
}

TEST(Rattlers, ADiskHeldFromOneSideOnlyIsARattler) {
  // Delta(3) without the floor bond of the bottom-middle disk: its four remaining contacts lie in
  // a closed half-plane (0, 60, 120, 180 degrees), so it is not held; its neighbours still are.
  Pattern pat = build_hexagonal(3);
  int middle = -1;
  for (std::size_t i = 0; i < pat.packing.size(); ++i)
    if (std::fabs(pat.packing.points[i].x - 0.5L) < 1e-12L && pat.packing.points[i].y < 1e-12L)
      middle = static_cast<int>(i);
  ASSERT_GE(middle, 0);
  std::vector<Bond> bonds = pat.bonds;
  std::erase(bonds, Bond::wall(middle, Side::Bottom));
  EXPECT_EQ(find_rattlers(pat.packing, bonds), std::vector<int>{middle});
  for (const auto& b : bonds) EXPECT_TRUE(b.a != middle && b.b != middle);
}

TEST(Rattlers, TightCageOf4e9StaysARattler) {
  // t33c: a rattler's gap to its cage is below 4e-9 d (GL1995 Sec.3). Press a rattler of t22a
  // into a corner of its cage, 4e-9 d from two cage disks: those near contacts are candidates
  // (below the 1e-8 d threshold) but do not hold it, and the bonds stay the builder's.
  Pattern pat = build_chain_family({3, 1, 1});
  const int r = pat.rattlers.front();
  const Vec2L x = pat.packing.points[static_cast<std::size_t>(r)];
  std::vector<std::pair<long double, int>> near;
  for (std::size_t i = 0; i < pat.packing.size(); ++i)
    if (static_cast<int>(i) != r &&
        !std::binary_search(pat.rattlers.begin(), pat.rattlers.end(), static_cast<int>(i)))
      near.emplace_back(norm(pat.packing.points[i] - x), static_cast<int>(i));
  std::sort(near.begin(), near.end());
  const Vec2L c1 = pat.packing.points[static_cast<std::size_t>(near[0].second)];
  const Vec2L c2 = pat.packing.points[static_cast<std::size_t>(near[1].second)];
  const long double rho = pat.packing.d * (1 + 4e-9L);
  const Vec2L mid = (c1 + c2) / 2.0L, dv = c2 - c1;
  const long double h = std::sqrt(rho * rho - dot(dv, dv) / 4);
  const Vec2L nrm = Vec2L(-dv.y, dv.x) / norm(dv);
  const Vec2L p1 = mid + nrm * h, p2 = mid - nrm * h;
  pat.packing.points[static_cast<std::size_t>(r)] = norm(p1 - x) < norm(p2 - x) ? p1 : p2;
  const auto gaps = smallest_gaps(pat.packing, pat.bonds, 3);
  ASSERT_NEAR(gaps[0].gap, 4e-9L, 1e-12L);  // the set-up: two gaps of 4e-9 d, nothing closer
  ASSERT_NEAR(gaps[1].gap, 4e-9L, 1e-12L);
  EXPECT_TRUE(gaps[0].rattler);
  Packing pk = pat.packing;
  const BondIdentification id = identify_bonds(pk, {});
  EXPECT_EQ(id.rattlers, pat.rattlers);
  EXPECT_EQ(id.bonds, pat.bonds);
  EXPECT_TRUE(id.polish.converged);
}

TEST(Rigidity, EveryBuiltFamilyIsJammed) {
  for (const Pattern& pat : {build_four_delta(4), build_twin(3, 0), build_twin(3, 2),
                             build_chain_family({4, 2, 1}), build_chain_family({3, 2, 0}),
                             build_odd_ripple_depressed(5), build_hexagonal_minus_one(6)}) {
    const RigidityReport r = test_rigidity(pat.packing, pat.bonds, pat.rattlers);
    EXPECT_TRUE(r.rigid) << pat.packing.size();
    EXPECT_LT(r.opening, 1e-9);
    EXPECT_LT(r.floppy, 1e-9);
  }
}

// Two touching disks on the floor: sliding along it keeps every bond.
struct FloorPair {
  Packing packing;
  std::vector<Bond> bonds;
};
FloorPair floor_pair() {
  FloorPair f;
  f.packing.points = {{0.4L, 0}, {0.6L, 0}};
  f.packing.d = 0.2L;
  f.bonds = {Bond::pair(0, 1), Bond::wall(0, Side::Bottom), Bond::wall(1, Side::Bottom)};
  return f;
}

TEST(Rigidity, AFloorPairIsNotRigidAndTheMotionIsReported) {
  const auto [pk, bonds] = floor_pair();
  const RigidityReport r = test_rigidity(pk, bonds, {});
  EXPECT_FALSE(r.rigid);
  EXPECT_GT(r.opening, 0.5);  // a unit-box motion opens bonds at O(1) rates
  EXPECT_EQ(r.moving_disks, 2);
  EXPECT_GE(r.opening_bonds, 2);
  // The reported motion closes no bond (first order).
  EXPECT_GE(r.motion[0].y, -1e-12L);
  EXPECT_GE(r.motion[1].y, -1e-12L);
  EXPECT_GE(r.motion[1].x - r.motion[0].x, -1e-12L);  // u = (p0 - p1)/|.| = (-1, 0)
}

TEST(Stress, T22aHasAStrictlyPositiveBalancedStress) {
  const Pattern pat = build_chain_family({3, 1, 1});
  const StressReport s = stress_certificate(pat.packing, pat.bonds, pat.rattlers);
  EXPECT_TRUE(s.exists);
  EXPECT_TRUE(s.strictly_positive);
  EXPECT_GT(s.min_force, 1e-3L);  // forces are ~1/(number of pair bonds) = 1/37
  EXPECT_LT(s.residual, 1e-14L);  // CLP's solution, re-balanced in long double
  long double pair_sum = 0;
  for (std::size_t b = 0; b < pat.bonds.size(); ++b) {
    EXPECT_GE(s.forces[b], 0);
    if (!pat.bonds[b].is_wall()) pair_sum += s.forces[b];
  }
  EXPECT_NEAR(pair_sum, 1, 1e-12L);  // KKT: the pair multipliers sum to 1
}

TEST(Stress, NoBalanceWithoutSideWalls) {
  // Two touching disks on the floor: their push apart is horizontal and nothing resists it.
  Packing pk;
  pk.points = {{0.4L, 0}, {0.6L, 0}};
  pk.d = 0.2L;
  const StressReport s = stress_certificate(
      pk, {Bond::pair(0, 1), Bond::wall(0, Side::Bottom), Bond::wall(1, Side::Bottom)}, {});
  EXPECT_FALSE(s.exists);
  EXPECT_FALSE(s.strictly_positive);
}

TEST(HardCases, SparseRowsNearDegenerateContactsPolishAndReportTheirGaps) {
  // docs/classes.md §5-6: smallest raised spacing - 1 = 9.4e-3, 1.5e-3, 1.2e-4, 3.1e-6, 1.9e-8 for
  // k = 8..12 (two printed digits), next to contacts that degenerate super-exponentially. From a
  // 1e-12 perturbation the polish converges (no divergence) and the gaps come out right.
  const long double expected[] = {9.4e-3L, 1.5e-3L, 1.2e-4L, 3.1e-6L, 1.9e-8L};
  for (long k = 8; k <= 12; ++k) {
    Pattern pat = build_chain_family({k, 1, 0});
    std::mt19937_64 rng(static_cast<std::uint64_t>(k));
    std::uniform_real_distribution<long double> u(-1e-12L, 1e-12L);
    for (auto& p : pat.packing.points)
      p = {p.x + u(rng) * pat.packing.d, p.y + u(rng) * pat.packing.d};
    const long double d0 = pat.packing.d;
    const PolishReport rep = polish_bond_system(pat.packing, pat.bonds, pat.rattlers);
    EXPECT_TRUE(rep.converged) << k;
    EXPECT_LT(std::fabs(pat.packing.d / d0 - 1), 1e-11L) << k;
    const long double L = 1 / pat.packing.d;
    long double raised = 1;
    for (const auto& g : smallest_gaps(pat.packing, pat.bonds, 400)) {
      EXPECT_GT(g.gap, 0) << k;
      if (g.contact.is_wall()) continue;
      const long double ya = pat.packing.points[static_cast<std::size_t>(g.contact.a)].y * L;
      const long double yb = pat.packing.points[static_cast<std::size_t>(g.contact.b)].y * L;
      if (ya > 0.5L && ya < 1.2L && yb > 0.5L && yb < 1.2L) raised = std::min(raised, g.gap);
    }
    EXPECT_NEAR(raised, expected[k - 8], 0.05L * expected[k - 8]) << k;
  }
}

TEST(FastCertificate, AcceptsBuiltRipplesWithAStrictlyPositiveBalancedStress) {
  for (long p : {3L, 22L}) {
    const Pattern pat = build_chain_family({p, 1, 1});
    const FastCertificate c = fast_certificate(pat.packing, pat.bonds, pat.rattlers);
    ASSERT_TRUE(c.accepted) << c.declined;
    EXPECT_GT(c.min_eigenvalue, 1e-4);
    EXPECT_TRUE(c.stress.strictly_positive);
    EXPECT_LT(c.stress.residual, 1e-15L);
    long double pair_sum = 0;
    for (std::size_t b = 0; b < pat.bonds.size(); ++b) {
      EXPECT_GT(c.stress.forces[b], 0);
      if (!pat.bonds[b].is_wall()) pair_sum += c.stress.forces[b];
    }
    EXPECT_NEAR(pair_sum, 1, 1e-12L);
    // The LPs agree.
    EXPECT_TRUE(test_rigidity(pat.packing, pat.bonds, pat.rattlers).rigid);
    EXPECT_TRUE(stress_certificate(pat.packing, pat.bonds, pat.rattlers).strictly_positive);
  }
}

TEST(FastCertificate, DeclinesAPlantedFloppyDisk) {
  // t22a with every bond of one held disk but one removed: it slides along that contact.
  const Pattern pat = build_chain_family({3, 1, 1});
  int disk = 0;
  while (std::binary_search(pat.rattlers.begin(), pat.rattlers.end(), disk)) ++disk;
  std::vector<Bond> bonds;
  bool kept = false;
  for (const auto& b : pat.bonds) {
    const bool touches = b.a == disk || (!b.is_wall() && b.b == disk);
    if (touches && kept) continue;
    kept = kept || touches;
    bonds.push_back(b);
  }
  const FastCertificate c = fast_certificate(pat.packing, bonds, pat.rattlers);
  EXPECT_FALSE(c.accepted);
  EXPECT_FALSE(c.declined.empty());
  EXPECT_FALSE(test_rigidity(pat.packing, bonds, pat.rattlers).rigid);  // the LP agrees
}

TEST(FastCertificate, DeclinesWithoutAStrictlyPositiveStress) {
  // The floor pair: sliding along the floor keeps every bond (G^T G is singular) and no stress
  // balances the pair's push.
  const auto [pk, bonds] = floor_pair();
  const FastCertificate c = fast_certificate(pk, bonds, {});
  EXPECT_FALSE(c.accepted);
}

}  // namespace
}  // namespace tripack
