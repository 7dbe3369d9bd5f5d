// Class 3: 2Delta(k+1) + 2Delta(k) - 1, L = 2k - 1 + sqrt3, k+1 packings with the same d
// (docs/classes.md §3): the rattler packing, k-1 cavity packings and the full packing. Every
// coordinate but the rattler's is exact in Q(sqrt3); the long double ones derive from them.
#include <cmath>
#include <stdexcept>

#include "constructors/blocks.hpp"
#include "constructors/builders.hpp"
#include "constructors/registry.hpp"

namespace tripack {

namespace {
using E = Sqrt3Directions;
}

Pattern build_twin(long k, long cavity) {
  if (k < 1) throw std::invalid_argument("2Delta(k+1)+2Delta(k)-1 needs k >= 1");
  if (cavity < 0 || cavity > k) throw std::invalid_argument("twin: cavity must be in 0..k");
  const HalfSurd3 zero{}, half{1, 0};
  const HalfSurd3 L0{4 * (k - 1), 2};  // the 4Delta(k) inside: 2k - 2 + sqrt3
  const HalfSurd3 L = L0 + HalfSurd3::integer(1);
  const Sqrt3Point shift{half, {0, 1}};                        // (1/2, sqrt3/2)
  const Sqrt3Point apex0{{2 * (k - 1), 1}, {3, 2 * (k - 1)}};  // (L0/2, L0 sqrt3/2)
  DiskUnitsPattern pat(L);
  pat.reserve(static_cast<std::size_t>(2 * k * (k + 1) + 2 * k + 1));
  // 4Delta(k) moved up one hexagonal row: apex and side walls stay, the floor moves down.
  pat.add_triangle(shift, E::e0, E::e60, k);
  const int right = pat.add_triangle(Sqrt3Point{L0, zero} + shift, E::e180, E::e120, k);
  pat.add_triangle(apex0 + shift, E::e240, E::e300, k);
  pat.add_triangle(Sqrt3Point{apex0.x, half} + shift, E::e60, E::e120, k);
  // The new floor row: k disks under each bottom corner triangle.
  for (long j = 0; j < k; ++j) pat.add_sqrt3(Sqrt3Point{HalfSurd3::integer(j), zero});
  for (long j = 0; j < k; ++j) pat.add_sqrt3(Sqrt3Point{L + HalfSurd3::integer(j - k + 1), zero});
  if (cavity == 0) {
    // The rattler in the floor cage under the central triangle's lower vertex; finish() centres
    // it numerically, so it has no exact coordinates.
    pat.mark_rattler(pat.add({pat.side() / 2, 0.25L}));
  } else {
    // The rattler completes the left large triangle; the first `cavity` disks of the right large
    // triangle's left edge rotate about their square-contact partners into the cavity.
    pat.add_sqrt3(Sqrt3Point{HalfSurd3::integer(k), zero});
    for (long j = 1; j <= cavity; ++j) {
      // P_j = (L-k, 0) + j e60 is (i, j') = (k-j, j-1) of the bottom-right Delta(k) (its far
      // edge); it goes to Q_j = (k + sqrt3/2, 1/2) + (j-1) e60.
      const int idx =
          right + static_cast<int>(DiskUnitsPattern::index_in_triangle(k, k - j, j - 1));
      const Sqrt3Point from = Sqrt3Point{L - HalfSurd3::integer(k), zero} + E::e60 * j;
      if (norm(pat.points()[static_cast<std::size_t>(idx)] - from.value()) > 1e-9L)
        throw std::logic_error("twin: edge disk not found");
      pat.move_sqrt3(idx, Sqrt3Point{{2 * k + j - 1, 1}, {1, j - 1}});
    }
  }
  return pat.finish({});
}

namespace {
// Variants: rattler (no disk in the cavity), cavity-m, full (= cavity-k).
const BuilderRegistration kTwin{"twin", [](const BuilderCall& c) {
                                  long cavity = 0;
                                  if (c.variant == "full")
                                    cavity = c.k;
                                  else if (c.variant.starts_with("cavity-"))
                                    cavity = std::stol(c.variant.substr(7));
                                  return build_twin(c.k, cavity);
                                }};
}  // namespace

}  // namespace tripack
