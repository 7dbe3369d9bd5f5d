// Statement (II) of docs/exact.md at the exact configuration of statement (I): the bond-opening
// map G of the held disks (rows: (x_i - x_j, y_i - y_j) for a pair bond, the inward normals
// (0, 1), (sqrt3, -1), (-sqrt3, -1) for the walls) has full column rank over K, proven by a minor
// that is a unit modulo a prime (exact/field_kernel.hpp); and a stress s over K with G^T s = 0
// exactly (from the self-stresses found modulo primes and verified over K) is strictly positive
// at the embedding (Arb). By docs/certified.md "Why this proves local optimality", the held disks
// are then a strict local maximum of d.
#pragma once

#include <string>
#include <vector>

#include "exact/configuration.hpp"

namespace tripack::exact {

struct StrictOptimality {
  bool proven = false;
  std::string reason;
  std::vector<RationalPolynomial> stress;  // per bond, in the order of the input's bonds
  int rank = 0, columns = 0;               // of G over K; rigid when equal
  int stresses = 0;                        // dimension of the self-stresses {s : G^T s = 0}
  double smallest_stress_ratio = 0;        // min s / max s at t0 (a lower bound)
};

// `forces`: a numerical strictly positive stress of the same bonds (the analysis's), used to
// pick a positive combination when the self-stresses have dimension > 1 (empty: dimension 1 only).
StrictOptimality prove_strict_optimality(const ConfigurationInput& input,
                                         const ExactConfiguration& configuration,
                                         const std::vector<long double>& forces);

}  // namespace tripack::exact
