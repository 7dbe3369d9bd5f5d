// The "ripple chain": the one-unknown problem behind the matrix class (anchor step 2) and the
// sparse-rows / pairs classes (anchor step 1), docs/classes.md §4a and §5-6.
//
// Disk units. A top hexagonal triangle hangs from the apex; its anchors are
// A_i = (X + step*i, sqrt3*X), i = 0..q-1, and the side is L = (q-1)*step + 2X. Below, raised
// disks R_0..R_{q-1} and floor disks F_0..F_q (corners F_0, F_q) with R_i touching F_i, F_{i+1}
// and A_i. The pattern is mirror-symmetric, and we march from the axis outwards: that direction
// is contracting, so it stays accurate even for step 1 at large q, where the root X approaches 1
// super-exponentially (1 - Y_12 ~ 1e-31) and a march from the corner loses every digit.
#pragma once

#include <optional>
#include <vector>

#include "core/geometry.hpp"

namespace tripack {

struct RippleChain {
  int q = 0;
  int step = 0;
  long double X = 0;          // anchor offset: A_0 = (X, sqrt3 X)
  long double L = 0;          // side in disk units
  std::vector<Vec2L> floor;   // F_0..F_q
  std::vector<Vec2L> raised;  // R_0..R_{q-1}
  Vec2L anchor(int i) const { return {X + static_cast<long double>(step * i), kSqrt3 * X}; }
};

// The intersection of the unit circles about c1 and c2 on the left of the direction c1 -> c2 (the
// right one is unit_circles_left(c2, c1)), or nullopt if they do not meet. The builders' marches
// place each disk this way.
std::optional<Vec2L> unit_circles_left(const Vec2L& c1, const Vec2L& c2);

// Solves the chain for q >= 1 and step 1 or 2. Throws std::runtime_error if no root is found.
RippleChain solve_ripple_chain(int q, int step);

}  // namespace tripack
