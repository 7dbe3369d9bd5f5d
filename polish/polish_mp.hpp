// Multiprecision polish of the bond system (MPFR), to 1..kMaxMultiprecisionDigits significant
// digits (docs/precision.md).
//
// Newton with precision on demand: the state is kept in MPFR at digits + 10 decimal digits; each
// Newton step (quadratic convergence: the digits double) evaluates the residuals only to the
// precision the next step needs, without square roots, and solves for its correction by
// iterative refinement with one double factorization of the Jacobian (SuiteSparseQR): a sweep
// gains ~14 digits and costs one multiply-add of a 64-bit word per nonzero of the Jacobian on
// fixed-point integers, linear in the precision. So the total is a few residual evaluations at
// full precision plus digits / 14 cheap sweeps, where the linear scheme before paid digits / 14
// full evaluations. From the long double start 100 digits take 3 Newton steps, 20,000 digits 11.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "core/packing.hpp"

namespace tripack {

// The most digits polish_multiprecision accepts. The time grows as digits^1.5 .. digits^2 and the
// memory as n * digits (~7 bytes per disk per digit): at 100,000 digits n = 200 takes ~11 s and
// 150 MB (docs/precision.md).
inline constexpr int kMaxMultiprecisionDigits = 100000;

struct MultiprecisionPolish {
  int digits = 0;    // requested significant digits
  std::string d, L;  // decimal strings (fixed notation) with `digits` significant digits
  // Unit-triangle coordinates in fixed notation with `digits` decimals (they lie in [0, 1]).
  // Rattlers are not unknowns: they keep their start coordinates (rattlers only rescale).
  std::vector<std::array<std::string, 2>> points;
  double log10_max_residual = 0;  // log10 of the largest |equation| at the end (disk units),
                                  // floored at the working precision's resolution
  int iterations = 0;             // Newton steps in MPFR (after the long double polish)
  int sweeps = 0;                 // refinement sweeps of their linear solves, all together
  int factorizations = 0;         // double QR factorizations used by those steps (one)
  bool converged = false;         // residual below 10^-(digits+3) relative to L
};

// Polishes the bond system of `start` (unit-triangle coordinates and d) to `digits` significant
// digits: first the long double polish, then Newton in MPFR. digits must lie in
// 1..kMaxMultiprecisionDigits (std::invalid_argument otherwise). When the system has no solution
// near the start (inconsistent bonds), converged is false and d, L and points are left empty rather
// than filled with digits that mean nothing. No global state: every MPFR number carries its own
// precision and MPFR's default precision is neither read nor changed, so concurrent calls are safe
// with a thread-safe MPFR build (Debian's).
MultiprecisionPolish polish_multiprecision(const Packing& start, const std::vector<Bond>& bonds,
                                           const std::vector<int>& rattlers, int digits);

// Moves every rattler of a converged polish to the centre of its cage, the point of largest
// clearance (its distance to the nearest other centre minus d, or to the nearest side), found by
// a compass search in MPFR whose steps shrink to 10^-(digits+4) of the side; besides 8 fixed
// directions it tries the gradients of the constraints that are nearly active and their
// bisectors, so it follows the ridges of the max-min. Needed because polish_multiprecision keeps
// the rattlers' long double places, and a cage narrower than long double's resolution (the
// rattler of t160a: room below 1e-15 d) leaves the rattler overlapping its neighbours at 30
// digits. Returns the smallest clearance reached, in units of d (>= 0 up to 10^-digits when the
// cages have room; +inf without rattlers). polish.points change; d and the rest do not.
double centre_rattlers_multiprecision(MultiprecisionPolish& polish,
                                      const std::vector<int>& rattlers);

// The radius r = d / (2 (1 + sqrt3 d)) (radius = true) or the side S = 2/d + 2 sqrt3 (false) of
// docs/conventions.md from a decimal d, to `digits` significant digits in MPFR: a d polished to 50
// digits keeps its 50 digits in the user's convention.
std::string radius_or_side_from_d(const std::string& d, bool radius, int digits);

// delta(n) = L - t(n), Oler's bound t(n) = (-3 + sqrt(8n + 1)) / 2 (docs/conventions.md), from a
// decimal L (a multiprecision polish's), in MPFR, with as many decimals as L has: delta is known to
// L's absolute accuracy, not to L's number of significant digits.
std::string oler_delta_from_L(const std::string& L, long long n);

}  // namespace tripack

