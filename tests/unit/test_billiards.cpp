// sim/: the Lubachevsky–Stillinger billiards engine and its scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "sim/billiards.hpp"
#include "sim/effects.hpp"
#include "sim/scene.hpp"

namespace tripack {
namespace {

constexpr double kH = 0.8660254037844386;

// Container positions of disks of diameter `diam` as a scene start (Packing convention).
Scene container_scene(const std::vector<Vec2>& x, const std::vector<Vec2>& v, long double diam) {
  Scene s;
  s.n = static_cast<int>(x.size());
  const long double r = diam / 2, side = 1 - kSqrt3 * diam;
  for (const auto& p : x) s.points.push_back({(p.x - kSqrt3 * r) / side, (p.y - r) / side});
  s.start_d = d_from_diameter(diam);
  s.velocities = v;
  return s;
}

// A random non-overlapping start at a moderate density: a short growth run, shrunk a little.
Scene random_start(int n, std::uint64_t seed, long double shrink) {
  Scene grow = default_scene(n);
  grow.stop.relative_gap = 1e-2;
  std::mt19937_64 rng(seed);
  const BilliardsResult r = run_billiards(grow, rng);
  Packing p = r.packing;
  p.d *= shrink;
  return scene_from_packing(p);
}

double energy(const std::vector<Vec2>& v) {
  double e = 0;
  for (const auto& x : v) e += dot(x, x) / 2;
  return e;
}

TEST(Billiards, ElasticGasConservesEnergyAndNeverOverlaps) {
  Scene s = random_start(50, 1, 0.8L);
  s.stop.max_collisions = 1'000'000;
  std::mt19937_64 rng(2);
  const BilliardsResult r = run_billiards(s, rng);
  EXPECT_EQ(r.stop_reason, "max collisions");
  EXPECT_EQ(r.collisions, 1'000'000u);
  ASSERT_EQ(r.positions.size(), 50u);
  EXPECT_NEAR(r.kinetic_energy_end, r.kinetic_energy_start, 1e-12 * r.kinetic_energy_start);
  EXPECT_NEAR(energy(r.velocities), r.kinetic_energy_start, 1e-12 * r.kinetic_energy_start);
  EXPECT_LE(r.max_overlap, 1e-12);
  EXPECT_FALSE(r.jammed);
  EXPECT_NEAR(static_cast<double>(r.diameter), static_cast<double>(diameter_from_d(s.start_d)),
              1e-15);
}

TEST(Billiards, ElasticGasCheckedAfterEveryEvent) {
  // 10^6 collisions at packing fraction ~0.8, every pair and wall checked after every event.
  Scene s = random_start(50, 3, 0.95L);
  s.stop.max_collisions = 1'000'000;
  BilliardsOptions o;
  o.check_every_event = true;
  std::mt19937_64 rng(4);
  const BilliardsResult r = run_billiards(s, rng, o);
  EXPECT_EQ(r.collisions, 1'000'000u);
  EXPECT_EQ(r.positions.size(), 50u);
  EXPECT_LE(r.max_overlap, 1e-12);
  EXPECT_NEAR(r.kinetic_energy_end, r.kinetic_energy_start, 1e-12 * r.kinetic_energy_start);
}

// Growth from random points to jamming, every pair checked after every event: the neighbourhood
// updates, the growing neighbourhoods and the clock restarts never let a pair overlap.
TEST(Billiards, GrowthToJammingCheckedAfterEveryEvent) {
  for (int n : {22, 100}) {
    Scene s = default_scene(n);
    BilliardsOptions o;
    o.check_every_event = true;
    std::mt19937_64 rng(6);
    const BilliardsResult r = run_billiards(s, rng, o);
    EXPECT_TRUE(r.jammed) << r.stop_reason;
    EXPECT_GT(r.events, 10'000u);
    EXPECT_LE(r.max_overlap, 1e-12) << "n = " << n;
  }
}

// Runs a scene with seed 1 and returns every collision it processed.
std::vector<BilliardsEvent> traced_run(const Scene& s) {
  std::vector<BilliardsEvent> trace;
  BilliardsOptions o;
  o.trace = &trace;
  std::mt19937_64 rng(1);
  run_billiards(s, rng, o);
  return trace;
}

TEST(Billiards, WallReflection) {
  for (double diam : {0.0, 0.2}) {
    Scene s = container_scene({{0.5, 0.3}}, {{0.6, -0.8}}, diam);
    s.stop.max_collisions = 1;  // the first collision (updates are events too)
    const std::vector<BilliardsEvent> trace = traced_run(s);
    ASSERT_EQ(trace.size(), 1u);
    EXPECT_EQ(trace[0].partner, -1 - static_cast<int>(Side::Bottom));
    EXPECT_NEAR(trace[0].time, (0.3 - diam / 2) / 0.8, 1e-14);
    EXPECT_NEAR(trace[0].velocity_i.x, 0.6, 1e-15);
    EXPECT_NEAR(trace[0].velocity_i.y, 0.8, 1e-15);
  }
}

TEST(Billiards, CornerReflectionReversesTheBisector) {
  // From the incentre straight into the bottom-left corner along the bisector: two walls at once.
  const double c = std::sqrt(3.0) / 2, s30 = 0.5;
  Scene s = container_scene({{0.5, 0.5 / std::sqrt(3.0)}}, {{-c, -s30}}, 0.0);
  s.stop.max_events = 8;
  const std::vector<BilliardsEvent> trace = traced_run(s);
  const double hit = 1 / std::sqrt(3.0);
  Vec2 out{};
  int at_corner = 0;
  for (const auto& e : trace)
    if (std::abs(e.time - hit) < 1e-12) out = e.velocity_i, ++at_corner;
  EXPECT_GE(at_corner, 2);
  EXPECT_NEAR(out.x, c, 1e-14);
  EXPECT_NEAR(out.y, s30, 1e-14);
}

TEST(Billiards, TwoDisksCollideAtThePredictedTime) {
  for (double g : {0.0, 0.05}) {
    const double diam = 0.1;
    Scene s = container_scene({{0.3, 0.3}, {0.7, 0.3}}, {{1, 0}, {-1, 0}}, diam);
    if (g > 0) s.growth = GrowthEffect{g, {}};
    s.stop.max_collisions = 1;  // the first collision (updates are events too)
    const std::vector<BilliardsEvent> trace = traced_run(s);
    ASSERT_EQ(trace.size(), 1u);
    EXPECT_EQ(trace[0].partner, 1);
    EXPECT_NEAR(trace[0].time, 0.3 / (2 + g), 1e-12);   // 0.4 - 2t = diam + g t
    EXPECT_NEAR(trace[0].velocity_i.x, -1 - g, 1e-14);  // separate at 2g - u = 2 + 2g
  }
  // An oblique course: solve |dx + dv t| = D + g t in long double.
  for (double g : {0.0, 0.02}) {
    const Vec2 x1{0.3, 0.2}, x2{0.62, 0.31}, v1{0.9, 0.1}, v2{-0.7, -0.2};
    const double diam = 0.08;
    Scene s = container_scene({x1, x2}, {v1, v2}, diam);
    if (g > 0) s.growth = GrowthEffect{g, {}};
    s.stop.max_collisions = 1;  // the first collision (updates are events too)
    const std::vector<BilliardsEvent> trace = traced_run(s);
    const long double dx = 0.32L, dy = 0.11L, vx = -1.6L, vy = -0.3L;
    const long double a = vx * vx + vy * vy - g * g, b = dx * vx + dy * vy - g * diam,
                      cc = dx * dx + dy * dy - diam * diam;
    const long double t = (-b - std::sqrt(b * b - a * cc)) / a;
    ASSERT_EQ(trace.size(), 1u);
    EXPECT_EQ(trace[0].i + trace[0].partner, 1);  // the pair (0, 1), planned by either disk
    EXPECT_NEAR(trace[0].time, static_cast<double>(t), 1e-12);
  }
}

void expect_clean_jam(const BilliardsResult& r) {
  EXPECT_TRUE(r.jammed) << r.stop_reason;
  EXPECT_FALSE(r.stop_reason.empty());
  EXPECT_LE(r.max_overlap, 1e-12);
}

TEST(Billiards, GrowthJamsToTheRelativeGap) {
  for (int n : {22, 100, 260}) {
    std::mt19937_64 rng(7);
    const BilliardsResult r = run_billiards(default_scene(n), rng);
    expect_clean_jam(r);
    EXPECT_LT(r.relative_gap, 1e-12);
    EXPECT_EQ(r.packing.size(), static_cast<std::size_t>(n));
    // d is below Oler's bound and the packing is feasible to 1e-12.
    EXPECT_LE(r.packing.d, 2 / (-3 + std::sqrt(8.0L * n + 1)));
  }
}

TEST(Billiards, DegenerateStartsWallsCornersTouching) {
  // Corners, a wall midpoint, all touching at d = 1/2.
  Packing p;
  p.points = {{0, 0}, {1, 0}, {0.5L, kSqrt3 / 2}, {0.5L, 0}, {0.25L, kSqrt3 / 4}};
  p.d = 0.5L;
  Scene s = scene_from_packing(p, 0.01);
  std::mt19937_64 rng(3);
  const BilliardsResult r = run_billiards(s, rng);
  expect_clean_jam(r);
  EXPECT_GE(r.packing.d, 0.5L - 1e-12L);
}

TEST(Billiards, OneTwoThreeDisks) {
  std::mt19937_64 rng(11);
  const BilliardsResult one = run_billiards(default_scene(1), rng);
  expect_clean_jam(one);
  EXPECT_NEAR(static_cast<double>(one.diameter), 1 / std::sqrt(3.0), 1e-9);  // inscribed disk
  for (int n : {2, 3}) {
    const BilliardsResult r = run_billiards(default_scene(n), rng);
    expect_clean_jam(r);
    EXPECT_NEAR(static_cast<double>(r.packing.d), 1.0, 1e-9) << n;
  }
}

TEST(Billiards, SmallHexagonalAndFourDeltaNumbers) {
  struct Case {
    int n;
    long double d;
  };
  for (const Case c : {Case{3, 1}, Case{4, 1 / kSqrt3}, Case{6, 0.5L}, Case{10, 1 / 3.0L}}) {
    long double best = 0;
    for (std::uint64_t seed = 0; seed < 20 && best < c.d * (1 - 1e-9L); ++seed) {
      std::mt19937_64 rng(seed);
      const BilliardsResult r = run_billiards(default_scene(c.n), rng);
      EXPECT_LE(r.max_overlap, 1e-12);
      best = std::max(best, r.packing.d);
    }
    EXPECT_NEAR(static_cast<double>(best / c.d), 1.0, c.n == 3 ? 1e-9 : 1e-6) << c.n;
  }
}

TEST(Billiards, PinnedDisksStayPut) {
  Scene s = default_scene(12);
  s.pinned = {0, 5};
  std::mt19937_64 rng(5);
  std::mt19937_64 copy = rng;
  // Where the random start puts the disks (diameter 0: the container and Packing coincide).
  std::uniform_real_distribution<double> u01(0, 1);
  std::vector<Vec2> start;
  for (int i = 0; i < 12; ++i) {
    double a = u01(copy), b = u01(copy);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    start.push_back({a + b / 2, b * kH});
  }
  const BilliardsResult r = run_billiards(s, rng);
  EXPECT_TRUE(r.jammed);
  EXPECT_LE(r.max_overlap, 1e-12);
  for (int i : {0, 5}) {
    EXPECT_EQ(r.positions[std::size_t(i)].x, start[std::size_t(i)].x);
    EXPECT_EQ(r.positions[std::size_t(i)].y, start[std::size_t(i)].y);
  }
}

TEST(Billiards, GrowsBackFromAShrunkPattern) {
  // Delta(4) at 0.9 of its d (touching nothing) grows back to d = 1/3.
  Packing p;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; i + j < 4; ++j) p.points.push_back({(i + j / 2.0L) / 3, j * kSqrt3 / 6});
  p.d = 0.3L;
  Scene s = scene_from_packing(p, 0.005);
  std::mt19937_64 rng(9);
  const BilliardsResult r = run_billiards(s, rng);
  expect_clean_jam(r);
  EXPECT_NEAR(static_cast<double>(r.packing.d), 1 / 3.0, 1e-9);
}

TEST(Billiards, ThermostatHoldsTheEnergyAndCapsStop) {
  Scene s = default_scene(40);
  s.thermostat = ThermostatEffect{100};
  s.stop.max_events = 50'000;
  std::mt19937_64 rng(8);
  const BilliardsResult r = run_billiards(s, rng);
  // Pumped by growth for at most 100 collisions since the last rescale: a collision at approach
  // speed w leaves at 2g + w, gaining g^2 + g w (reduced mass 1/2); with g = 0.01 and mean
  // approach speeds ~1.3 (unit rms speed) that is ~1.3 = 6.5% of E = 20 at most on average;
  // 15% allows twice that. Without the thermostat the same run gains far more.
  EXPECT_NEAR(r.kinetic_energy_end, r.kinetic_energy_start, 0.15 * r.kinetic_energy_start);
  EXPECT_EQ(r.stop_reason, "max events");
  EXPECT_FALSE(r.jammed);
  Scene free = s;
  free.thermostat.reset();
  std::mt19937_64 rng_free(8);
  EXPECT_GT(run_billiards(free, rng_free).kinetic_energy_end, 2 * r.kinetic_energy_start);
  Scene slow = default_scene(200);
  slow.growth->rate = 1e-6;
  slow.stop.max_seconds = 0.2;
  const BilliardsResult t = run_billiards(slow, rng);
  EXPECT_EQ(t.stop_reason, "max seconds");
  EXPECT_LT(t.seconds, 1.0);
}

TEST(Billiards, DeterministicForASeed) {
  std::mt19937_64 a(42), b(42);
  const BilliardsResult ra = run_billiards(default_scene(30), a);
  const BilliardsResult rb = run_billiards(default_scene(30), b);
  EXPECT_EQ(ra.events, rb.events);
  EXPECT_EQ(ra.packing.d, rb.packing.d);
  EXPECT_EQ(ra.packing.points, rb.packing.points);
}

TEST(Billiards, SceneParsesEveryKey) {
  const Scene s = parse_scene(R"(
container: triangle
n: 3
initial: {points: [[0, 0], [1, 0], [0.5, 0.8660254037844386]], d: 0.5}
effects:
  growth: {rate: 0.02}
  thermostat: {every: 50}
  pinned: [1]
  stop: {relative_gap: 1e-9, max_events: 1e6, max_seconds: 5}
)");
  EXPECT_EQ(s.n, 3);
  EXPECT_EQ(s.points.size(), 3u);
  EXPECT_EQ(s.start_d, 0.5L);
  ASSERT_TRUE(s.growth && s.thermostat);
  EXPECT_EQ(s.growth->rate, 0.02);
  EXPECT_EQ(s.thermostat->every, 50u);
  EXPECT_EQ(s.pinned, std::vector<int>{1});
  EXPECT_EQ(s.stop.relative_gap, 1e-9);
  EXPECT_EQ(s.stop.max_events, 1'000'000u);
  // Disk 1 is pinned in a corner (two walls): it cannot let the disks grow.
  std::mt19937_64 rng(1);
  const BilliardsResult r = run_billiards(s, rng);
  EXPECT_TRUE(r.jammed);
  EXPECT_EQ(r.stop_reason, "pinned disks touch");
  EXPECT_NEAR(static_cast<double>(r.packing.d), 0.5, 1e-12);
  Scene free = s;
  free.pinned.clear();
  const BilliardsResult f = run_billiards(free, rng);
  EXPECT_NEAR(static_cast<double>(f.packing.d), 1.0, 1e-9);
  // A random start without growth stays at diameter 0 forever: refused, not run to max_seconds.
  EXPECT_THROW(parse_scene("n: 5"), std::runtime_error);
  EXPECT_THROW(parse_scene("n: 5\neffects: {growth: {rate: 0}}"), std::runtime_error);
  EXPECT_NO_THROW(parse_scene("n: 5\neffects: {growth: {rate: 0.01}, thermostat: {}}"));
  // Growth without a thermostat never reaches the stop gap (measured): refused in a YAML scene.
  EXPECT_THROW(parse_scene("n: 5\neffects: {growth: {rate: 0.01}}"), std::runtime_error);
  // Fuzz finding (fuzz/findings/fuzz_scene): non-finite inline start points are one-line errors.
  for (const char* bad : {"[[0.4, .nan], [0.3, 0.1]]", "[[0.4, .inf], [0.3, 0.1]]"}) {
    try {
      parse_scene(std::string("initial: {points: ") + bad + "}");
      ADD_FAILURE() << bad;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("finite"), std::string::npos) << e.what();
    }
  }
}

TEST(Billiards, SceneParsesScheduleShakeAndPattern) {
  const Scene s = parse_scene(R"(
n: 30
effects:
  growth:
    rate: 0.01
    schedule: [{gap: 1e-8, rate: 0.001}, {pressure: 1e3, rate: 0.005}]
  thermostat: {}
  shake: {per_disk: 300, rattler_factor: 50}
)");
  ASSERT_TRUE(s.growth && s.shake);
  ASSERT_EQ(s.growth->schedule.size(), 2u);
  EXPECT_EQ(s.growth->schedule[0].gap, 2 / 1e3);  // pressure p is the gap 2 / p, sorted first
  EXPECT_EQ(s.growth->schedule[0].rate, 0.005);
  EXPECT_EQ(s.growth->schedule[1].gap, 1e-8);
  EXPECT_EQ(s.shake->per_disk, 300u);
  EXPECT_EQ(s.shake->rattler_factor, 50.0);
  const Scene pat = parse_scene("initial: {pattern: matrix, p: 3, k: 1}\neffects: {shake: {}}");
  ASSERT_TRUE(pat.pattern);
  EXPECT_EQ(pat.pattern->class_name, "matrix");
  EXPECT_EQ(pat.pattern->k, 1);
  EXPECT_EQ(pat.pattern->p, 3);
  EXPECT_EQ(pat.shake->per_disk, 200u);  // defaults
  // Nothing can run it until the caller has built the points.
  EXPECT_THROW(validate_scene(pat), std::runtime_error);
}

// The schedule lowers the rate as the pressure rises, and the run still jams cleanly.
TEST(Billiards, GrowthScheduleChangesTheRate) {
  Scene s = default_scene(30);
  s.growth->schedule = {{2e-3, 0.005}, {2e-6, 0.001}};
  std::mt19937_64 rng(5);
  const BilliardsResult r = run_billiards(s, rng);
  expect_clean_jam(r);
  EXPECT_EQ(r.growth_rate, 0.001);  // the last step is passed on the way to a gap of 1e-12
  // A pressure stop rule: the same estimate, p = 2 / gap.
  Scene pressured = default_scene(30);
  pressured.stop.pressure = 1e4;
  std::mt19937_64 rng3(5);
  const BilliardsResult pr = run_billiards(pressured, rng3);
  EXPECT_EQ(pr.stop_reason, "pressure reached");
  EXPECT_LT(pr.relative_gap, 2 / 1e4);
  EXPECT_GT(pr.relative_gap, 1e-7);  // stopped at the first block past it, not at 1e-12
  Scene never = default_scene(30);
  never.growth->schedule = {{1e-13, 0.001}};  // below the stop gap: never reached
  std::mt19937_64 rng2(5);
  const BilliardsResult q = run_billiards(never, rng2);
  expect_clean_jam(q);
  EXPECT_EQ(q.growth_rate, 0.01);
}

// The built-in growth against n (docs/performance.md, "Billiards defaults against n"):
// up to n = 40 the old constant 0.01 (small n keep their cost per run); beyond, 0.01 except while
// the estimated gap is in [0.01, 0.1), where the disks order, at a rate that falls with n, about
// 1e-3 at n = 79 and 1e-4 at n = 254 (where constant 0.01 never reached t254a in 64 runs), and
// never below 3e-5 (the slowest rate measured).
TEST(Billiards, DefaultGrowthSlowsOnlyTheOrderingWindowAndMoreWithN) {
  auto slowest = [](const Scene& s) {
    double r = s.growth->rate;
    for (const auto& st : s.growth->schedule) r = std::min(r, st.rate);
    return r;
  };
  for (int n = 1; n <= 40; ++n) {
    const Scene s = default_scene(n);
    ASSERT_TRUE(s.growth && s.thermostat) << n;
    EXPECT_EQ(s.growth->rate, 0.01) << n;
    EXPECT_TRUE(s.growth->schedule.empty()) << n;
  }
  double previous = 0.01;
  for (int n = 41; n <= 3000; ++n) {
    const Scene s = default_scene(n);
    ASSERT_TRUE(s.growth && s.thermostat) << n;
    EXPECT_NO_THROW(validate_scene(s)) << n;
    const double window = slowest(s);
    EXPECT_LE(window, previous) << n;  // never faster for more disks
    EXPECT_LT(window, 0.01) << n;
    EXPECT_GE(window, 3e-5) << n;
    previous = window;
    // As the engine reads the schedule: fast before the window, slow in it, fast after it.
    const auto rate_at = [&](double gap) {
      return sim_detail::scheduled_rate(s.growth->rate, s.growth->schedule, gap);
    };
    EXPECT_EQ(rate_at(0.5), 0.01) << n;
    EXPECT_EQ(rate_at(0.11), 0.01) << n;
    EXPECT_EQ(rate_at(0.09), window) << n;
    EXPECT_EQ(rate_at(0.011), window) << n;
    EXPECT_EQ(rate_at(0.009), 0.01) << n;
    EXPECT_EQ(rate_at(1e-12), 0.01) << n;
  }
  EXPECT_GT(slowest(default_scene(41)), 1e-3);  // no sudden drop past 40
  EXPECT_NEAR(slowest(default_scene(79)), 1e-3, 0.1e-3);
  EXPECT_NEAR(slowest(default_scene(254)), 1e-4, 0.1e-4);
  EXPECT_EQ(slowest(default_scene(3000)), 3e-5);
}

// What the window is for: from random starts at n = 79 the default jams in t79a (GL1995's
// d(79) = 0.0871159038791759) far more often than constant 0.01 (hit-rate table: 62% of 32 runs
// against 5% of 64; billiards d before any polish, which is within ~1e-13 of the jam's).
TEST(Billiards, DefaultGrowthFindsT79aMoreOftenThanConstantRate) {
  const long double t79a = 0.0871159038791759L;
  Scene constant = default_scene(79);
  constant.growth->schedule.clear();
  int hits_default = 0, hits_constant = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    std::mt19937_64 a(seed), b(seed);
    const BilliardsResult rd = run_billiards(default_scene(79), a);
    const BilliardsResult rc = run_billiards(constant, b);
    expect_clean_jam(rd);
    expect_clean_jam(rc);
    hits_default += std::fabs(rd.packing.d / t79a - 1) < 1e-9L;
    hits_constant += std::fabs(rc.packing.d / t79a - 1) < 1e-9L;
  }
  EXPECT_GE(hits_default, 4);
  EXPECT_GT(hits_default, 2 * hits_constant);
}

