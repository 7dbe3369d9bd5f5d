#include "jobs/compare.hpp"

#include "core/timing.hpp"

namespace tripack::jobs {

ConstructedVsBilliards compare_constructed(const Catalogue& catalogue, long long n,
                                           BilliardsRunsRequest runs,
                                           const pipeline::BuildSettings& settings,
                                           const JobContext& job) {
  const auto start = Clock::now();
  ConstructedVsBilliards result;
  result.n = n;
  if (!catalogue.classify(n).empty())
    result.constructed =
        pipeline::build_best_for_n(catalogue, n, settings, {job.cancel, {}, job.tool_version});
  if (runs.scene.n == 0) runs.scene = default_scene(static_cast<int>(n));
  prepare_scene(catalogue, runs.scene, n);
  result.billiards = billiards_runs(runs, job);
  if (result.both()) {
    const pipeline::BuildResult& best = result.constructed->best;
    const Pattern& built = best.analysis ? best.analysis->pattern : best.pattern;
    const Pattern& found = result.billiards.packings.front().pattern;
    result.comparison = compare_packings(built, found);
    result.d_relative_difference = (found.packing.d - built.packing.d) / built.packing.d;
  }
  result.seconds = seconds_since(start);
  return result;
}

}  // namespace tripack::jobs
