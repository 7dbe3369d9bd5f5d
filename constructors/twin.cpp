// Class 3: 2Delta(k+1) + 2Delta(k) - 1, L = 2k - 1 + sqrt3, k+1 packings with the same d
// (CONSTRUCTIONS.md §3): the rattler packing, k-1 cavity packings and the full packing.
#include <cmath>
#include <stdexcept>

#include "constructors/blocks.hpp"
#include "constructors/builders.hpp"

namespace tripack {

namespace {
using D = Directions<long double>;
}

Pattern build_twin(long k, long cavity) {
  if (k < 1) throw std::invalid_argument("2Delta(k+1)+2Delta(k)-1 needs k >= 1");
  if (cavity < 0 || cavity > k) throw std::invalid_argument("twin: cavity must be in 0..k");
  const long double kk = static_cast<long double>(k);
  const long double L0 = 2 * (kk - 1) + kSqrt3;  // the 4Delta(k) inside
  const long double L = L0 + 1;
  const Vec2L shift{0.5L, kSqrt3 / 2};
  DiskUnitsPattern pat(L);
  // 4Delta(k) moved up one hexagonal row: apex and side walls stay, the floor moves down.
  pat.add_triangle(Vec2L{0, 0} + shift, D::e0, D::e60, k);
  pat.add_triangle(Vec2L{L0, 0} + shift, D::e180, D::e120, k);
  pat.add_triangle(Vec2L{L0 / 2, L0 * kSqrt3 / 2} + shift, D::e240, D::e300, k);
  pat.add_triangle(Vec2L{L0 / 2, 0.5L} + shift, D::e60, D::e120, k);
  // The new floor row: k disks under each bottom corner triangle.
  for (long j = 0; j < k; ++j) pat.add({static_cast<long double>(j), 0});
  for (long j = 0; j < k; ++j) pat.add({L - kk + 1 + static_cast<long double>(j), 0});
  if (cavity == 0) {
    // The rattler in the floor cage under the central triangle's lower vertex.
    pat.mark_rattler(pat.add({L / 2, 0.25L}));
  } else {
    // The rattler completes the left large triangle; the first `cavity` disks of the right large
    // triangle's left edge rotate about their square-contact partners into the cavity.
    pat.add({kk, 0});
    for (long j = 1; j <= cavity; ++j) {
      const Vec2L from = Vec2L{L - kk, 0} + D::e60 * static_cast<long double>(j);
      const Vec2L to = Vec2L{kk + kSqrt3 / 2, 0.5L} + D::e60 * static_cast<long double>(j - 1);
      bool moved = false;
      for (auto& p : pat.points()) {
        if (norm(p - from) < 1e-9L) {
          p = to;
          moved = true;
          break;
        }
      }
      if (!moved) throw std::logic_error("twin: edge disk not found");
    }
  }
  return pat.finish({});
}

}  // namespace tripack