// Shaking a jammed state at fixed size: the disks that hardly collide are the rattlers, and a
// pattern's jammed disks never move farther than the remaining gap allows.
TEST(Billiards, ShakingFindsTheRattlersOfAJam) {
  // Jam n = 22 from random points; a disk whose nearest neighbour (or wall) is farther than the
  // diameter by 1e-6 relative, a million times the remaining gap, can only be a rattler.
  for (std::uint64_t seed : {1, 2, 3}) {
    Scene s = default_scene(22);
    s.shake = ShakeEffect{};
    std::mt19937_64 rng(seed);
    const BilliardsResult r = run_billiards(s, rng);
    ASSERT_TRUE(r.jammed);
    ASSERT_EQ(r.shake_hits.size(), 22u);
    EXPECT_EQ(r.shake_collisions, 200u * 22u);
    EXPECT_LE(r.max_overlap, 1e-12);
    std::vector<int> loose;
    const double D = static_cast<double>(r.diameter);
    for (int i = 0; i < 22; ++i) {
      double nearest = INFINITY;
      for (int j = 0; j < 22; ++j)
        if (j != i) nearest = std::min(nearest, norm(r.positions[j] - r.positions[i]));
      for (Side side : kSides)
        nearest = std::min(nearest, 2 * wall_distance(r.positions[i], side, 1.0));
      if (nearest > D * (1 + 1e-6)) loose.push_back(i);
    }
    // A rattler may still touch one neighbour; every loose disk is a rattler.
    for (int i : loose)
      EXPECT_NE(std::find(r.shake_rattlers.begin(), r.shake_rattlers.end(), i),
                r.shake_rattlers.end())
          << "seed " << seed << " disk " << i;
    EXPECT_LE(r.shake_rattlers.size(), 5u);  // a handful, not the jammed disks
  }
}

