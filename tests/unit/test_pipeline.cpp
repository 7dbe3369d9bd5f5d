// pipeline/: analyze(build) for every class, conventions and input validation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "analysis/compare.hpp"
#include "analysis/interior_relax.hpp"
#include "constructors/catalogue.hpp"
#include "constructors/registry.hpp"
#include "core/io.hpp"
#include "core/points.hpp"
#include "core/ranking.hpp"
#include "jobs/billiards_runs.hpp"
#include "pipeline/analyze.hpp"
#include "pipeline/build.hpp"
#include "sim/billiards.hpp"

namespace tripack::pipeline {
namespace {

const Catalogue& catalogue() {
  static const Catalogue c = Catalogue::load(TRIPACK_DEFAULT_CATALOGUE);
  return c;
}

// `build --n` weighs every variant, not only the default: GL1995 sec. 5 says the other
// modification of Delta(2k+1)+1 is the better one at k = 3, 4 and the depressed one from k = 5.
TEST(Pipeline, BuildBestForNWeighsEveryVariant) {
  BuildSettings quick;
  quick.certify = false;
  EXPECT_EQ(build_best_for_n(catalogue(), 29, quick).best.pattern.provenance.variant, "other");
  EXPECT_EQ(build_best_for_n(catalogue(), 46, quick).best.pattern.provenance.variant, "other");
  const BestBuild at67 = build_best_for_n(catalogue(), 67, quick);
  EXPECT_EQ(at67.best.pattern.provenance.variant, "depressed");
  // Both odd-ripple variants were built (67 = Delta(12) - 11 is also a vacancy-segment member).
  EXPECT_EQ(
      std::count_if(at67.candidates.begin(), at67.candidates.end(),
                    [](const BuildCandidate& c) { return c.member.class_id == "odd-ripple"; }),
      2);
}

TEST(Pipeline, AnalyzeOfBuildFindsTheBuildersBondsAndCertifiesEveryClass) {
  // Every class and variant, k = 1..8 (matrix p = 1..3): bonds and rattlers from the geometry
  // alone equal the builder's, the packing is jammed and carries a strictly positive stress.
  // (Delta(k)-1 with its corner removed is jammed too: the LP test finds no motion.)
  int cases = 0;
  for (const auto& c : catalogue().classes()) {
    for (long p = c.has_p ? c.p_min : 0; p <= (c.has_p ? c.p_min + 2 : 0); ++p) {
      for (long k = c.k_min; k <= 8 && (!c.k_max || k <= c.k_max); ++k) {
        // The discovered classes relax every vacancy segment of their lattice: above n = 150 a
        // member costs seconds (tests/unit/test_vacancy_segment.cpp builds larger ones).
        if (c.claim_status == "discovered" && catalogue().n_of(c, k, p) > 150) continue;
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

TEST(Pipeline, ABuiltOptimumSkipsTheRelaxLPAndAMissingContactDoesNot) {
  // The built state certifies without LPs (relax's fast path) ...
  const Pattern built = build_pattern(catalogue(), {"even-ripple", 3, 0, ""});
  const Analysis fast = analyze_packing(built.packing, {});
  EXPECT_TRUE(fast.relax.fast_path);
  EXPECT_EQ(fast.relax.iterations, 0);
  EXPECT_TRUE(fast.fast.accepted);
  EXPECT_TRUE(fast.certified()) << fast.status();
  EXPECT_EQ(fast.pattern.bonds, built.bonds);
  // ... but with one held disk pushed 1e-3 d off a contact (that contact missing, others
  // overlapping) it is no optimum: the fast path declines and relax's LPs recover the packing.
  Packing moved = built.packing;
  // (a disk off the walls: relax would project a wall overlap away before measuring d)
  std::vector<char> walled(built.packing.size(), 0);
  for (const auto& b : built.bonds)
    if (b.is_wall()) walled[static_cast<std::size_t>(b.a)] = 1;
  const Bond contact = *std::find_if(built.bonds.begin(), built.bonds.end(), [&](const Bond& b) {
    return !b.is_wall() && !walled[static_cast<std::size_t>(b.a)] &&
           !std::binary_search(built.rattlers.begin(), built.rattlers.end(), b.a);
  });
  auto& p = moved.points[static_cast<std::size_t>(contact.a)];
  const Vec2L away = p - moved.points[static_cast<std::size_t>(contact.b)];
  p = p + away / norm(away) * (1e-3L * moved.d);
  const Analysis slow = analyze_packing(moved, {});
  EXPECT_FALSE(slow.relax.fast_path);
  EXPECT_GE(slow.relax.iterations, 1);
  EXPECT_LT(slow.relax.d_start, built.packing.d * (1 - 1e-5L));  // the start was no optimum
  EXPECT_TRUE(slow.certified()) << slow.status();
  EXPECT_EQ(slow.pattern.bonds, built.bonds);
  EXPECT_LT(std::fabs(slow.pattern.packing.d / built.packing.d - 1), 1e-14L);
}

// Every coordinate of `pk` moved by up to `amplitude` d (seeded uniform).
Packing perturbed(const Packing& pk, long double amplitude, std::uint64_t seed) {
  Packing out = pk;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<long double> u(-amplitude, amplitude);
  for (auto& x : out.points) x = {x.x + u(rng) * pk.d, x.y + u(rng) * pk.d};
  return out;
}

TEST(Pipeline, InteriorRelaxRecoversAPerturbedPatternWithoutLPs) {
  // Even-ripple k = 6 (n = 79) with every coordinate moved by up to 1e-5 d is no
  // optimum; the interior-point relax brings it back to the built packing, which then certifies
  // without any LP: same bonds, d equal to the builder's (its closed form) to 1e-14.
  const Pattern built = build_pattern(catalogue(), {"even-ripple", 6, 0, ""});
  const Packing start = perturbed(built.packing, 1e-5L, 7);
  AnalysisOptions interior;
  interior.interior_from = 0;
  const Analysis a = analyze_packing(start, interior);
  ASSERT_TRUE(a.interior.has_value());
  EXPECT_TRUE(a.interior->converged);
  EXPECT_TRUE(a.relax.interior);
  EXPECT_EQ(a.relax.iterations, 0);  // no LP step
  EXPECT_TRUE(a.certified()) << a.status();
  EXPECT_EQ(a.pattern.bonds, built.bonds);
  EXPECT_EQ(a.pattern.rattlers, built.rattlers);
  EXPECT_LT(std::fabs(a.pattern.packing.d / built.packing.d - 1), 1e-14L);
  EXPECT_LT(a.relax.d_start, built.packing.d * (1 - 1e-6L));  // the start was no optimum
  // Below interior_from (500 by default) the LP relax decides: the same packing and verdict.
  const Analysis lp = analyze_packing(start, {});
  EXPECT_FALSE(lp.interior.has_value());
  EXPECT_GE(lp.relax.iterations, 1);
  EXPECT_TRUE(lp.certified()) << lp.status();
  EXPECT_EQ(lp.pattern.bonds, built.bonds);
  EXPECT_LT(std::fabs(lp.pattern.packing.d / built.packing.d - 1), 1e-14L);
}

TEST(Pipeline, InteriorRelaxNeverLowersDAndDeclinesToTheLPs) {
  // An interior-point relax that cannot finish (one Newton step per stage: no stage is centred)
  // leaves d where it was, and the pipeline then hands over to the LPs: verdict, bonds and d
  // exactly those of the LP path alone.
  const Pattern built = build_pattern(catalogue(), {"even-ripple", 4, 0, ""});
  const Packing start = perturbed(built.packing, 1e-4L, 3);
  AnalysisOptions capped;
  capped.interior_from = 0;
  capped.interior.max_stage_steps = 1;
  Packing moved = start;
  const InteriorRelaxReport report = interior_relax(moved, capped.interior);
  EXPECT_FALSE(report.converged);
  EXPECT_GE(moved.d, report.d_start);
  const Analysis a = analyze_packing(start, capped);
  const Analysis lp = analyze_packing(start, {});
  ASSERT_TRUE(a.interior.has_value());
  EXPECT_FALSE(a.relax.interior);
  EXPECT_GE(a.relax.iterations, 1);
  EXPECT_EQ(a.status(), lp.status());
  EXPECT_EQ(a.pattern.bonds, lp.pattern.bonds);
  EXPECT_EQ(a.pattern.packing.d, lp.pattern.packing.d);
  EXPECT_TRUE(a.certified()) << a.status();
  // Above lp_limit the LPs do not run: the interior result is reported, not certified, and its
  // d is never below the start's.
  AnalysisOptions no_lps = capped;
  no_lps.lp_limit = 0;
  const Analysis skipped = analyze_packing(start, no_lps);
  EXPECT_TRUE(skipped.lps_skipped);
  EXPECT_EQ(skipped.relax.iterations, 0);
  EXPECT_FALSE(skipped.certified());
  EXPECT_NE(skipped.status().find("not certified"), std::string::npos) << skipped.status();
  EXPECT_GE(skipped.pattern.packing.d, report.d_start);
}

TEST(Pipeline, ProgressReportsEveryStageInOrder) {
  // The events a progress line shows: the start's check, the interior-point relax step by step,
  // then the check of its result.
  const Pattern built = build_pattern(catalogue(), {"even-ripple", 6, 0, ""});
  AnalysisOptions options;
  options.interior_from = 0;
  std::vector<Progress> events;
  options.progress = [&](const Progress& p) { events.push_back(p); };
  const Analysis a = analyze_packing(perturbed(built.packing, 1e-5L, 7), options);
  ASSERT_TRUE(a.relax.interior);
  std::vector<std::string> stages;
  int last_step = -1;
  for (const auto& e : events) {
    if (stages.empty() || stages.back() != e.stage) {
      stages.push_back(e.stage);
      last_step = -1;
    }
    EXPECT_GT(e.step, last_step) << e.stage;  // steps count up within a stage
    last_step = e.step;
  }
  // (The perturbed start's few contacts within 1e-6 d hold no disk: the start's check ends at
  // its bonds.)
  const std::vector<std::string> expected = {
      "bonds + polish of the start", "relax (interior point)", "bonds + polish of the start",
      "LP-free certificate of the start"};
  EXPECT_EQ(stages, expected);
  EXPECT_EQ(last_step, 0);
  // One event at the start of the relax and one per accepted Newton step: every step but the
  // last of each stage, which only finds the stage centred.
  ASSERT_TRUE(a.interior.has_value());
  EXPECT_EQ(std::count_if(events.begin(), events.end(),
                          [](const auto& e) { return e.stage == "relax (interior point)"; }),
            1 + a.interior->newton_steps - a.interior->stages);
}

TEST(Pipeline, RandomPointsGetAVerdictNotAnLPFailure) {
  // 40 random points (seed 11) relax to a row of 9 disks spanning the bottom side (d = 1/8, the
  // side divided into 8 gaps) held by no strictly surrounding contacts: every disk is a rattler.
  // The stress LP once failed here (CLP status 4 on an empty pair-force row).
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<long double> u(0, 1);
  Packing start;
  while (start.points.size() < 40) {
    const Vec2L p{u(rng), u(rng)};
    if (wall_distance(p, Side::Left, 1.0L) > 0 && wall_distance(p, Side::Right, 1.0L) > 0)
      start.points.push_back(p);
  }
  const Analysis a = analyze_packing(start, {});
  EXPECT_FALSE(a.certified());
  EXPECT_NE(a.status().find("every disk is a rattler"), std::string::npos) << a.status();
  EXPECT_NEAR(static_cast<double>(a.pattern.packing.d), 0.125, 1e-14);
}

TEST(Pipeline, MultiprecisionDigits) {
  // docs/classes.md: d(22) = 5 sqrt3 / (20 sqrt3 + 7 + 2 sqrt11) =
  // 0.17939690861186597956121884705073659574141764618876... (50 digits, mpmath).
  const Pattern built = build_pattern(catalogue(), {"even-ripple", 3, 0, ""});
  AnalysisOptions fifty;
  fifty.digits = 50;
  const Analysis a = analyze_packing(built.packing, fifty);
  EXPECT_EQ(a.d_string(50), "0.17939690861186597956121884705073659574141764618876");
}

TEST(Pipeline, ConventionsMapBackToTheUnitTriangle) {
  const Pattern built = build_pattern(catalogue(), {"even-ripple", 3, 0, ""});
  const long double d = built.packing.d;
  // Radius convention: circles of radius r in the side-1 container; their centres fill the
  // triangle inset by r: offset (sqrt3 r, r), side 1 - 2 sqrt3 r (docs/conventions.md).
  const long double r = radius_from_d(d);
  std::vector<Vec2L> circles;
  for (const auto& p : built.packing.points)
    circles.push_back(Vec2L{kSqrt3 * r, r} + p * (1 - 2 * kSqrt3 * r));
  const Packing back =
      packing_from_points({circles, {}, {}, "x y", {}, {}, {}}, Convention::Radius, 22).packing;
  EXPECT_NEAR(back.d, d, 1e-17L);
  for (std::size_t i = 0; i < circles.size(); ++i)
    EXPECT_NEAR(norm(back.points[i] - built.packing.points[i]), 0, 1e-17L);
  // Unit-disk-side: unit circles in a triangle of side S = 2/d + 2 sqrt3; same centres, scaled.
  std::vector<Vec2L> unit;
  for (const auto& p : built.packing.points) unit.push_back(Vec2L{kSqrt3, 1} + p / d);
  const Packing back2 =
      packing_from_points({unit, {}, {}, "x y", {}, {}, {}}, Convention::UnitDiskSide, std::nullopt)
          .packing;
  EXPECT_NEAR(back2.d, d, 1e-17L);
  EXPECT_NEAR(side_from_d(back2.d), 2 / d + 2 * kSqrt3, 1e-14L);
}

TEST(Pipeline, BadPointSetsAreRejectedWithOneLine) {
  auto rejects = [](std::vector<Vec2L> pts, std::optional<long long> n, const std::string& needle) {
    try {
      packing_from_points({std::move(pts), {}, {}, "x y", {}, {}, {}}, Convention::UnitTriangle, n);
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "accepted: " << needle;
  };
  rejects({{0.1L, 0.1L}, {0.5L, 0.2L}}, 3, "expected 3 points");
  rejects({{0.1L, 0.1L}}, std::nullopt, "at least 2");
  rejects({{0.1L, 0.1L}, {0.9L, 0.9L}}, std::nullopt, "outside");
  // Beyond the 1e-6 rounding tolerance (tests/unit/test_points.cpp covers the tolerated side).
  rejects({{0.1L, 0.1L}, {0.5L, -1e-5L}}, std::nullopt, "outside");
  rejects({{0.3L, 0.1L}, {0.3L, 0.1L}, {0.5L, 0.2L}}, std::nullopt, "coincide");
}

// Billiards from random starts, then the analysis: the first certified end state whose d matches
// `target` to 1e-12 relative within `max_runs` seeds, or nullopt.
std::optional<Analysis> billiards_find(int n, long double target, int max_runs) {
  for (int seed = 1; seed <= max_runs; ++seed) {
    std::mt19937_64 rng(static_cast<std::uint64_t>(seed));
    const BilliardsResult sim = run_billiards(default_scene(n), rng);
    Analysis a = analyze_packing(sim.packing, {});
    if (a.certified() && std::fabs(a.pattern.packing.d / target - 1) < 1e-12L) return a;
  }
  return std::nullopt;
}

TEST(Pipeline, BilliardsReproducesTheKnownOptimaUpTo15And22) {
  // n = 2..15: the catalogue's closed forms (Oler 1961 for Delta(k) and Delta(k)-1; 4Delta(1),
  // twin k=1 (t7a), sparse-rows k=2, 3 (t8a, t13a), even-ripple k=2 (t11a, Melissen), 4Delta(2)
  // (t12a)); n = 22: d(22) = 0.179396908611866 (GL1995 Fig.t22). At most 50 runs each.
  for (int n = 2; n <= 15; ++n) {
    long double best = 0;
    for (const auto& m : catalogue().classify(n)) {
      const Pattern p = build_pattern(catalogue(), {m.cls->id, m.k, m.p, ""});
      best = std::max(best, p.packing.d);
    }
    EXPECT_TRUE(billiards_find(n, best, 50).has_value())
        << "n = " << n << ", d = " << static_cast<double>(best);
  }
  const auto t22a = billiards_find(22, 0.179396908611866L, 50);
  ASSERT_TRUE(t22a.has_value());
  EXPECT_EQ(t22a->pattern.bonds.size(), 47u);
  EXPECT_EQ(t22a->pattern.rattlers.size(), 2u);
  // Its contact graph (rattlers removed, walls as coloured vertices) is the builder's matrix
  // p = 3, k = 1 graph, up to the triangle's symmetries and relabelling.
  const Pattern built = build_pattern(catalogue(), {"matrix", 1, 3, ""});
  const Comparison c = compare_packings(built, t22a->pattern);
  EXPECT_TRUE(c.same) << c.reason;
  EXPECT_TRUE(c.isomorphic);
}

TEST(Pipeline, BilliardsFromABuiltPatternStaysInIt) {
  // Start t22a, t31a81.2 and 4Delta(3) at 0.999 of their d (the scene starts from the points at
  // their own d; shrink by moving towards the centroid) with growth: the jammed state certifies
  // as the same packing as the builder's.
  for (const BuildRequest& req :
       {BuildRequest{"even-ripple", 3, 0, ""}, BuildRequest{"twin", 3, 0, "cavity-2"},
        BuildRequest{"four-delta", 3, 0, ""}}) {
    const Pattern built = build_pattern(catalogue(), req);
    Packing start = built.packing;
    const Vec2L c{0.5L, kSqrt3 / 6};
    for (auto& p : start.points) p = c + (p - c) * 0.999L;
    start.d *= 0.999L;
    Scene scene = scene_from_packing(start, 0.005);
    scene.stop.max_seconds = 60;
    std::mt19937_64 rng(11);
    const BilliardsResult sim = run_billiards(scene, rng);
    EXPECT_TRUE(sim.jammed) << req.class_id << ": " << sim.stop_reason;
    const Analysis a = analyze_packing(sim.packing, {});
    EXPECT_TRUE(a.certified()) << req.class_id;
    const Comparison cmp = compare_packings(built, a.pattern);
    EXPECT_TRUE(cmp.same) << req.class_id << ": " << cmp.reason;
  }
}

// Shaking at fixed size (sim/) and the analysis' geometry (relax, LP loads) agree on rattlers.
// The shake judges the run's end state, the analysis the relaxed jam, which can still catch a
// disk the run had not (a disk with one near contact at the end of the run, held by three after
// relax): every rattler of the analysis is a shaken rattler, and a shaken rattler that the
// analysis holds is loose in the end state (its near contacts leave an angular gap of pi).
// Built patterns are exact jams: there both agree exactly (t22a = matrix p=3 k=1 with 2
// rattlers, GL1995 Fig.t22; twin cavity-2 k=3; 4Delta(3) has none).
TEST(Pipeline, ShakingNamesTheRattlersTheAnalysisFinds) {
  int extra = 0, total = 0;
  for (int n : {22, 31})
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
      Scene s = default_scene(n);
      s.shake = ShakeEffect{};
      std::mt19937_64 rng(seed);
      const BilliardsResult r = run_billiards(s, rng);
      const Analysis a = analyze_packing(r.packing, {});
      const auto& shaken = r.shake_rattlers;
      for (int i : a.pattern.rattlers)
        EXPECT_TRUE(std::binary_search(shaken.begin(), shaken.end(), i))
            << "n = " << n << ", seed " << seed << ": rattler " << i << " not shaken loose";
      const double D = static_cast<double>(r.diameter);
      for (int i : shaken) {
        ++total;
        if (std::binary_search(a.pattern.rattlers.begin(), a.pattern.rattlers.end(), i)) continue;
        ++extra;
        // Directions to the near contacts (disks and walls within 1e-9 relative): the disk is
        // held only if they leave no angular gap of pi or more.
        std::vector<double> angle;
        for (int j = 0; j < n; ++j)
          if (const Vec2 dx = r.positions[j] - r.positions[i]; j != i && norm(dx) < D * (1 + 1e-9))
            angle.push_back(std::atan2(dx.y, dx.x));
        for (Side side : kSides)
          if (2 * wall_distance(r.positions[i], side, 1.0) < D * (1 + 1e-9)) {
            const Vec2 out = wall_normal<double>(side) * -1.0;
            angle.push_back(std::atan2(out.y, out.x));
          }
        std::sort(angle.begin(), angle.end());
        double widest = angle.empty() ? 2 * M_PI : 2 * M_PI - (angle.back() - angle.front());
        for (std::size_t k = 1; k < angle.size(); ++k)
          widest = std::max(widest, angle[k] - angle[k - 1]);
        EXPECT_GE(widest, M_PI - 1e-9) << "n = " << n << ", seed " << seed << ": disk " << i;
      }
    }
  EXPECT_LE(extra, total / 4);  // mostly the same disks
  for (const BuildRequest& req :
       {BuildRequest{"matrix", 1, 3, ""}, BuildRequest{"twin", 3, 0, "cavity-2"},
        BuildRequest{"four-delta", 3, 0, ""}}) {
    const Pattern built = build_pattern(catalogue(), req);
    Scene s = scene_from_packing(built.packing);
    s.shake = ShakeEffect{};
    std::mt19937_64 rng(3);
    const BilliardsResult r = run_billiards(s, rng);
    EXPECT_EQ(r.shake_rattlers, built.rattlers) << req.class_id;
    EXPECT_LE(r.max_overlap, 1e-12) << req.class_id;
  }
}

}  // namespace
}  // namespace tripack::pipeline

namespace tripack::pipeline {
namespace {

TEST(Labels, RankLettersContinuePastZ) {
  // Bijective base 26: a..z, then aa..az, ba.., zz, aaa; every rank has one label, all distinct.
  EXPECT_EQ(rank_letters(0), "a");
  EXPECT_EQ(rank_letters(25), "z");
  EXPECT_EQ(rank_letters(26), "aa");
  EXPECT_EQ(rank_letters(27), "ab");
  EXPECT_EQ(rank_letters(51), "az");
  EXPECT_EQ(rank_letters(52), "ba");
  EXPECT_EQ(rank_letters(701), "zz");
  EXPECT_EQ(rank_letters(702), "aaa");
  std::set<std::string> seen;
  for (std::size_t r = 0; r < 20000; ++r) {
    const std::string s = rank_letters(r);
    EXPECT_TRUE(std::all_of(s.begin(), s.end(), [](char c) { return c >= 'a' && c <= 'z'; }));
    EXPECT_TRUE(seen.insert(s).second) << s;
  }
}

TEST(Labels, SharedDGetsBondCountsAndSharedBondsGetSuffixes) {
  // The paper's naming (GL1995): t17a40, t17a42 share d; t31a81.1, t31a81.2 share d and bonds.
  const std::vector<RankKey> keys{
      {0.30L, 42}, {0.30L * (1 - 1e-14L), 40}, {0.29L, 40}, {0.28L, 81}, {0.28L, 81}, {0.27L, 30}};
  const auto labels = paper_labels(17, keys);
  EXPECT_EQ(labels,
            (std::vector<std::string>{"t17a42", "t17a40", "t17b", "t17c81.1", "t17c81.2", "t17d"}));
  // Fifty ranks: the 27th is t17aa.
  std::vector<RankKey> many;
  for (int i = 0; i < 50; ++i) many.push_back({1.0L - i * 1e-3L, 10});
  const auto long_labels = paper_labels(17, many);
  EXPECT_EQ(long_labels[25], "t17z");
  EXPECT_EQ(long_labels[26], "t17aa");
  EXPECT_EQ(std::set<std::string>(long_labels.begin(), long_labels.end()).size(), 50u);
}

// The atlas confirms a value d(n). Delta(k) - 1 has d = 1/(k-1) with its vacancy at any
// site (distinct contact graphs), so runs that end in different vacancy places all reach d(n);
// a packing whose d differs by 1e-13 (further apart than any two values of one n met: 8e-12 at
// n = 74) is another value and confirms nothing of it.
TEST(Labels, ConfirmationsCountEveryPackingOfTheSameValue) {
  const auto record = [](long double d, long long runs, long long independent, bool builder) {
    PackingRecord r;
    r.d = PreciseReal(d);
    r.sources.push_back({PackingSource::Kind::Billiards, "", 7, runs, independent});
    if (builder) r.sources.push_back({PackingSource::Kind::Builder, "hexagonal-minus-one k=16"});
    return r;
  };
  const long double d = 1.0L / 15;  // Delta(16) - 1 = 135
  std::vector<PackingRecord> records{record(d, 0, 0, true), record(d * (1 + 2e-19L), 3, 2, false),
                                     record(d, 1, 1, false), record(d * (1 - 1e-13L), 9, 9, false)};
  EXPECT_EQ(records[1].confirmations(), 2);  // its own: a continued search does not confirm
  count_value_confirmations(records);
  EXPECT_EQ(records[0].confirmations(), 1 + 2 + 1);
  EXPECT_EQ(records[1].confirmations(), 4);
  EXPECT_EQ(records[2].confirmations(), 4);
  EXPECT_EQ(records[3].confirmations(), 9);
  EXPECT_EQ(records[0].own_confirmations(), 1);  // the builder's packing itself
  count_value_confirmations(records);            // counted again: the same (own counts only)
  EXPECT_EQ(records[2].confirmations(), 4);
}

TEST(BilliardsRuns, RankingDoesNotDependOnThreads) {
  // Run r uses seed + r whatever thread runs it, and ties are broken by bonds then seed: one and
  // two threads give the same labels, d and counts (n = 22: t22a d = 0.179396908611866, GL1995).
  jobs::BilliardsRunsRequest runs;
  runs.scene = default_scene(22);
  runs.runs = 12;
  const auto one = jobs::billiards_runs(runs);
  runs.threads = 2;
  const auto two = jobs::billiards_runs(runs);
  ASSERT_EQ(one.packings.size(), two.packings.size());
  for (std::size_t i = 0; i < one.packings.size(); ++i) {
    EXPECT_EQ(one.packings[i].label, two.packings[i].label);
    EXPECT_EQ(one.packings[i].pattern.packing.d, two.packings[i].pattern.packing.d);
    EXPECT_EQ(one.packings[i].runs(), two.packings[i].runs());
  }
  for (std::size_t r = 0; r < one.runs.size(); ++r) EXPECT_EQ(one.runs[r].label, two.runs[r].label);
  ASSERT_FALSE(one.packings.empty());
  EXPECT_EQ(one.packings.front().label, "t22a");
  EXPECT_NEAR(static_cast<double>(one.packings.front().pattern.packing.d), 0.179396908611866,
              1e-14);
}

}  // namespace
}  // namespace tripack::pipeline
