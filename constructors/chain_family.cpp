// Classes 4-6 in one construction (CONSTRUCTIONS.md §4b, §5-6): a top hexagonal triangle over a
// row of q inverted and q+1 upright small triangles, positioned by the compressed ripple chain.
#include <stdexcept>

#include "constructors/blocks.hpp"
#include "constructors/builders.hpp"
#include "constructors/chain.hpp"

namespace tripack {

namespace {
using D = Directions<long double>;
}

Pattern build_chain_family(const ChainFamilyShape& s) {
  if (s.q < 1 || s.block < 1 || (s.separator != 0 && s.separator != 1))
    throw std::invalid_argument("chain family needs q >= 1, block >= 1, separator 0 or 1");
  const RippleChain chain = solve_ripple_chain(static_cast<int>(s.q), 1 + s.separator);
  const long double w = static_cast<long double>(s.block - 1);  // width of a small triangle
  const long double L = chain.L + static_cast<long double>(s.q + 1) * w;
  const long M = s.q * s.block + (s.q - 1) * s.separator;
  DiskUnitsPattern pat(L);

  // Top Delta(M) from the apex, touching both side walls; its bottom row is index j = 0..M-1.
  const int top = pat.add_triangle({L / 2, L * kSqrt3 / 2}, D::e240, D::e300, M);
  if (s.separator) {
    for (long b = 0; b + 1 < s.q; ++b) {
      const long j = b * (s.block + 1) + s.block;  // the disk between blocks b and b+1
      // Bottom row of the top triangle: i + j = M - 1 with i along e240.
      pat.mark_rattler(top + static_cast<int>(DiskUnitsPattern::index_in_triangle(M, M - 1 - j, j)));
    }
  }
  // Upright triangles on the floor and inverted triangles between them, uncompressed.
  for (long i = 0; i <= s.q; ++i) {
    const long double x = chain.floor[static_cast<std::size_t>(i)].x + static_cast<long double>(i) * w;
    pat.add_triangle({x, 0}, D::e0, D::e60, s.block);
  }
  for (long i = 0; i < s.q; ++i) {
    const Vec2L& r = chain.raised[static_cast<std::size_t>(i)];
    pat.add_triangle({r.x + static_cast<long double>(i + 1) * w, r.y}, D::e60, D::e120, s.block);
  }
  return pat.finish({});
}

}  // namespace tripack