TEST(Billiards, SceneFromFile) {
  const auto dir = std::filesystem::temp_directory_path() / "tripack_billiards_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "pts.txt") << "0.2 0.1\n0.6 0.2\n0.5 0.5\n";
  std::ofstream(dir / "scene.yaml")
      << "n: 3\ninitial: pts.txt\neffects: {growth: {}, thermostat: {}}\n";
  const Scene s = load_scene((dir / "scene.yaml").string());
  EXPECT_EQ(s.points.size(), 3u);
  EXPECT_GT(s.start_d, 0.3L);
  std::ofstream(dir / "bad.yaml") << "n: 3\ninitial: {file: pts.txt, d: 0.5}\n";
  EXPECT_THROW(load_scene((dir / "bad.yaml").string()), std::runtime_error);
  std::filesystem::remove_all(dir);
}

void expect_one_line_error(const std::string& yaml, const std::string& fragment) {
  try {
    parse_scene(yaml);
    ADD_FAILURE() << "no error for: " << yaml;
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    EXPECT_NE(msg.find(fragment), std::string::npos) << msg;
  }
}

TEST(Billiards, BadScenesGiveOneLineErrors) {
  expect_one_line_error("n: [1, 2", "malformed");
  expect_one_line_error("n: 5\neffects: {wind: {speed: 1}}", "wind");
  expect_one_line_error("n: 5\nshape: square", "shape");
  expect_one_line_error("container: square\nn: 5", "square");
  expect_one_line_error("n: 0", "n must be");
  expect_one_line_error("n: -3", "n must be");
  expect_one_line_error("n: abc", "n");
  expect_one_line_error("n: 2\ninitial: {points: [[0.5, 0.2], [0.52, 0.2]], d: 0.1}", "overlap");
  expect_one_line_error("n: 1\ninitial: {points: [[2, 0.2]]}", "outside");
  expect_one_line_error("n: 5\neffects: {stop: {relative_gap: 0}}", "relative_gap");
  expect_one_line_error("n: 5\neffects: {stop: {relative_gap: 1.5}}", "relative_gap");
  expect_one_line_error("n: 5\neffects: {stop: {max_events: -1}}", "max_events");
  expect_one_line_error("n: 5\neffects: {stop: {max_seconds: -1}}", "max_seconds");
  expect_one_line_error("n: 5\neffects: {pinned: [7]}", "pinned");
  expect_one_line_error("n: 5\neffects: {growth: {rate: -1}}", "growth");
  expect_one_line_error("n: 5\ninitial: /nonexistent/file.txt", "initial file");
  expect_one_line_error("n: 5\neffects: {growth: {schedule: [{pressure: 1e3}]}}", "rate");
  expect_one_line_error("n: 5\neffects: {growth: {schedule: [{pressure: 1, rate: 0.1}]}}",
                        "pressure");
  expect_one_line_error(
      "n: 5\neffects: {growth: {schedule: [{pressure: 1e3, gap: 1e-3, rate: 0.1}]}}", "one of");
  expect_one_line_error("n: 5\neffects: {growth: {schedule: [{gap: 2, rate: 0.1}]}}", "gap");
  expect_one_line_error("n: 5\neffects: {growth: {schedule: [{gap: 0.1, rate: 0}]}}", "rate");
  expect_one_line_error("n: 5\neffects: {shake: {per_disk: 0}}", "per_disk");
  expect_one_line_error("n: 5\neffects: {stop: {pressure: 1}}", "pressure");
  expect_one_line_error("n: 5\neffects: {shake: {rattler_factor: 1}}", "rattler_factor");
  expect_one_line_error("n: 5\neffects: {shake: {wiggle: 3}}", "wiggle");
  expect_one_line_error("initial: {pattern: matrix}", "needs k");
  Scene s = default_scene(0);
  std::mt19937_64 rng(1);
  EXPECT_THROW(run_billiards(s, rng), std::runtime_error);
}

