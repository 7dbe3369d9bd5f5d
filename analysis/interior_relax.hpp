// Interior-point relax: the local maximum of the minimum distance near a start, in
// near-linear time, for the states relax's linear programs are slow on (billiards end states:
// their step LPs are massively degenerate; CLP's simplex needs ~30 s per LP at n = 2000).
//
// A log-barrier method on the nonlinear problem itself: maximize
//   F_t(x, D) = t D + sum_pairs log(|xi - xj| - D) + sum_walls log(w_i(x))
// over positions x and a lower bound D on every near pair's distance, for t growing by a factor
// per stage. Each Newton step solves one sparse symmetric positive definite system (the
// Gauss-Newton Hessian: the pair terms' positive curvature across the contact is left out, which
// keeps it definite; the line search uses the true F_t, so every accepted step increases it and
// keeps every slack positive). At the end of stage t, 1/(t s) on a pair is its contact force (the
// forces sum to ~1) and D is within ~m/t of the local maximum.
//
// Unlike relax's linear steps it also follows second-order gains (rows sliding across their
// contacts): on billiards end states it can end higher than relax, at a degenerate maximum that
// the first-order certificates cannot certify (n = 1000: d 1.8e-9 higher, every disk a rattler
// by the surround test). What this proves: nothing. It only moves the packing close to a local
// maximum; the caller identifies the bonds, polishes them and certifies the result
// (pipeline/analyze.cpp), and runs the LP relax when that certificate declines.
#pragma once

#include <functional>

#include "core/packing.hpp"

namespace tripack {

struct InteriorRelaxOptions {
  long double start_margin = 1e-6L;  // D starts this far (relative) below the minimum distance
  long double final_gap = 1e-13L;    // stop once m / t is below this (units of d)
  double t_factor = 8;               // t grows by this per stage
  int max_newton_steps = 400;        // over all stages
  int max_stage_steps = 80;          // a stage not centred by then ends the relax (declined)
  // The first stage's limit: from a start far from the maximum (a lattice with a long vacancy
  // segment, whose disks travel several spacings) it is the journey, not a stall.
  int max_first_stage_steps = 80;
  // CHOLMOD's supernodal Cholesky at any n (by default Eigen's simplicial one below 50,000
  // disks, 2x faster there). On a degenerate maximum the relax's end depends on the
  // factorization's rounding: the vacancy-segment enumeration keeps the supernodal one, with
  // which n = 188's end is certified (with the simplicial one its bonds are not identified).
  bool supernodal = false;
  // Called after every Newton step with its number and the current lower bound D on d.
  std::function<void(int step, long double D)> on_step;
};

struct InteriorRelaxReport {
  bool converged = false;  // reached final_gap with every stage centred
  int newton_steps = 0;
  int stages = 0;
  long double d_start = 0, d_end = 0;  // true minimum distances (unit triangle)
  int constraints = 0;                 // barrier terms in the last system
};

// Moves `packing` (unit-triangle coordinates) in place; its d becomes the true minimum distance,
// which never decreases. Throws std::invalid_argument for fewer than two disks.
InteriorRelaxReport interior_relax(Packing& packing, const InteriorRelaxOptions& options = {});

}  // namespace tripack
