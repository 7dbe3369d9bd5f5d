// Newton / Gauss-Newton on the bond system: every pair bond at distance d, every wall bond on its
// side. Unknowns are the non-rattler centres and L = 1/d, in disk units, where a pair equation is
// |xi - xj| = 1 and only right-wall equations involve L (so the Jacobian stays sparse).
//
// The system is usually over-determined (t22a: 41 unknowns, 47 bonds) and consistent; some are
// rank-deficient (Delta(k)-1 is floppy). Steps are rank-revealing sparse least-squares solves
// (SuiteSparseQR, multifrontal and rank-revealing, through Eigen), residuals are evaluated in long
// double so the result is accurate to double rounding regardless of the Jacobian's conditioning
// (mixed-precision refinement). polish/polish_mp.hpp takes the result on to 30-100,000 digits in
// MPFR; both share the equations and the Jacobian through polish/bond_system.hpp.
#pragma once

#include <vector>

#include "core/packing.hpp"

namespace tripack {

struct PolishOptions {
  int max_iterations = 60;
  // Stop once the largest residual (disk units) is below tolerance * max(1, L): a few units of
  // long double rounding for coordinates of size L. Iteration also stops when the residual no
  // longer decreases (the rounding floor).
  long double tolerance = 1e-18L;
};

struct PolishReport {
  bool converged = false;
  int iterations = 0;
  int factorizations = 0;
  long double max_residual = 0;  // largest |equation| at the end, disk units
  int rank = -1;                 // numerical rank of the last factorized Jacobian (-1: none was
                                 // needed, the start already met the tolerance)
  int unknowns = 0;
  int equations = 0;
};

// Polishes `packing` (unit-triangle coordinates and d) in place. Rattlers are not unknowns and
// are moved only by the rescaling of the triangle. The start may be rough: steps are damped by
// a backtracking line search on the residual norm.
PolishReport polish_bond_system(Packing& packing, const std::vector<Bond>& bonds,
                                const std::vector<int>& rattlers,
                                const PolishOptions& options = {});

// The same on disk-unit coordinates (side L), for builders that set up contact systems there.
PolishReport polish_bond_system_disk_units(std::vector<Vec2L>& points, long double& L,
                                           const std::vector<Bond>& bonds,
                                           const std::vector<int>& rattlers,
                                           const PolishOptions& options = {});

}  // namespace tripack