// Refactor equivalence: the engine's end state for fixed scenes and seeds, one scene per
// combination of effects (and the all-effects-compiled-in option). The expected values were
// produced by the engine before the effects became policy types (commit 3a1d470, the old
// Engine<kGrowth, kThermostat, kPinned, kTrack>); any change of the event sequence, however
// small, changes the events, the diameter's last bits or the state hash.
std::uint64_t state_hash(const BilliardsResult& r) {
  std::uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a over the bit patterns
  const auto mix = [&](double x) {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    for (int b = 0; b < 64; b += 8) h = (h ^ ((bits >> b) & 0xff)) * 0x100000001b3ull;
  };
  for (const auto& x : r.positions) mix(x.x), mix(x.y);
  for (const auto& v : r.velocities) mix(v.x), mix(v.y);
  for (double e : r.excursion) mix(e);
  for (std::uint64_t hits : r.shake_hits) mix(static_cast<double>(hits));
  return h;
}

struct EquivalenceCase {
  const char* name;
  std::uint64_t seed;
  double diameter;  // hexadecimal: bit for bit
  std::uint64_t events, collisions;
  std::uint64_t hash;
  const char* stop_reason;
};

Scene equivalence_scene(const std::string& name, BilliardsOptions& o) {
  if (name == "growth+thermostat") return default_scene(22);
  if (name == "growth schedule") return default_scene(60);
  if (name == "growth+thermostat+pinned") {
    Scene s = default_scene(12);
    s.pinned = {0, 5};
    return s;
  }
  if (name == "growth+thermostat+shake") {
    Scene s = default_scene(22);
    s.shake = ShakeEffect{};
    return s;
  }
  if (name == "growth" || name == "growth, all effects compiled in") {
    Scene s = default_scene(40);
    s.thermostat.reset();
    s.stop.max_events = 200'000;
    o.all_policies = name != "growth";
    return s;
  }
  if (name == "growth+pinned") {
    Scene s = default_scene(30);
    s.thermostat.reset();
    s.pinned = {2, 9};
    s.stop.max_events = 100'000;
    return s;
  }
  if (name == "growth+pinned in a corner") {  // growth stops when the pinned disk touches
    Scene s = parse_scene(R"(
n: 3
initial: {points: [[0, 0], [1, 0], [0.5, 0.8660254037844386]], d: 0.5}
effects: {growth: {rate: 0.02}, thermostat: {every: 50}, pinned: [1]}
)");
    s.thermostat.reset();
    return s;
  }
  Scene s = random_start(30, 3, 0.9L);  // the rest start from points, without growth
  s.stop.max_collisions = 20'000;
  if (name.find("thermostat") != std::string::npos) s.thermostat = ThermostatEffect{50};
  if (name.find("pinned") != std::string::npos) {
    s.pinned = {3, 17};
    s.stop.max_events = 20'000;
  }
  return s;
}

