// Class 2: 4 Delta(k), L = 2k - 2 + sqrt3 (docs/classes.md §2). Every coordinate is exact in
// Q(sqrt3); the long double ones are derived from the exact ones.
#include <stdexcept>

#include "constructors/blocks.hpp"
#include "constructors/builders.hpp"
#include "constructors/registry.hpp"

namespace tripack {

namespace {
using E = Sqrt3Directions;
}

Pattern build_four_delta(long k) {
  if (k < 1) throw std::invalid_argument("4Delta(k) needs k >= 1");
  const HalfSurd3 L{4 * (k - 1), 2};  // 2k - 2 + sqrt3
  DiskUnitsPattern pat(L);
  pat.reserve(static_cast<std::size_t>(2 * k * (k + 1)));
  const HalfSurd3 zero{}, half = {1, 0};
  // The apex (L/2, L sqrt3/2): L/2 = (2k-2 + sqrt3)/2, L sqrt3/2 = (3 + (2k-2) sqrt3)/2.
  const Sqrt3Point apex{{2 * (k - 1), 1}, {3, 2 * (k - 1)}};
  pat.add_triangle({zero, zero}, E::e0, E::e60, k);      // bottom-left corner
  pat.add_triangle({L, zero}, E::e180, E::e120, k);      // bottom-right corner
  pat.add_triangle(apex, E::e240, E::e300, k);           // top corner
  pat.add_triangle({apex.x, half}, E::e60, E::e120, k);  // inverted, concentric, vertex (L/2, 1/2)
  return pat.finish({});
}

namespace {
const BuilderRegistration kFourDelta{"four-delta",
                                     [](const BuilderCall& c) { return build_four_delta(c.k); }};
}  // namespace

}  // namespace tripack
