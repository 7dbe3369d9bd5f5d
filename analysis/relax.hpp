// Relax: local maximization of the minimum distance from any start (docs/certified.md step 2).
//
// Sequential linear programming with a trust region. At each step an LP over the displacements
// (and the gain in d) keeps every near pair at least d + gain apart using the linearization
// |xi - xj| + u.(di - dj), which never overestimates the new distance (Cauchy-Schwarz), and keeps
// every disk inside (wall constraints are linear and exact). So each accepted step is feasible
// and d never decreases; near a rigid optimum the steps converge quadratically. The LP duals at
// the end are the contact forces: positive ones mark the contacts.
#pragma once

#include <functional>
#include <vector>

#include "core/packing.hpp"

namespace tripack {

struct RelaxOptions {
  long double trust = 0.05L;       // initial trust region: max displacement, in units of d
  long double min_trust = 1e-13L;  // give up shrinking below this (units of d)
  // Stop once an LP gains less than this (relative to d). Soft packings need it small: with a
  // smallest contact force of 6e-6 (sparse-rows k = 7) an error of 1e-9 in d still leaves
  // positions ~1e-4 d off, too far for bond identification.
  long double stationary = 1e-13L;
  int max_iterations = 300;
  // Called after every LP step with its number and the current d (progress lines).
  std::function<void(int step, long double d)> on_step;
};

struct RelaxReport {
  bool converged = false;  // the last LP found no gain above `stationary`
  int iterations = 0;
  // No LP was solved: the start was certified a strict local optimum (pipeline/analyze.cpp), so
  // the step LP could gain nothing; active/forces are then the bonds and the certificate's stress.
  bool fast_path = false;
  // No LP either: the interior-point relax (analysis/interior_relax.hpp) moved the start to a
  // state that certified this way (pipeline/analyze.cpp).
  bool interior = false;
  int newton_steps = 0;  // of the interior-point relax, when it ran
  long double d_start = 0, d_end = 0;
  int lp_columns = 0, lp_rows = 0;  // size of the last LP
  std::vector<Bond> active;         // constraints with positive duals in the last LP, sorted
  std::vector<long double> forces;  // their duals (contact forces, summing to ~1 over pairs)
};

// Relaxes `packing` (unit-triangle coordinates) in place; d becomes the true minimum distance.
// Throws std::invalid_argument for fewer than two disks.
RelaxReport relax_packing(Packing& packing, const RelaxOptions& options = {});

}  // namespace tripack
