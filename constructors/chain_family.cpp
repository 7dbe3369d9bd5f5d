// Classes 4-6 in one construction (docs/classes.md §4b, §5-6): a top hexagonal triangle over a
// row of q inverted and q+1 upright small triangles, positioned by the compressed ripple chain.
#include <stdexcept>

#include "constructors/blocks.hpp"
#include "constructors/builders.hpp"
#include "constructors/chain.hpp"
#include "constructors/registry.hpp"

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

  using Edge = DiskUnitsPattern::Edge;
  const auto edge = [](int first, long k, Edge e) {
    return DiskUnitsPattern::triangle_edge(first, k, e);
  };
  // Bonds come from the construction, not from distances: for anchor step 1 the corner raised
  // disk comes within 1.5e-11 (k = 11) or 5e-16 (k = 12) of a wall without touching it.
  pat.use_recorded_bonds();

  // Top Delta(M) from the apex, touching both side walls; its bottom row (far edge) is
  // j = 0..M-1 from the left.
  const int top = pat.add_triangle({L / 2, L * kSqrt3 / 2}, D::e240, D::e300, M);
  for (int i : edge(top, M, Edge::A)) pat.add_wall_bond(i, Side::Left);
  for (int i : edge(top, M, Edge::B)) pat.add_wall_bond(i, Side::Right);
  const std::vector<int> anchor_row = edge(top, M, Edge::Far);
  for (long b = 0; s.separator && b + 1 < s.q; ++b)
    pat.mark_rattler(anchor_row[static_cast<std::size_t>(b * (s.block + 1) + s.block)]);

  // Upright triangles on the floor and inverted triangles between them, uncompressed.
  std::vector<int> up, down;
  for (long i = 0; i <= s.q; ++i) {
    const long double x =
        chain.floor[static_cast<std::size_t>(i)].x + static_cast<long double>(i) * w;
    up.push_back(pat.add_triangle({x, 0}, D::e0, D::e60, s.block));
    for (int d : edge(up.back(), s.block, Edge::A)) pat.add_wall_bond(d, Side::Bottom);
  }
  for (int d : edge(up.front(), s.block, Edge::B)) pat.add_wall_bond(d, Side::Left);
  for (int d : edge(up.back(), s.block, Edge::Far)) pat.add_wall_bond(d, Side::Right);
  for (long i = 0; i < s.q; ++i) {
    const Vec2L& r = chain.raised[static_cast<std::size_t>(i)];
    down.push_back(pat.add_triangle({r.x + static_cast<long double>(i + 1) * w, r.y}, D::e60,
                                    D::e120, s.block));
  }
  // Interfaces, each k parallel unit bars: block i over V_i's top row (the far edge runs right
  // to left), V_i's lower-left edge against U_i's upper-right edge, V_i's lower-right edge
  // against U_{i+1}'s upper-left edge.
  for (long i = 0; i < s.q; ++i) {
    const auto v_top = edge(down[static_cast<std::size_t>(i)], s.block, Edge::Far);
    const auto v_left = edge(down[static_cast<std::size_t>(i)], s.block, Edge::B);
    const auto v_right = edge(down[static_cast<std::size_t>(i)], s.block, Edge::A);
    const auto u_right = edge(up[static_cast<std::size_t>(i)], s.block, Edge::Far);
    const auto u_left = edge(up[static_cast<std::size_t>(i + 1)], s.block, Edge::B);
    for (long t = 0; t < s.block; ++t) {
      const auto ut = static_cast<std::size_t>(t);
      pat.add_bond(anchor_row[static_cast<std::size_t>(i * (s.block + s.separator) + t)],
                   v_top[static_cast<std::size_t>(s.block - 1 - t)]);
      pat.add_bond(v_left[ut], u_right[ut]);
      pat.add_bond(v_right[ut], u_left[ut]);
    }
  }
  return pat.finish({});
}

namespace {
const BuilderRegistration kChainFamily{
    "chain-family", [](const BuilderCall& c) {
      return build_chain_family({c.arg("q"), c.arg("block"), static_cast<int>(c.arg("separator"))});
    }};
}  // namespace

}  // namespace tripack
