// The billiards engine (docs/billiards.md, §6): events/s while compressing to jamming, the time to
// reach a relative gap of 1e-3 .. 1e-12, and the cost of an effect that is compiled in but absent.
// Single thread. Run: build/bench/bench_billiards
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "sim/billiards.hpp"

namespace tripack {
namespace {

double density(const BilliardsResult& r) {
  const double rad = static_cast<double>(r.diameter) / 2;
  return static_cast<double>(r.positions.size()) * M_PI * rad * rad / (std::sqrt(3.0) / 4);
}

// A start at packing fraction ~0.3: a fast growth run from random points, stopped early.
Scene loose_start(int n, std::uint64_t seed, double* start_density) {
  Scene s = default_scene(n);
  s.growth->rate = 0.05;
  s.stop.relative_gap = 0.3;
  std::mt19937_64 rng(seed);
  BilliardsResult r = run_billiards(s, rng);
  Packing p = r.packing;
  // Shrink to packing fraction 0.3 exactly (the estimate above is rough at low density).
  const long double target_diam = std::sqrt(0.3 * (std::sqrt(3.0) / 4) / (n * M_PI)) * 2;
  if (target_diam < r.diameter) p.d = d_from_diameter(target_diam);
  *start_density = 0.3;
  Scene out = scene_from_packing(p);
  out.growth = GrowthEffect{};
  out.thermostat = ThermostatEffect{};
  return out;
}

void BM_CompressToJamming(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  double rho = 0;
  Scene s = loose_start(n, 1, &rho);
  if (n >= 10000) s.stop.max_events = 100'000'000;  // cap the largest run
  BilliardsResult r;
  double seconds = 0;
  std::uint64_t events = 0, collisions = 0;
  // Three velocity seeds (one at n = 10000): one trajectory's mix of events (and so its rate)
  // varies by ~10%.
  const std::vector<std::uint64_t> seeds =
      n >= 10000 ? std::vector<std::uint64_t>{2} : std::vector<std::uint64_t>{2, 3, 4};
  for (auto _ : state)
    for (std::uint64_t seed : seeds) {
      std::mt19937_64 rng(seed);
      r = run_billiards(s, rng);
      seconds += r.seconds;
      events += r.events;
      collisions += r.collisions;
    }
  state.counters["n"] = n;
  state.counters["events_per_s"] = static_cast<double>(events) / seconds;
  state.counters["collisions_per_s"] = static_cast<double>(collisions) / seconds;
  state.counters["events"] = static_cast<double>(events) / double(seeds.size());  // per run
  state.counters["density_end"] = density(r);
  state.counters["gap_end"] = r.relative_gap;
  state.SetLabel(r.stop_reason);
}

// Time from random points (diameter 0) to an estimated relative gap 10^-range(1).
void BM_TimeToGap(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  Scene s = default_scene(n);
  s.stop.relative_gap = std::pow(10.0, -static_cast<double>(state.range(1)));
  BilliardsResult r;
  for (auto _ : state) {
    std::mt19937_64 rng(3);
    r = run_billiards(s, rng);
  }
  state.counters["n"] = n;
  state.counters["events"] = static_cast<double>(r.events);
  state.counters["events_per_s"] = static_cast<double>(r.events) / r.seconds;
  state.counters["d"] = static_cast<double>(r.packing.d);
  state.counters["gap_estimate"] = r.relative_gap;
}

// Same run (growth, no thermostat, no pins; 2e6 events: without a thermostat the speeds grow and
// jamming is slow) in the engine built for it and in the engine with every effect compiled in but
// unused: the cost of absent effects.
void BM_AbsentEffects(benchmark::State& state) {
  Scene s = default_scene(254);
  s.thermostat.reset();
  s.stop.max_events = 2'000'000;
  BilliardsOptions o;
  o.all_policies = state.range(0) != 0;
  BilliardsResult r;
  double seconds = 0;
  std::uint64_t events = 0;
  for (auto _ : state) {
    std::mt19937_64 rng(4);
    r = run_billiards(s, rng, o);
    seconds += r.seconds;
    events += r.events;
  }
  state.counters["events_per_s"] = static_cast<double>(events) / seconds;
  state.counters["events"] = static_cast<double>(r.events);
  state.SetLabel(o.all_policies ? "all effects compiled in" : "only growth compiled in");
}

BENCHMARK(BM_CompressToJamming)
    ->Arg(22)
    ->Arg(100)
    ->Arg(260)
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_TimeToGap)
    ->ArgsProduct({{22, 79, 254}, {3, 6, 9, 12}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_AbsentEffects)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
}  // namespace tripack

BENCHMARK_MAIN();
