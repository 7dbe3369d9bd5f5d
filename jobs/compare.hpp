// Constructed vs billiards for one n (docs/certified.md step 6): the catalogue's best builder
// against the best packing billiards runs find: d difference, bonds, rattlers, and whether the
// contact graphs agree up to the triangle's 6 symmetries.
#pragma once

#include <optional>

#include "analysis/compare.hpp"
#include "jobs/billiards_runs.hpp"
#include "pipeline/build.hpp"

namespace tripack::jobs {

struct ConstructedVsBilliards {
  long long n = 0;
  std::optional<pipeline::BestBuild> constructed;  // none: no class of the catalogue contains n
  BilliardsRunsResult billiards;
  // Against the best (first-ranked) billiards packing, when both exist:
  std::optional<Comparison> comparison;
  long double d_relative_difference = 0;  // (d_billiards - d_constructed) / d_constructed
  double seconds = 0;
  bool both() const { return constructed && !billiards.packings.empty(); }
};

// `runs.scene` may be left empty: the default scene for n is used then.
ConstructedVsBilliards compare_constructed(const Catalogue& catalogue, long long n,
                                           BilliardsRunsRequest runs,
                                           const pipeline::BuildSettings& settings,
                                           const JobContext& job = {});

}  // namespace tripack::jobs
