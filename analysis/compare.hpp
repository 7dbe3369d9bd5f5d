// Contact-graph comparison (SPEC §2.6): are two packings of n disks "the same packing"?
//
// Two packings are the same when their d agree to a relative tolerance and, after removing the
// rattlers, one symmetry g of the triangle maps the first onto the second both geometrically
// (every non-rattler of g(a) lies within a tolerance of a distinct non-rattler of b) and
// combinatorially (that point matching maps the bonds of a, walls included with their sides
// permuted by g, onto the bonds of b). Disk indices are irrelevant; rattler positions too.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/packing.hpp"

namespace tripack {

// The 6 symmetries of the unit triangle (0,0), (1,0), (1/2, sqrt3/2) with centroid G.
//  Identity;
//  Rotate120, Rotate240: counter-clockwise rotations about G; Rotate120 sends (0,0) -> (1,0) ->
//    apex -> (0,0), so Bottom -> Right -> Left -> Bottom;
//  MirrorVertical: reflection in the vertical median x = 1/2 (Left <-> Right);
//  MirrorLeft: reflection in the median through the corner (0,0) (Bottom <-> Left);
//  MirrorRight: reflection in the median through the corner (1,0) (Bottom <-> Right).
// Every permutation of the three sides comes from exactly one of them.
enum class Symmetry { Identity, Rotate120, Rotate240, MirrorVertical, MirrorLeft, MirrorRight };
inline constexpr std::array<Symmetry, 6> kSymmetries{Symmetry::Identity,   Symmetry::Rotate120,
                                                     Symmetry::Rotate240,  Symmetry::MirrorVertical,
                                                     Symmetry::MirrorLeft, Symmetry::MirrorRight};

std::string_view symmetry_name(Symmetry g);  // "identity", "rotate-120", "mirror-vertical", ...
Symmetry inverse(Symmetry g);
Symmetry compose(Symmetry outer, Symmetry inner);  // p -> outer(inner(p))

Vec2L apply(Symmetry g, const Vec2L& p);
Side apply(Symmetry g, Side s);

// The pattern with its points moved by g and its wall bonds' sides permuted accordingly (bonds
// re-sorted). Exact coordinates are dropped: a rotation leaves their Q(sqrt3)/2 form.
Pattern transformed(const Pattern& p, Symmetry g);

// The pattern with disk i renamed permutation[i] (points, bonds, rattlers and exact coordinates
// moved along). Throws std::invalid_argument unless `permutation` is a permutation of 0..n-1.
Pattern relabelled(const Pattern& p, const std::vector<int>& permutation);

struct Comparison {
  bool same = false;        // same_d, and one symmetry makes the graphs and the points match
  bool same_n = false;      // same number of disks
  bool same_d = false;      // |d_a - d_b| <= d_relative_tolerance * max(d_a, d_b)
  bool isomorphic = false;  // contact graphs (rattlers removed) isomorphic, walls onto walls
  bool geometric = false;   // some symmetry matches the non-rattler points within tolerance
  std::optional<Symmetry> symmetry;  // g with transformed(a, g) ~ b, when same
  std::string reason;                // one line: why they differ, or which symmetry matches
};

// Rattlers are the listed ones plus any disk without bonds. Bonds are taken from the patterns
// (they are not recomputed from the points). position_tolerance is in units of the mean d.
// Cost: O(n) per symmetry when the points propose the vertex matching; Boost's VF2 (with
// colour-refinement invariants) decides isomorphism only when no symmetry proposes one.
Comparison compare_packings(const Pattern& a, const Pattern& b,
                            long double d_relative_tolerance = 1e-12L,
                            long double position_tolerance = 1e-9L);

// Groups patterns into classes of "the same packing" (compare_packings(...).same, default
// position tolerance); returns a class id per input, ids 0, 1, ... in first-seen order.
std::vector<int> distinct_packings(const std::vector<Pattern>& patterns,
                                   long double d_relative_tolerance = 1e-12L);

}  // namespace tripack
