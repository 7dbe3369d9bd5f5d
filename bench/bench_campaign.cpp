// The campaign database's cost per run: one ResultsDb::record (one BEGIN IMMEDIATE
// transaction in WAL mode, synchronous=NORMAL) against the work unit it records (a default-scene
// billiards run and its analysis), at n = 22 and 100. Throughput of whole campaigns (threads,
// mpirun) is bench/campaign_throughput.sh. Run: build/bench/bench_campaign
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <random>
#include <string>

#include "analysis/compare.hpp"
#include "core/io.hpp"
#include "pipeline/analyze.hpp"
#include "sim/billiards.hpp"
#include "sim/scene.hpp"
#include "store/results_db.hpp"

namespace tripack {
namespace {

// A unit as the campaign runs it (jobs/campaign.cpp run_unit): billiards from seed, analysis.
store::RunRecord run_unit(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const BilliardsResult sim = run_billiards(default_scene(n), rng);
  const pipeline::Analysis analysis = pipeline::analyze_packing(sim.packing, {});
  store::RunRecord run;
  run.n = n;
  run.seed = seed;
  run.events = static_cast<long long>(sim.events);
  run.seconds = sim.seconds;
  run.outcome = analysis.certified() ? "certified" : "not certified";
  run.tool_version = "bench";
  if (analysis.certified()) {
    store::StoredPacking p;
    p.n = n;
    p.d = format_significant(analysis.pattern.packing.d, 18);
    p.graph_hash = contact_graph_hash(analysis.pattern);
    p.points = analysis.pattern.packing.points;
    p.bonds = analysis.pattern.bonds;
    p.rattlers = analysis.pattern.rattlers;
    p.certified = true;
    p.first_seed = seed;
    run.packing = p;
  }
  return run;
}

std::string fresh_db() {
  const auto path = (std::filesystem::temp_directory_path() /
                     ("tripack_bench_campaign_" + std::to_string(getpid()) + ".db"))
                        .string();
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path + suffix);
  return path;
}

void BM_UnitRun(benchmark::State& s) {
  const int n = static_cast<int>(s.range(0));
  std::uint64_t seed = 1;
  for (auto _ : s) benchmark::DoNotOptimize(run_unit(n, seed++));
  s.counters["n"] = n;
}
BENCHMARK(BM_UnitRun)->Arg(22)->Arg(100)->Unit(benchmark::kMillisecond);

// Recording a run whose packing is already stored (the common case: the counts go up) and one
// whose packing is new (its coordinates, bonds and rattlers are written).
void record_runs(benchmark::State& s, bool new_packing) {
  const int n = static_cast<int>(s.range(0));
  const store::RunRecord unit = run_unit(n, 1);
  const std::string path = fresh_db();
  store::ResultsDb db = store::ResultsDb::open(path);
  std::uint64_t seed = 1;
  for (auto _ : s) {
    store::RunRecord run = unit;
    run.seed = seed++;
    if (new_packing && run.packing) run.packing->graph_hash = std::to_string(run.seed);
    benchmark::DoNotOptimize(db.record(run));
  }
  s.counters["n"] = n;
  s.counters["bytes_per_run"] = static_cast<double>(std::filesystem::file_size(path) +
                                                    std::filesystem::file_size(path + "-wal")) /
                                static_cast<double>(seed);
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path + suffix);
}
void BM_RecordRunKnownPacking(benchmark::State& s) {
  record_runs(s, false);
}
void BM_RecordRunNewPacking(benchmark::State& s) {
  record_runs(s, true);
}
BENCHMARK(BM_RecordRunKnownPacking)->Arg(22)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RecordRunNewPacking)->Arg(22)->Arg(100)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace tripack

BENCHMARK_MAIN();