TEST(Billiards, SameEndStateAsBeforeTheEffectPolicies) {
  const EquivalenceCase cases[] = {
      {"growth+thermostat", 1, 0x1.1611ff4df7c14p-3, 62000, 54760, 0xd1375708eca54b40ull,
       "relative gap reached"},
      {"growth schedule", 2, 0x1.654a0ac186503p-4, 230000, 209383, 0x289b147b1fe232fbull,
       "relative gap reached"},
      {"growth+thermostat+pinned", 5, 0x1.1119687d4d65ep-4, 1776, 249, 0x15c14430ccb8a772ull,
       "pinned disks touch"},
      {"growth+thermostat+shake", 1, 0x1.1611ff4df7c14p-3, 62000, 54760, 0xc5c476745b3a9596ull,
       "relative gap reached"},
      {"growth", 4, 0x1.a9bf8e1d98188p-4, 200000, 178238, 0x4e2ce9c5b3cef50bull, "max events"},
      {"growth, all effects compiled in", 4, 0x1.a9bf8e1d98188p-4, 200000, 178238,
       0x4e2ce9c5b3cef50bull, "max events"},
      {"growth+pinned", 6, 0x1.b4c499d22128p-4, 100000, 85931, 0xaeba7853b8261ec2ull, "max events"},
      {"growth+pinned in a corner", 1, 0x1.126145e9ecd56p-2, 2, 2, 0x6f71431c8c698c97ull,
       "pinned disks touch"},
      {"elastic", 4, 0x1.c0d7558ccd69fp-4, 21895, 20000, 0x3d08afe43d8a4749ull, "max collisions"},
      {"thermostat", 4, 0x1.c0d7558ccd69fp-4, 21892, 20000, 0xa0feff5eff3b92f9ull,
       "max collisions"},
      // Pinned disks without growth: values after the exit_time fix (a disk at rest in its
      // neighbourhood never leaves it); the old engine processed 20000 updates of the pinned
      // disks at time 0 and no collision here (Billiards.PinnedDisksWithoutGrowthLetTheOthersMove).
      {"pinned", 4, 0x1.c0d7558ccd69fp-4, 20000, 18439, 0x5d9d81fe1d21b1d1ull, "max events"},
      {"thermostat+pinned", 4, 0x1.c0d7558ccd69fp-4, 20000, 18433, 0xd211f04a929c60fcull,
       "max events"},
  };
  for (const auto& c : cases) {
    BilliardsOptions o;
    const Scene s = equivalence_scene(c.name, o);
    std::mt19937_64 rng(c.seed);
    const BilliardsResult r = run_billiards(s, rng, o);
    EXPECT_EQ(static_cast<double>(r.diameter), c.diameter) << c.name;
    EXPECT_EQ(r.events, c.events) << c.name;
    EXPECT_EQ(r.collisions, c.collisions) << c.name;
    EXPECT_EQ(state_hash(r), c.hash) << c.name;
    EXPECT_EQ(r.stop_reason, c.stop_reason) << c.name;
  }
}