// Evaluations at a converged polish in MPFR, for the multiprecision certificate
// (docs/certified.md, "The multiprecision certificate"). Each reads the polish's decimal
// coordinates and d back at its working precision (digits + 10), so a gap of 1e-11 d is known to
// ~digits - 11 significant digits where long double coordinates (the long double polish's, off
// by its residual over the smallest singular value of the bond system) may not even get its
// sign. Values come back as long double, whose exponent reaches 1e-4931: a gap at 10^-digits is
// still a number, not 0.
namespace tripack {

// A non-bond contact and its gap in units of d (pair: |xi - xj|/d - 1; wall: distance / d).
struct PreciseGap {
  Bond contact;
  long double gap = 0;
  bool rattler = false;  // involves a rattler or a disk without bonds (a cage's play)
};
struct PreciseGaps {
  std::vector<PreciseGap> gaps;  // every non-bond pair closer than 1.25 d and wall closer than
                                 // 0.25 d, smallest first
  // The largest |gap| of a bond: what the polish and the decimal coordinates leave of the
  // equations, measured (~10^-digits). A non-bond gap is resolved only far above it.
  long double bond_floor = 0;
};
// `bonds` need not be sorted. Rattlers (given, or without bonds) are flagged.
PreciseGaps precise_gaps(const MultiprecisionPolish& polish, const std::vector<Bond>& bonds,
                         const std::vector<int>& rattlers);

// The polish's coordinates and d rounded to long double (the nearest long double to each).
Packing rounded_packing(const MultiprecisionPolish& polish);

// The unit contact directions of the bonds computed in MPFR and rounded to long double: a pair
// bond a-b gives (x_a - x_b)/|x_a - x_b|, a wall bond its inward normal. Each component is within
// one long double rounding of the exact direction at the polished coordinates, where directions
// from long double coordinates carry their error divided by d.
std::vector<Vec2L> precise_directions(const MultiprecisionPolish& polish,
                                      const std::vector<Bond>& bonds);

// A balancing stress to the working precision: `forces` (one per bond, any balance) are
// projected onto the self-stresses {f : G^T f = 0} of the polished coordinates (G the
// bond-opening map over the non-rattlers, its rows the directions above, evaluated in MPFR) by
// iterative refinement: each sweep evaluates r = G^T f in MPFR, asks `solve` for y with
// (G^T W G) y = r (in double or long double; W = diag(weights), all ones when empty), and
// subtracts W G y in MPFR. The columns of r and y are the non-rattlers' x and y in disk order
// (rattlers have none). The weighted projection changes each force relative to its weight, so
// weights equal to the forces keep small forces small. Then the forces are scaled so the pair
// forces sum to 1.
struct PreciseBalance {
  std::vector<long double> forces;  // per bond, pair forces summing to 1
  long double residual = 0;         // largest |G^T f| component at the end, in MPFR
  long double start_residual = 0;   // the same for the forces given (scaled alike)
  int sweeps = 0;
  bool converged = false;  // the residual reached the working precision's floor
};
PreciseBalance balance_multiprecision(
    const MultiprecisionPolish& polish, const std::vector<Bond>& bonds,
    const std::vector<int>& rattlers, const std::vector<long double>& forces,
    const std::vector<long double>& weights,
    const std::function<std::vector<long double>(const std::vector<long double>&)>& solve);

}  // namespace tripack
