#include "core/symmetry.hpp"

#include <algorithm>
#include <stdexcept>

namespace tripack {

namespace {

constexpr long double kCentroidY = kSqrt3 / 6;

// Reflection of p in the line through `base` with unit direction u.
Vec2L reflect(const Vec2L& p, const Vec2L& base, const Vec2L& u) {
  const Vec2L v = p - base;
  return base + u * (2 * dot(u, v)) - v;
}

// Rotation of p about the centroid by an angle with cosine -1/2 and sine s.
Vec2L rotate(const Vec2L& p, long double s) {
  const Vec2L v{p.x - 0.5L, p.y - kCentroidY};
  return {0.5L - v.x / 2 - s * v.y, kCentroidY + s * v.x - v.y / 2};
}

}  // namespace

std::string_view symmetry_name(Symmetry g) {
  static constexpr std::string_view kNames[] = {"identity",        "rotate-120",  "rotate-240",
                                                "mirror-vertical", "mirror-left", "mirror-right"};
  return kNames[static_cast<int>(g)];
}

Symmetry inverse(Symmetry g) {
  if (g == Symmetry::Rotate120) return Symmetry::Rotate240;
  if (g == Symmetry::Rotate240) return Symmetry::Rotate120;
  return g;  // the identity and the reflections are involutions
}

Symmetry compose(Symmetry outer, Symmetry inner) {
  // A symmetry is determined by its permutation of the sides.
  for (Symmetry g : kSymmetries) {
    bool ok = true;
    for (Side s : kSides) ok = ok && apply(g, s) == apply(outer, apply(inner, s));
    if (ok) return g;
  }
  return Symmetry::Identity;  // unreachable
}

Vec2L apply(Symmetry g, const Vec2L& p) {
  switch (g) {
    case Symmetry::Identity:
      return p;
    case Symmetry::Rotate120:
      return rotate(p, kSqrt3 / 2);
    case Symmetry::Rotate240:
      return rotate(p, -kSqrt3 / 2);
    case Symmetry::MirrorVertical:
      return {1 - p.x, p.y};
    case Symmetry::MirrorLeft:
      return reflect(p, {0, 0}, {kSqrt3 / 2, 0.5L});
    case Symmetry::MirrorRight:
      return reflect(p, {1, 0}, {-kSqrt3 / 2, 0.5L});
  }
  return p;
}

Side apply(Symmetry g, Side s) {
  // Rows: the images of Bottom, Left, Right (docs/classes.md vertex order (0,0), (1,0), apex).
  static constexpr Side kImage[6][3] = {
      {Side::Bottom, Side::Left, Side::Right},  // identity
      {Side::Right, Side::Bottom, Side::Left},  // rotate-120: (0,0) -> (1,0) -> apex
      {Side::Left, Side::Right, Side::Bottom},  // rotate-240
      {Side::Bottom, Side::Right, Side::Left},  // mirror in x = 1/2
      {Side::Left, Side::Bottom, Side::Right},  // mirror through (0,0)
      {Side::Right, Side::Left, Side::Bottom},  // mirror through (1,0)
  };
  return kImage[static_cast<int>(g)][static_cast<int>(s)];
}

Pattern transformed(const Pattern& p, Symmetry g) {
  Pattern out = p;
  for (auto& q : out.packing.points) q = apply(g, q);
  for (auto& bond : out.bonds) {
    if (bond.is_wall()) bond = Bond::wall(bond.a, apply(g, bond.side()));
  }
  std::sort(out.bonds.begin(), out.bonds.end());
  if (g != Symmetry::Identity) out.sqrt3.reset();
  return out;
}

Pattern relabelled(const Pattern& p, const std::vector<int>& permutation) {
  const std::size_t n = p.packing.size();
  if (permutation.size() != n) throw std::invalid_argument("relabelled: permutation size != n");
  std::vector<char> hit(n, 0);
  for (int target : permutation) {
    if (target < 0 || static_cast<std::size_t>(target) >= n || hit[target]) {
      throw std::invalid_argument("relabelled: not a permutation of 0..n-1");
    }
    hit[target] = 1;
  }
  Pattern out = p;
  for (std::size_t i = 0; i < n; ++i) out.packing.points[permutation[i]] = p.packing.points[i];
  for (auto& bond : out.bonds) {
    bond = bond.is_wall() ? Bond::wall(permutation[bond.a], bond.side())
                          : Bond::pair(permutation[bond.a], permutation[bond.b]);
  }
  std::sort(out.bonds.begin(), out.bonds.end());
  for (auto& r : out.rattlers) r = permutation[r];
  std::sort(out.rattlers.begin(), out.rattlers.end());
  if (out.sqrt3 && out.sqrt3->points.size() == n) {
    for (std::size_t i = 0; i < n; ++i) out.sqrt3->points[permutation[i]] = p.sqrt3->points[i];
    if (out.sqrt3->known.size() == n) {
      for (std::size_t i = 0; i < n; ++i) out.sqrt3->known[permutation[i]] = p.sqrt3->known[i];
    }
  }
  return out;
}

}  // namespace tripack
