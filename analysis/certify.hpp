// Certificates for a packing with known bonds and rattlers (docs/certified.md step 4).
//
// Rigidity: the LP test of Donev, Torquato, Stillinger & Connelly for collective jamming with
// hard walls. With G the bond-opening map (pair: u_ij.(di - dj), wall: n.di), the packing is
// jammed when the only first-order motion of the non-rattlers with G d >= 0 is d = 0. Two LPs:
// max sum(G d) s.t. G d >= 0, |d| <= 1 (> 0: a motion opens bonds), then max c.d s.t. G d = 0,
// |d| <= 1 for a seeded random c (> 0: a floppy motion that keeps every bond).
//
// Stress (KKT): non-negative forces f on the bonds with pair forces summing to 1 that balance
// every non-rattler (neighbours push apart along u_ij, walls push along their inward normal):
// exactly the multipliers of "maximize d" at a first-order optimum. We maximize the smallest
// force; strictly positive stress + rigidity certify a strict local optimum of d.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/packing.hpp"

namespace tripack {

struct MultiprecisionPolish;  // polish/polish_mp.hpp

struct RigidityReport {
  bool rigid = false;
  double opening = 0;         // optimum of the first LP (0 when jammed)
  double floppy = 0;          // optimum of the second LP (0 when no bond-preserving motion)
  int moving_disks = 0;       // disks the found motion moves (by > 1e-6 of the largest move)
  int opening_bonds = 0;      // bonds the found motion opens
  std::vector<Vec2L> motion;  // per disk (zero for rattlers); empty when rigid
};
RigidityReport test_rigidity(const Packing& packing, const std::vector<Bond>& bonds,
                             const std::vector<int>& rattlers, std::uint64_t seed = 20261121);

struct StressReport {
  bool exists = false;             // some non-negative balancing stress exists
  bool strictly_positive = false;  // every bond force > 100 x the balance residual (resolved)
  long double min_force = 0;       // smallest force of the max-min stress (pairs and walls)
  long double min_pair_force = 0, min_wall_force = 0;
  long double residual = 0;         // largest force imbalance on a disk, recomputed in long double
  std::vector<long double> forces;  // per bond, in the order of `bonds`
};
StressReport stress_certificate(const Packing& packing, const std::vector<Bond>& bonds,
                                const std::vector<int>& rattlers);

// Fast path for both certificates, linear algebra instead of LPs. With G the
// bond-opening map over the non-rattlers and A = G^T G:
//  * a sparse LDL^T of A with positive pivots, and an inverse-iteration estimate of its smallest
//    eigenvalue above `min_eigenvalue`, say G has full column rank: no motion keeps every bond
//    at first order (what LP 2 of test_rigidity looks for);
//  * Newton steps towards the analytic centre of the self-stresses f > 0 (G^T f = 0) give a
//    balancing stress, scaled so the pair forces sum to 1; it is accepted when every force
//    exceeds `min_force` and passes stress_certificate's own test (> 1e-12 and > 100 x the long
//    double balance residual).
// Then no motion opens a bond either (LP 1): if G d >= 0 then f.(G d) = (G^T f).d = 0 with f > 0,
// so G d = 0 and d = 0. So an accepted fast certificate is the same verdict as rigid + strictly
// positive stress. It declines (and the LPs decide) otherwise; its forces are a strictly positive
// stress, not the max-min one the LP reports.
struct FastCertificate {
  bool accepted = false;
  std::string declined;       // why not, when !accepted
  double min_eigenvalue = 0;  // estimate of the smallest eigenvalue of G^T G
  int newton_steps = 0;       // of the stress search
  StressReport stress;        // filled when the stress step was reached
};
FastCertificate fast_certificate(const Packing& packing, const std::vector<Bond>& bonds,
                                 const std::vector<int>& rattlers, double min_eigenvalue = 1e-8,
                                 long double min_force = 1e-9L);

// The same two facts as fast_certificate, G injective and a strictly positive self-stress, at a
// configuration polished in MPFR, every error measured rather than assumed (docs/certified.md,
// "The multiprecision certificate"):
//  * G is built from the bond directions computed in MPFR and rounded to long double. A long
//    double sparse Cholesky factorization of A = G^T G and inverse iteration estimate its
//    smallest eigenvalue; a second factorization, of A - mu I with mu half the estimate, gives
//    the lower bound lambda_min(A) >= mu - ||L L^T - (A - mu I)||_F - (the rounding of A's
//    entries): `min_eigenvalue`. Rigid when the subtracted errors are at most mu / 2.
//  * A start stress (the analytic centre's Newton in double, else the max-min stress LP) is
//    balanced in MPFR by balance_multiprecision (plain projection, then the projection weighted
//    by the start forces if a force went negative). Its distance to an exact self-stress at the
//    polished coordinates is at most (|G^T f|_2 + ||dG||_F |f|_2) / sqrt(min_eigenvalue), dG the
//    directions' error (2 10^-digits / d per component): `force_error`. Strictly positive when
//    the smallest force exceeds 1e6 x force_error.
// Accepted (certified) = rigid and strictly positive, which is the verdict of the rigidity LPs
// and the stress LP together, as for fast_certificate; the caller checks the gaps.
struct MultiprecisionCertificate {
  bool rigid = false;
  bool strictly_positive = false;
  std::string declined;                 // why not, when not certified
  long double eigenvalue_estimate = 0;  // inverse iteration's Rayleigh quotient
  long double min_eigenvalue = 0;       // proven lower bound of lambda_min(G^T G)
  long double eigenvalue_error = 0;     // what the bound subtracted from mu (measured)
  StressReport stress;  // forces (pair forces sum to 1), smallest ones, residual |G^T f| (MPFR)
  long double force_error = 0;  // bound on the forces' distance to an exact self-stress
  std::string stress_start;     // "analytic centre" or "max-min LP"
  bool weighted = false;        // the weighted projection was needed
  int balance_sweeps = 0;
  bool certified() const { return rigid && strictly_positive; }
};
MultiprecisionCertificate multiprecision_certificate(const MultiprecisionPolish& polish,
                                                     const std::vector<Bond>& bonds,
                                                     const std::vector<int>& rattlers);

}  // namespace tripack