// Each effect describes itself for the reports (sim/effects/*.hpp), in the effect list's order,
// and only when the scene uses it.
TEST(Billiards, EffectsDescribeThemselves) {
  const Scene s = parse_scene(R"(
n: 22
effects:
  growth: {rate: 0.01, schedule: [{pressure: 1e3, rate: 0.005}]}
  thermostat: {}
  shake: {per_disk: 300}
  pinned: [4, 7]
)");
  const std::vector<std::string> expected{
      "growth at rate 0.01, 0.005 below an estimated gap of 0.002",
      "thermostat every 10 n = 220 collisions",
      "shake 300 collisions per disk (rattlers: 20x fewer than the median disk)",
      "pinned disks 4 7"};
  EXPECT_EQ(describe_effects(s), expected);
  Scene plain = s;
  plain.shake.reset();
  plain.pinned.clear();
  plain.thermostat = ThermostatEffect{50};
  EXPECT_EQ(describe_effects(plain).back(), "thermostat every 50 collisions");
  EXPECT_TRUE(describe_effects(scene_from_packing(Packing{{{0, 0}}, 1})).empty());
}

// A disk at rest in a neighbourhood that does not shrink (a pinned disk without growth) never
// leaves it. exit_time read that never as now, so such a disk had an update event at the same
// time over and over: an elastic run with pinned disks did nothing but those until max_events,
// and shaking with pinned disks (always elastic) never collided.
TEST(Billiards, PinnedDisksWithoutGrowthLetTheOthersMove) {
  Scene s = random_start(30, 3, 0.9L);
  s.pinned = {3, 17};
  s.stop.max_collisions = 20'000;
  std::mt19937_64 rng(4);
  const BilliardsResult r = run_billiards(s, rng);
  EXPECT_EQ(r.stop_reason, "max collisions");
  EXPECT_EQ(r.collisions, 20'000u);
  EXPECT_LT(r.events, 30'000u);
  EXPECT_LE(r.max_overlap, 1e-12);
  for (int i : s.pinned) {  // (to the rounding of the container <-> Packing mapping)
    EXPECT_NEAR(double(r.packing.points[std::size_t(i)].x), double(s.points[std::size_t(i)].x),
                1e-15)
        << i;
    EXPECT_NEAR(double(r.packing.points[std::size_t(i)].y), double(s.points[std::size_t(i)].y),
                1e-15)
        << i;
  }
  Scene shaken = random_start(30, 3, 0.9L);
  shaken.pinned = {3, 17};
  shaken.shake = ShakeEffect{50, 20};
  std::mt19937_64 rng2(4);
  const BilliardsResult sh = run_billiards(shaken, rng2);
  EXPECT_EQ(sh.stop_reason, "shake only");
  EXPECT_EQ(sh.shake_collisions, 50u * 30u);
  EXPECT_EQ(sh.excursion[3], 0.0);  // the pinned disks are hit but never move
  EXPECT_EQ(sh.excursion[17], 0.0);
  EXPECT_GT(sh.excursion[0], 0.0);
  EXPECT_LT(sh.shake_seconds, 5.0);
}

}  // namespace
}  // namespace tripack
