// The Delta(2)-inflation (patterns/inflation.hpp; docs/findings.md §3) and the search's use of it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "core/io.hpp"
#include "core/neighbours.hpp"
#include "formats/formats.hpp"
#include "patterns/inflation.hpp"
#include "pipeline/analyze.hpp"
#include "search/search.hpp"

namespace tripack {
namespace {

// A packing of the committed atlas (data/atlas/LABEL.txt): found by billiards and polished,
// none of it by the inflation.
Packing atlas_packing(const std::string& label) {
  const PointsFile file = read_packing_file(
      (std::filesystem::path(TRIPACK_SOURCE_DIR) / "data" / "atlas" / (label + ".txt")).string());
  Packing p;
  p.points = file.points;
  p.d = file.declared_d.value();
  return p;
}

// The lattice Delta(K) with two adjacent sites vacant inflates to the lattice Delta(2K - 1)
// with three vacant sites in a row: spacing 1/(2K - 2) (the hexagonal packing's d), every
// centre on a site of that lattice.
TEST(Inflation, InflatesTheLatticeToTheLattice) {
  for (long long rows : {4, 7, 10}) {
    Packing base;
    base.d = 1.0L / static_cast<long double>(rows - 1);
    for (long long j = 0; j < rows; ++j)
      for (long long i = 0; i + j < rows; ++i)
        if (!(j == 1 && (i == 1 || i == 2)))  // vacancies (1, 1) and (2, 1)
          base.points.push_back({(i + j / 2.0L) * base.d, j * base.d * kSqrt3 / 2});
    const auto inflated = patterns::inflate_by_two(base);
    ASSERT_TRUE(inflated);
    const long long big = 2 * rows - 1;
    ASSERT_EQ(static_cast<long long>(inflated->size()), big * (big + 1) / 2 - 3);
    const long double spacing = 1.0L / static_cast<long double>(big - 1);
    EXPECT_NEAR(static_cast<double>(inflated->d), static_cast<double>(spacing), 1e-15);
    EXPECT_NEAR(static_cast<double>(min_pair_distance(inflated->points, 1)),
                static_cast<double>(spacing), 1e-15);
    for (const Vec2L& p : inflated->points) {
      const long double j = p.y / (spacing * kSqrt3 / 2), i = p.x / spacing - j / 2;
      EXPECT_NEAR(static_cast<double>(j), std::round(static_cast<double>(j)), 1e-12);
      EXPECT_NEAR(static_cast<double>(i), std::round(static_cast<double>(i)), 1e-12);
      EXPECT_GE(std::round(static_cast<double>(i)), 0);
      EXPECT_LE(std::round(static_cast<double>(i + j)), static_cast<double>(big - 1));
    }
  }
}

// Closed forms: t4a (the Delta(3) - 2 optimum, L = sqrt3) inflates to t12a with L = 2 + sqrt3
// (GL1995 §7: 12 = 4Delta(2)); t8a, d(8) = (sqrt33 - 3)/8, to t25a with L = L(8) + 3 = 4 +
// sqrt(11/3) (docs/classes.md §5: L(Delta(2k+3)-3) = mu_k + k + 1). The inflation is the packing
// itself: its minimum distance is d, and its analysis certifies it.
TEST(Inflation, GivesTheClosedFormsOfTwelveAndTwentyFive) {
  const std::pair<const char*, double> cases[] = {{"t4a", 1 / (2 + std::sqrt(3.0))},
                                                  {"t8a", 1 / (4 + std::sqrt(11.0 / 3))}};
  for (const auto& [label, d] : cases) {
    const auto inflated = patterns::inflate_by_two(atlas_packing(label));
    ASSERT_TRUE(inflated) << label;
    EXPECT_NEAR(static_cast<double>(inflated->d), d, 1e-15) << label;
    const PackingRecord record = pipeline::record_of(pipeline::analyze_packing(*inflated, {}));
    EXPECT_TRUE(record.certified) << label;
    EXPECT_NEAR(static_cast<double>(record.d.value()), d, 1e-15) << label;
  }
}

// findings §3, checked from the atlas's own files: the inflation of the best packing found at
// Delta(k+2) - 2 has the d of the best found at Delta(2k+3) - 3 (both found by billiards, 30
// digits in data/atlas.csv), here to relative 1e-17, and is certified.
TEST(Inflation, InflatesTheAtlasBestsToTheAtlasBests) {
  const std::pair<const char*, const char*> cases[] = {
      {"t26a", "t88a"}, {"t43a", "t150a"}, {"t53a", "t187a"}, {"t12a", "t40a"}, {"t51a", "t183a"}};
  for (const auto& [base, inflated_best] : cases) {
    const auto inflated = patterns::inflate_by_two(atlas_packing(base));
    ASSERT_TRUE(inflated) << base;
    const Packing best = atlas_packing(inflated_best);
    ASSERT_EQ(inflated->size(), best.size()) << base;
    EXPECT_LT(std::fabs(inflated->d / best.d - 1), 1e-17L) << base;
    const PackingRecord record = pipeline::record_of(pipeline::analyze_packing(*inflated, {}));
    EXPECT_TRUE(record.certified) << base;
    EXPECT_LT(std::fabs(record.d.value() / best.d - 1), 1e-17L) << base;
  }
}

// Which n are inflations: Delta(2K-1) - (2m-1) from Delta(K) - m, m >= 2.
TEST(Inflation, NamesTheBaseOfAnInflatedN) {
  const std::pair<long long, long long> bases[] = {{12, 4},   {25, 8},   {40, 12},  {61, 18},
                                                   {150, 43}, {187, 53}, {183, 51}, {144, 40}};
  for (const auto& [n, base] : bases) EXPECT_EQ(patterns::inflation_base(n), base) << n;
  for (long long n : {10, 11, 26, 53, 102, 134, 166, 190})
    EXPECT_FALSE(patterns::inflation_base(n)) << n;
}

// A lattice that does not round site by site (two disks on one site) is refused.
TEST(Inflation, RefusesAPackingOffTheLattice) {
  Packing p;
  p.d = 0.5L;
  p.points = {{0, 0}, {0.01L, 0}, {1, 0}, {0.5L, kSqrt3 / 2}};
  EXPECT_FALSE(patterns::inflate_by_two(p));
}

// The search at n = 150 = Delta(17) - 3 searches 43 = Delta(9) - 2 alongside and reaches the
// atlas's t150a (its d from data/atlas.csv, found by billiards) within 40 steps of one chain.
TEST(Search, ReachesTheInflationOfTheBaseSearch) {
  const long double target = atlas_packing("t150a").d;
  for (std::uint64_t seed : {1, 3}) {
    search::SearchRequest r;
    r.n = 150;
    r.steps = 40;
    r.seconds = 600;
    r.seed = seed;
    r.target = target;
    const search::SearchResult result = search::run_search(r);
    ASSERT_FALSE(result.packings.empty());
    EXPECT_TRUE(result.chains.at(0).target_reached) << seed;
    EXPECT_EQ(result.chains.at(0).base_n, 43);
    EXPECT_GT(result.chains.at(0).base_steps, 0);
    EXPECT_LE(result.chains.at(0).base_steps, result.chains.at(0).steps);
    EXPECT_NEAR(static_cast<double>(result.packings.front().d.value() / target), 1.0, 1e-15)
        << seed;
  }
}

}  // namespace
}  // namespace tripack
