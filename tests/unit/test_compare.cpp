// analysis/compare: the triangle's symmetries, and "the same packing" on the twin class (several
// packings with one d, GL1995 Fig.t17 and Sec.5), relabelled, moved and perturbed copies.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <numeric>
#include <random>
#include <utility>

#include "analysis/compare.hpp"
#include "constructors/builders.hpp"

namespace tripack {
namespace {

const Vec2L kCorners[3] = {{0, 0}, {1, 0}, {0.5L, kSqrt3 / 2}};

Pattern shuffled(const Pattern& p, std::uint64_t seed) {
  std::vector<int> perm(p.packing.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::mt19937_64 rng(seed);
  std::shuffle(perm.begin(), perm.end(), rng);
  return relabelled(p, perm);
}

// Every point moved by a random vector of length `noise` d.
Pattern perturbed(const Pattern& p, long double noise, std::uint64_t seed) {
  Pattern out = p;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> angle(0, 2 * std::numbers::pi);
  for (auto& q : out.packing.points) {
    const long double t = angle(rng);
    q += Vec2L{std::cos(t), std::sin(t)} * (noise * p.packing.d);
  }
  return out;
}

// The same disks and bonds at random places in the triangle: only the graph is left to compare.
Pattern scrambled(const Pattern& p, std::uint64_t seed) {
  Pattern out = p;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<long double> u(0, 1);
  for (auto& q : out.packing.points) {
    long double s = u(rng), t = u(rng);
    if (s + t > 1) s = 1 - s, t = 1 - t;
    q = kCorners[1] * s + kCorners[2] * t;
  }
  return out;
}

// Best of 5 runs, in seconds.
double seconds_of(const std::function<void()>& f) {
  double best = 1e300;
  for (int run = 0; run < 5; ++run) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

TEST(CompareSymmetry, MapsTheTriangleOntoItself) {
  for (Symmetry g : kSymmetries) {
    // Corners go to corners, and the wall distances follow the side permutation.
    for (const Vec2L& c : kCorners) {
      const Vec2L image = apply(g, c);
      long double nearest = 1;
      for (const Vec2L& o : kCorners) nearest = std::min(nearest, norm(image - o));
      EXPECT_LT(nearest, 1e-18L) << symmetry_name(g);
    }
    const Vec2L p{0.3L, 0.2L};
    for (Side s : kSides) {
      EXPECT_NEAR(static_cast<double>(wall_distance(p, s, 1.0L)),
                  static_cast<double>(wall_distance(apply(g, p), apply(g, s), 1.0L)), 1e-18)
          << symmetry_name(g) << " " << side_name(s);
    }
    const Vec2L back = apply(inverse(g), apply(g, p));
    EXPECT_LT(norm(back - p), 1e-18L) << symmetry_name(g);
    EXPECT_EQ(compose(inverse(g), g), Symmetry::Identity);
  }
  // The conventions in the header.
  EXPECT_LT(norm(apply(Symmetry::Rotate120, kCorners[0]) - kCorners[1]), 1e-18L);
  EXPECT_EQ(apply(Symmetry::Rotate120, Side::Bottom), Side::Right);
  EXPECT_EQ(apply(Symmetry::MirrorVertical, Side::Left), Side::Right);
  EXPECT_EQ(apply(Symmetry::MirrorLeft, Side::Bottom), Side::Left);
  EXPECT_EQ(apply(Symmetry::MirrorRight, Side::Right), Side::Bottom);
  EXPECT_EQ(compose(Symmetry::Rotate120, Symmetry::Rotate120), Symmetry::Rotate240);
}

TEST(CompareSymmetry, RelabelledRejectsNonPermutations) {
  const Pattern p = build_twin(1, 0);
  EXPECT_THROW(relabelled(p, {0, 1, 2}), std::invalid_argument);
  std::vector<int> twice(p.packing.size(), 0);
  EXPECT_THROW(relabelled(p, twice), std::invalid_argument);
}

TEST(Compare, TwinClassPackingsArePairwiseDistinct) {
  // t17a40, t17a42, t17a43: one d, three packings.
  const std::vector<Pattern> t17{build_twin(2, 0), build_twin(2, 1), build_twin(2, 2)};
  for (std::size_t i = 0; i < t17.size(); ++i) {
    for (std::size_t j = 0; j < t17.size(); ++j) {
      const Comparison c = compare_packings(t17[i], t17[j]);
      EXPECT_TRUE(c.same_n && c.same_d);
      EXPECT_EQ(c.same, i == j) << i << " " << j << ": " << c.reason;
      EXPECT_EQ(c.isomorphic, i == j) << i << " " << j << ": " << c.reason;
    }
  }
  // t31a81.1 and t31a81.2: same d and 81 bonds each; only the graph tells them apart.
  const Pattern m1 = build_twin(3, 1), m2 = build_twin(3, 2);
  ASSERT_EQ(m1.bonds.size(), 81u);
  ASSERT_EQ(m2.bonds.size(), 81u);
  for (const Pattern& b : {m2, shuffled(transformed(m2, Symmetry::MirrorLeft), 7)}) {
    const Comparison c = compare_packings(m1, b);
    EXPECT_TRUE(c.same_d);
    EXPECT_FALSE(c.same) << c.reason;
    EXPECT_FALSE(c.isomorphic) << c.reason;
    EXPECT_FALSE(c.geometric) << c.reason;
    EXPECT_NE(c.reason.find("contact graphs differ"), std::string::npos) << c.reason;
  }
}

TEST(Compare, SymmetricImagesAreTheSame) {
  // t17a42 and t31a81.1 have no symmetry, so the reported map is unique.
  for (const Pattern& p : {build_twin(2, 1), build_twin(3, 1)}) {
    for (Symmetry g : kSymmetries) {
      const Comparison c = compare_packings(p, transformed(p, g));
      EXPECT_TRUE(c.same) << symmetry_name(g) << ": " << c.reason;
      ASSERT_TRUE(c.symmetry.has_value());
      EXPECT_EQ(*c.symmetry, g) << c.reason;
      // And the other way round.
      const Comparison back = compare_packings(transformed(p, g), p);
      ASSERT_TRUE(back.symmetry.has_value());
      EXPECT_EQ(*back.symmetry, inverse(g));
    }
  }
  // Symmetric packings: whatever map is reported must carry a onto b.
  for (const Pattern& p : {build_twin(2, 0), build_twin(3, 3), build_four_delta(3)}) {
    for (Symmetry g : kSymmetries) {
      const Pattern b = transformed(p, g);
      const Comparison c = compare_packings(p, b);
      ASSERT_TRUE(c.same) << symmetry_name(g) << ": " << c.reason;
      EXPECT_TRUE(compare_packings(transformed(p, *c.symmetry), b, 1e-12L).symmetry ==
                  Symmetry::Identity);
    }
  }
}

TEST(Compare, GraphHashIsInvariantAndSeparatesTheT17AndT31Packings) {
  // Invariant: every symmetry and relabelling of t22a, t17a42 and t31a81.1 hashes alike.
  for (const Pattern& p : {build_chain_family({3, 1, 1}), build_twin(2, 1), build_twin(3, 1)}) {
    const std::string h = contact_graph_hash(p);
    EXPECT_EQ(h.size(), 16u);
    for (Symmetry g : kSymmetries)
      EXPECT_EQ(contact_graph_hash(shuffled(transformed(p, g), 31)), h) << symmetry_name(g);
  }
  // Separating: the three t17 packings (one d) and t31a81.1 / t31a81.2 (one d, 81 bonds each)
  // have pairwise different hashes, as their graphs differ (see the test above).
  const std::vector<std::string> t17{contact_graph_hash(build_twin(2, 0)),
                                     contact_graph_hash(build_twin(2, 1)),
                                     contact_graph_hash(build_twin(2, 2))};
  EXPECT_NE(t17[0], t17[1]);
  EXPECT_NE(t17[0], t17[2]);
  EXPECT_NE(t17[1], t17[2]);
  EXPECT_NE(contact_graph_hash(build_twin(3, 1)), contact_graph_hash(build_twin(3, 2)));
}

TEST(Compare, RelabelledCopyIsTheSame) {
  const Pattern p = build_chain_family({3, 1, 1});  // t22a, 2 rattlers
  const Pattern q = shuffled(p, 12345);
  const Comparison c = compare_packings(p, q);
  EXPECT_TRUE(c.same) << c.reason;
  EXPECT_EQ(c.symmetry, Symmetry::Identity);
  const Comparison r = compare_packings(p, shuffled(transformed(p, Symmetry::Rotate240), 99));
  EXPECT_TRUE(r.same) << r.reason;
  EXPECT_EQ(r.symmetry, Symmetry::Rotate240);
}

TEST(Compare, RattlerPositionsDoNotMatter) {
  Pattern p = build_twin(2, 0);
  ASSERT_EQ(p.rattlers.size(), 1u);
  Pattern q = p;
  q.packing.points[p.rattlers[0]] += Vec2L{0.01L, 0.005L};
  EXPECT_TRUE(compare_packings(p, q).same);
}

TEST(Compare, DifferentNOrDIsNotTheSame) {
  const Pattern t17 = build_twin(2, 0), t31 = build_twin(3, 0);
  const Comparison c = compare_packings(t17, t31);
  EXPECT_FALSE(c.same_n);
  EXPECT_FALSE(c.same);
  EXPECT_NE(c.reason.find("n differs"), std::string::npos) << c.reason;

  Pattern scaled = t17;
  scaled.packing.d *= 1 + 1e-6L;
  const Comparison e = compare_packings(t17, scaled);
  EXPECT_TRUE(e.same_n);
  EXPECT_FALSE(e.same_d);
  EXPECT_FALSE(e.same) << e.reason;
  EXPECT_TRUE(e.isomorphic);
  EXPECT_TRUE(e.geometric);
  EXPECT_FALSE(e.symmetry.has_value());
  EXPECT_NE(e.reason.find("d differs"), std::string::npos) << e.reason;
}

TEST(Compare, DistinctPackingsGroupsTheTwinVariants) {
  const Pattern t17a40 = build_twin(2, 0), t17a42 = build_twin(2, 1), t17a43 = build_twin(2, 2);
  const std::vector<Pattern> all{t17a40, transformed(t17a40, Symmetry::MirrorVertical), t17a42,
                                 shuffled(transformed(t17a42, Symmetry::Rotate120), 3), t17a43};
  EXPECT_EQ(distinct_packings(all), (std::vector<int>{0, 0, 1, 1, 2}));
}

TEST(Compare, PerturbedCopies) {
  const Pattern p = build_twin(3, 2);
  const Comparison tiny = compare_packings(p, perturbed(p, 1e-12L, 1));
  EXPECT_TRUE(tiny.same) << tiny.reason;
  // 1e-6 d is far beyond the position tolerance, but the bonds (taken from the pattern) stay.
  const Pattern q = shuffled(transformed(perturbed(p, 1e-6L, 2), Symmetry::MirrorRight), 5);
  const Comparison big = compare_packings(p, q);
  EXPECT_FALSE(big.same);
  EXPECT_FALSE(big.geometric);
  EXPECT_TRUE(big.isomorphic) << big.reason;
  EXPECT_NE(big.reason.find("points differ"), std::string::npos) << big.reason;
}

TEST(Compare, IsomorphismWithoutGeometryUsesVf2) {
  // Same bonds, points elsewhere: only VF2 can find the correspondence.
  const Pattern p = build_twin(3, 1);
  const Pattern q = scrambled(shuffled(transformed(p, Symmetry::Rotate120), 11), 4);
  const Comparison c = compare_packings(p, q);
  EXPECT_TRUE(c.isomorphic) << c.reason;
  EXPECT_FALSE(c.geometric);
  EXPECT_FALSE(c.same);
  EXPECT_NE(c.reason.find("rotate-120"), std::string::npos) << c.reason;

  // Delta(k) and 4Delta(k) have the triangle's full symmetry; VF2 on the colour-refined graphs
  // must still be quick.
  for (const auto& [name, h] : {std::pair{"Delta(30)", build_hexagonal(30)},
                                std::pair{"4Delta(12)", build_four_delta(12)}}) {
    const Pattern hq = scrambled(shuffled(transformed(h, Symmetry::MirrorLeft), 13), 5);
    Comparison hc;
    const double t = seconds_of([&] { hc = compare_packings(h, hq); });
    EXPECT_TRUE(hc.isomorphic) << hc.reason;
    EXPECT_FALSE(hc.geometric);
    // Timing is printed, not asserted: the machines are shared (see docs/performance.md).
    std::printf("[ timing ] VF2 fallback, %s (n = %zu): %.3f ms\n", name, h.packing.size(),
                1e3 * t);
  }
}

TEST(Compare, LargePackingsCompare) {
  const Pattern big = build_four_delta(20);  // n = 840
  ASSERT_EQ(big.packing.size(), 840u);
  const Pattern copy = shuffled(transformed(big, Symmetry::Rotate120), 2024);
  Comparison c;
  const double t_big = seconds_of([&] { c = compare_packings(big, copy); });
  EXPECT_TRUE(c.same) << c.reason;

  const Pattern t22a = build_chain_family({3, 1, 1});
  const Pattern t22b = shuffled(transformed(t22a, Symmetry::MirrorVertical), 8);
  Comparison c22;
  const double t_22 = seconds_of([&] { c22 = compare_packings(t22a, t22b); });
  EXPECT_TRUE(c22.same) << c22.reason;
  std::printf(
      "[ timing ] compare_packings 4Delta(20) (n = 840) vs relabelled rotated copy: "
      "%.3f ms; t22a vs relabelled mirror: %.3f ms\n",
      1e3 * t_big, 1e3 * t_22);
}

}  // namespace
}  // namespace tripack
