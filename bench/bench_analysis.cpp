// Time of every analysis stage against n (the goal: the whole certify pipeline for n = 254 under
// 1 s; 50 digits for n = 254 under 5 s). Patterns: Delta(2p)+1 for p = 3, 6, 11, 22
// (n = 22, 79, 254, 991). Run: build/bench/bench_analysis
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <stdexcept>
#include <string>

#include "analysis/bonds.hpp"
#include "analysis/certify.hpp"
#include "analysis/relax.hpp"
#include "constructors/builders.hpp"
#include "pipeline/analyze.hpp"
#include "pipeline/build.hpp"
#include "polish/polish.hpp"
#include "polish/polish_mp.hpp"
#include "sim/billiards.hpp"
#include "sim/scene.hpp"

namespace tripack {
namespace {

Pattern ripple(long p) {
  return build_chain_family({p, 1, 1});
}

// Every coordinate moved by a relative `amplitude` of d, seeded: the start the stage sees.
Packing noisy(const Packing& pk, long double amplitude) {
  Packing out = pk;
  std::mt19937_64 rng(20261121);
  std::uniform_real_distribution<long double> u(-amplitude, amplitude);
  for (auto& x : out.points) x = {x.x + u(rng) * out.d, x.y + u(rng) * out.d};
  return out;
}

void set_n(benchmark::State& s, std::size_t n) {
  s.counters["n"] = static_cast<double>(n);
}

void BM_Relax(benchmark::State& s) {
  const Pattern pat = ripple(s.range(0));
  const Packing start = noisy(pat.packing, 1e-4L);
  for (auto _ : s) {
    Packing pk = start;
    benchmark::DoNotOptimize(relax_packing(pk).iterations);
  }
  set_n(s, pat.packing.size());
}

void BM_Bonds(benchmark::State& s) {  // identification + rattlers + polish, from the relaxed state
  const Pattern pat = ripple(s.range(0));
  Packing relaxed = noisy(pat.packing, 1e-4L);
  const RelaxReport r = relax_packing(relaxed);
  for (auto _ : s) {
    Packing pk = relaxed;
    benchmark::DoNotOptimize(identify_bonds(pk, r.active).bonds.size());
  }
  set_n(s, pat.packing.size());
}

void BM_RigidityLP(benchmark::State& s) {
  const Pattern pat = ripple(s.range(0));
  for (auto _ : s)
    benchmark::DoNotOptimize(test_rigidity(pat.packing, pat.bonds, pat.rattlers).rigid);
  set_n(s, pat.packing.size());
}

void BM_StressLP(benchmark::State& s) {
  const Pattern pat = ripple(s.range(0));
  for (auto _ : s)
    benchmark::DoNotOptimize(stress_certificate(pat.packing, pat.bonds, pat.rattlers).min_force);
  set_n(s, pat.packing.size());
}

void BM_Polish15(benchmark::State& s) {  // long double polish from a 1e-12 start
  const Pattern pat = ripple(s.range(0));
  const Packing start = noisy(pat.packing, 1e-12L);
  for (auto _ : s) {
    Packing pk = start;
    benchmark::DoNotOptimize(polish_bond_system(pk, pat.bonds, pat.rattlers).converged);
  }
  set_n(s, pat.packing.size());
}

void BM_Polish50(benchmark::State& s) {  // long double + MPFR to 50 digits, from a 1e-12 start
  const Pattern pat = ripple(s.range(0));
  const Packing start = noisy(pat.packing, 1e-12L);
  for (auto _ : s)
    benchmark::DoNotOptimize(polish_multiprecision(start, pat.bonds, pat.rattlers, 50).converged);
  set_n(s, pat.packing.size());
}

void BM_CertifyPipeline(benchmark::State& s) {  // relax + bonds + polish + rigidity + stress
  const Pattern pat = ripple(s.range(0));
  const Packing start = noisy(pat.packing, 1e-4L);
  for (auto _ : s) {
    const pipeline::Analysis a = pipeline::analyze_packing(start, {});
    if (!a.certified()) s.SkipWithError("not certified");
  }
  set_n(s, pat.packing.size());
}

// The whole analysis of `start` per iteration, its stage times as counters; an error unless it
// certifies (and, with `by_interior`, through the interior-point relax).
void certify_counting_stages(benchmark::State& s, const Packing& start, bool by_interior) {
  for (auto _ : s) {
    const pipeline::Analysis a = pipeline::analyze_packing(start, {});
    if (!a.certified() || (by_interior && !a.relax.interior))
      s.SkipWithError(by_interior ? "not certified by the interior path" : "not certified");
    s.counters["relax_s"] = a.times.relax;
    s.counters["newton"] = a.relax.newton_steps;
    s.counters["bonds_s"] = a.times.bonds;
    s.counters["certify_s"] = a.times.rigidity + a.times.stress;
  }
  set_n(s, start.size());
}

// The whole analysis from the built state (the fast certificate's case), at n = 991,
// 5051, 10154 and 100577 (Delta(2p)+1 for p = 22, 50, 71, 224).
void BM_CertifyBuilt(benchmark::State& s) {
  certify_counting_stages(s, ripple(s.range(0)).packing, false);
}

// The same patterns with every coordinate moved by up to 1e-6 d: no optimum, so the
// start does not certify; the interior-point relax brings it back and the LP-free certificate
// proves the result (no LP at any size).
void BM_CertifyPerturbed(benchmark::State& s) {
  certify_counting_stages(s, noisy(ripple(s.range(0)).packing, 1e-6L), true);
}

// 4Delta(k) with 10^5 disks (k = 224, n = 100,800), built (second argument 0), then
// perturbed by 1e-6 d (1).
void BM_CertifyFourDelta(benchmark::State& s) {
  const Packing built = build_four_delta(s.range(0)).packing;
  certify_counting_stages(s, s.range(1) ? noisy(built, 1e-6L) : built, s.range(1) != 0);
}

#define TRIPACK_RIPPLES \
  ->Arg(22)->Arg(50)->Arg(71)->Arg(224)->Iterations(1)->Unit(benchmark::kMillisecond)
BENCHMARK(BM_CertifyBuilt) TRIPACK_RIPPLES;
BENCHMARK(BM_CertifyPerturbed) TRIPACK_RIPPLES;
BENCHMARK(BM_CertifyFourDelta)
    ->Args({224, 0})
    ->Args({224, 1})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

// A billiards end state (default scene, seed 1): near contacts everywhere, rattlers,
// an imperfect jam; the fast path rarely applies and the LPs decide.
void BM_AnalyzeBilliardsEndState(benchmark::State& s) {
  const int n = static_cast<int>(s.range(0));
  std::mt19937_64 rng(1);
  const BilliardsResult end = run_billiards(default_scene(n), rng);
  for (auto _ : s) {
    const pipeline::Analysis a = pipeline::analyze_packing(end.packing, {});
    s.counters["certified"] = a.certified();
    s.counters["interior"] = a.relax.interior;
    s.counters["lp_steps"] = a.relax.iterations;
    s.counters["relax_s"] = a.times.relax;
    s.counters["bonds_s"] = a.times.bonds;
    s.counters["certify_s"] = a.times.rigidity + a.times.stress;
  }
  s.counters["billiards_s"] = end.seconds;
  set_n(s, static_cast<std::size_t>(n));
}
BENCHMARK(BM_AnalyzeBilliardsEndState)
    ->Arg(1000)
    ->Arg(3000)
    ->Arg(5000)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

// The MPFR polish of an atlas packing to D digits (docs/precision.md): data/atlas/t{n}a.txt
// analysed once in long double (bonds, rattlers), then polish_multiprecision timed alone.
// Arguments {n, D}; counters: Newton iterations, double factorizations, log10 residual.
// The atlas is found beside this file's source, or in $TRIPACK_ATLAS_DIR.
const pipeline::Analysis& atlas_analysis(long n) {
  static std::map<long, pipeline::Analysis> cache;
  auto it = cache.find(n);
  if (it != cache.end()) return it->second;
  const char* env = std::getenv("TRIPACK_ATLAS_DIR");
  const std::filesystem::path dir =
      env ? std::filesystem::path(env)
          : std::filesystem::path(__FILE__).parent_path().parent_path() / "data" / "atlas";
  pipeline::AnalyzeRequest request;
  std::string name = "t";  // appended, not concatenated: GCC 12's -Wrestrict false positive
  name += std::to_string(n);
  name += "a.txt";
  request.file = (dir / name).string();
  return cache.emplace(n, pipeline::analyze_file(request).analysis).first->second;
}

void BM_PolishDigits(benchmark::State& s) {
  const pipeline::Analysis& a = atlas_analysis(s.range(0));
  const Pattern& pat = a.pattern;
  const int digits = static_cast<int>(s.range(1));
  MultiprecisionPolish mp;
  try {
    for (auto _ : s) mp = polish_multiprecision(pat.packing, pat.bonds, pat.rattlers, digits);
  } catch (const std::invalid_argument& e) {  // digits beyond the limit
    s.SkipWithError(e.what());
    return;
  }
  if (!mp.converged) s.SkipWithError("not converged");
  s.counters["digits"] = digits;
  s.counters["iterations"] = mp.iterations;
  s.counters["sweeps"] = mp.sweeps;
  s.counters["factorizations"] = mp.factorizations;
  s.counters["log10_residual"] = mp.log10_max_residual;
  set_n(s, pat.packing.size());
}
BENCHMARK(BM_PolishDigits)
    ->ArgsProduct({{22, 53, 200}, {100, 300, 1000}})
    ->Unit(benchmark::kMillisecond);
// Beyond 1000 digits: one iteration each (up to seconds).
BENCHMARK(BM_PolishDigits)
    ->ArgsProduct({{22, 53, 200}, {2000, 5000, 10000, 20000}})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

#define TRIPACK_SIZES ->Arg(3)->Arg(6)->Arg(11)->Arg(22)->Unit(benchmark::kMillisecond)
BENCHMARK(BM_Relax) TRIPACK_SIZES;
BENCHMARK(BM_Bonds) TRIPACK_SIZES;
BENCHMARK(BM_RigidityLP) TRIPACK_SIZES;
BENCHMARK(BM_StressLP) TRIPACK_SIZES;
BENCHMARK(BM_Polish15) TRIPACK_SIZES;
BENCHMARK(BM_Polish50) TRIPACK_SIZES;
BENCHMARK(BM_CertifyPipeline) TRIPACK_SIZES;

// `build --n N` whole (every member containing N built, the best certified), the work of
// tripack.build(n=N) in Python: bench/python_overhead.py compares the two in one run.
void BM_BuildBestForN(benchmark::State& state) {
  const Catalogue catalogue = Catalogue::load(Catalogue::default_path());
  for (auto _ : state) {
    const auto b = pipeline::build_best_for_n(catalogue, state.range(0), {});
    if (!b.best.record.certified) state.SkipWithError("not certified");
    benchmark::DoNotOptimize(b.best.record.d);
  }
}
BENCHMARK(BM_BuildBestForN)->Arg(22)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tripack

BENCHMARK_MAIN();
