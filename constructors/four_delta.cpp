// Class 2: 4 Delta(k), L = 2k - 2 + sqrt3 (CONSTRUCTIONS.md §2).
#include <stdexcept>

#include "constructors/blocks.hpp"
#include "constructors/builders.hpp"

namespace tripack {

namespace {
using D = Directions<long double>;
}

Pattern build_four_delta(long k) {
  if (k < 1) throw std::invalid_argument("4Delta(k) needs k >= 1");
  const long double L = 2.0L * static_cast<long double>(k - 1) + kSqrt3;
  DiskUnitsPattern pat(L);
  pat.points().reserve(static_cast<std::size_t>(2 * k * (k + 1)));
  pat.add_triangle({0, 0}, D::e0, D::e60, k);                      // bottom-left corner
  pat.add_triangle({L, 0}, D::e180, D::e120, k);                   // bottom-right corner
  pat.add_triangle({L / 2, L * kSqrt3 / 2}, D::e240, D::e300, k);  // top corner
  pat.add_triangle({L / 2, 0.5L}, D::e60, D::e120, k);             // inverted, concentric
  return pat.finish({});
}

}  // namespace tripack
