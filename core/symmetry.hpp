// The triangle's 6 symmetries, acting on points, sides and whole patterns. Comparison, the
// explorer and the drawings all use them; they are geometry, so they live in core.
#pragma once

#include <array>
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

}  // namespace tripack
