#include "jobs/billiards_runs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "constructors/registry.hpp"
#include "core/ranking.hpp"
#include "core/timing.hpp"
#include "runner/runner.hpp"

namespace tripack::jobs {

void prepare_scene(const Catalogue& catalogue, Scene& scene, long long expected_n) {
  if (scene.pattern) {
    const auto& req = *scene.pattern;
    const BuildRequest request{req.class_name, static_cast<long>(req.k),
                               req.p ? static_cast<long>(*req.p) : 0, req.variant};
    const Pattern built = build_pattern(catalogue, request);
    if (scene.n && scene.n != static_cast<int>(built.packing.size()))
      throw std::invalid_argument(
          fmt::format("the scene has n = {} but pattern {} k={} has {} disks", scene.n,
                      req.class_name, req.k, built.packing.size()));
    scene.n = static_cast<int>(built.packing.size());
    scene.points = built.packing.points;
    scene.start_d = built.packing.d;
  }
  if (expected_n && scene.n != expected_n)
    throw std::invalid_argument(
        fmt::format("the scene has n = {} but {} was asked for", scene.n, expected_n));
  validate_scene(scene);
}

namespace {

// Every run on the runner's threads; run r uses seed + r.
std::vector<RunOutcome> run_all(const BilliardsRunsRequest& request, const JobContext& job) {
  std::vector<RunOutcome> runs(static_cast<std::size_t>(request.runs));
  const ProgressFn progress = serialised(job.progress);
  ProgressCounter counter("billiards", request.runs);
  JobItems items;
  items.count = runs.size();
  items.run = [&](std::size_t r) {
    RunOutcome& run = runs[r];
    run.seed = request.seed + r;
    std::mt19937_64 rng(run.seed);
    BilliardsOptions options;
    options.cancel = job.cancel;
    if (progress)
      options.progress = [&, r](const Progress& live) {
        Progress p = live;
        p.item = fmt::format("run {}", r);
        p.done = counter.done();
        p.total = request.runs;
        progress(p);
      };
    try {
      run.sim = run_billiards(request.scene, rng, options);
      if (request.scene.n >= 2 && request.certify)
        run.analysis = pipeline::analyze_packing(run.sim.packing, {});
    } catch (const std::exception& e) {
      run.error = e.what();
    }
    run.ran = true;  // not when abandoned (Abandoned passes through to the runner)
    return std::string();
  };
  items.finished = [&](std::size_t r, const std::string&) {
    Progress p = counter.finished(fmt::format("run {}", r), runs[r].sim.packing.d);
    if (progress) progress(p);
  };
  ThreadExecutor(request.threads).run_items(items, job.cancel);
  return runs;
}

// Distinct usable end states (core/record.hpp's same_packing), ranked and labelled
// (core/ranking.hpp): the first run in seed order gives a packing its pattern, so the result
// never depends on thread timing.
std::vector<PackingRecord> distinct_of(std::vector<RunOutcome>& runs, long long n) {
  std::vector<std::size_t> usable;
  std::vector<PackingRecord> found;
  for (std::size_t r = 0; r < runs.size(); ++r)
    if (runs[r].analysis && runs[r].analysis->identification.polish.converged) {
      usable.push_back(r);
      PackingRecord record = pipeline::record_of(*runs[r].analysis);
      record.sources.push_back({PackingSource::Kind::Billiards, "", runs[r].seed, 1, 1});
      found.push_back(std::move(record));
    }
  std::vector<std::size_t> group;
  std::vector<PackingRecord> distinct = merge_same_packings(std::move(found), &group);
  const std::vector<std::size_t> order = rank_records(n, distinct);
  std::vector<std::string> label_of_group(order.size());
  for (std::size_t r = 0; r < order.size(); ++r) label_of_group[order[r]] = distinct[r].label;
  for (auto& run : runs) run.label.assign(1, '-');  // (not = "-": GCC 12 -Wrestrict false positive)
  for (std::size_t u = 0; u < usable.size(); ++u) runs[usable[u]].label = label_of_group[group[u]];
  return distinct;
}

}  // namespace

BilliardsRunsResult billiards_runs(const BilliardsRunsRequest& request, const JobContext& job) {
  if (request.runs < 1) throw std::invalid_argument("--runs must be at least 1");
  const auto start = Clock::now();
  BilliardsRunsResult result;
  result.scene = request.scene;
  result.runs_asked = request.runs;
  result.runs = run_all(request, job);
  std::erase_if(result.runs, [](const RunOutcome& run) { return !run.ran; });
  result.cancelled = result.runs.size() < static_cast<std::size_t>(request.runs);
  result.packings = distinct_of(result.runs, request.scene.n);
  result.seconds = seconds_since(start);
  return result;
}

}  // namespace tripack::jobs
