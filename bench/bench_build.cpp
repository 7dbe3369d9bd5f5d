// Build and polish time against n (the goals: 10^6 disks built in < 1 s; polish of n ~ 10^4 in < 2
// s). Run: build/bench/bench_build --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <random>

#include "constructors/builders.hpp"
#include "polish/polish.hpp"

namespace tripack {
namespace {

void report_n(benchmark::State& state, std::size_t n) {
  state.counters["n"] = static_cast<double>(n);
}

// Builders already deliver the bond system solved to long double rounding, where the polish has
// nothing to do. A realistic polish starts from coordinates known to ~1e-12 (a file, a relaxed
// billiards state): perturb every coordinate and d by a relative 1e-12, seeded.
Pattern perturbed(Pattern p) {
  std::mt19937_64 rng(20261121);
  std::uniform_real_distribution<long double> u(-1e-12L, 1e-12L);
  for (auto& x : p.packing.points) x = {x.x + u(rng) * p.packing.d, x.y + u(rng) * p.packing.d};
  p.packing.d *= 1 + u(rng);
  return p;
}

template <class Builder>
void bench_build(benchmark::State& state, Builder&& builder) {
  std::size_t n = 0;
  for (auto _ : state) {
    Pattern p = builder(state.range(0));
    n = p.packing.size();
    benchmark::DoNotOptimize(p.packing.points.data());
  }
  report_n(state, n);
}

template <class Builder>
void bench_polish(benchmark::State& state, Builder&& builder) {
  const Pattern base = perturbed(builder(state.range(0)));
  for (auto _ : state) {
    state.PauseTiming();
    Pattern p = base;
    state.ResumeTiming();
    const auto rep = polish_bond_system(p.packing, p.bonds, p.rattlers);
    if (!rep.converged || rep.factorizations == 0) state.SkipWithError("polish did not converge");
    benchmark::DoNotOptimize(p.packing.d);
  }
  report_n(state, base.packing.size());
}

// Closed-form builders (construction only): k = 707 gives 4Delta(k) = 1,001,112 disks.
void BM_BuildFourDelta(benchmark::State& s) {
  bench_build(s, [](long k) { return build_four_delta(k); });
}
BENCHMARK(BM_BuildFourDelta)
    ->Arg(10)
    ->Arg(32)
    ->Arg(100)
    ->Arg(316)
    ->Arg(707)
    ->Unit(benchmark::kMillisecond);

void BM_BuildTwin(benchmark::State& s) {
  bench_build(s, [](long k) { return build_twin(k, 0); });
}
BENCHMARK(BM_BuildTwin)->Arg(10)->Arg(100)->Arg(707)->Unit(benchmark::kMillisecond);

// Chain family (matrix row p=3 at growing k, and Delta(2p)+1 at growing p).
void BM_BuildMatrixP3(benchmark::State& s) {
  bench_build(s, [](long k) { return build_chain_family({3, k, 1}); });
}
BENCHMARK(BM_BuildMatrixP3)->Arg(10)->Arg(100)->Arg(350)->Unit(benchmark::kMillisecond);

void BM_BuildEvenRipple(benchmark::State& s) {
  bench_build(s, [](long p) { return build_chain_family({p, 1, 1}); });
}
BENCHMARK(BM_BuildEvenRipple)->Arg(3)->Arg(11)->Arg(70)->Arg(700)->Unit(benchmark::kMillisecond);

void BM_BuildOddRipple(benchmark::State& s) {
  bench_build(s, [](long k) { return build_odd_ripple_depressed(k); });
}
BENCHMARK(BM_BuildOddRipple)->Arg(3)->Arg(7)->Arg(22)->Arg(70)->Unit(benchmark::kMillisecond);

// Polish of the full bond system from a 1e-12 start (sparse QR + long double residuals).
void BM_PolishFourDelta(benchmark::State& s) {
  bench_polish(s, [](long k) { return build_four_delta(k); });
}
BENCHMARK(BM_PolishFourDelta)
    ->Arg(3)
    ->Arg(10)
    ->Arg(22)
    ->Arg(50)
    ->Arg(71)
    ->Unit(benchmark::kMillisecond);

void BM_PolishEvenRipple(benchmark::State& s) {
  bench_polish(s, [](long p) { return build_chain_family({p, 1, 1}); });
}
BENCHMARK(BM_PolishEvenRipple)
    ->Arg(3)
    ->Arg(11)
    ->Arg(22)
    ->Arg(50)
    ->Arg(70)
    ->Unit(benchmark::kMillisecond);

void BM_PolishOddRipple(benchmark::State& s) {
  bench_polish(s, [](long k) { return build_odd_ripple_depressed(k); });
}
BENCHMARK(BM_PolishOddRipple)->Arg(3)->Arg(7)->Arg(22)->Arg(70)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tripack

BENCHMARK_MAIN();
