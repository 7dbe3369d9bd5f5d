// The three size conventions users meet (docs/conventions.md) and Oler's bound.
#pragma once

#include <optional>
#include <string_view>

#include "core/geometry.hpp"

namespace tripack {

// How a number describing the packing size is meant:
//  * unit-triangle: d, the minimum distance of the centres in the side-1 triangle (the paper's);
//  * radius: r, the radius of n circles inside the side-1 triangle;
//  * unit-disk-side: S, the side of the smallest triangle holding n circles of radius 1.
enum class Convention { UnitTriangle, Radius, UnitDiskSide };

std::optional<Convention> parse_convention(std::string_view name);
// As given to an option: throws std::invalid_argument "unknown convention 'X' (unit-triangle,
// radius, unit-disk-side)" for any other name.
Convention convention_from_option(std::string_view name);
// The help of every --convention option.
inline constexpr const char* kConventionHelp =
    "unit-triangle (centres in the side-1 triangle), radius (circles of radius r in a side-1 "
    "triangle) or unit-disk-side (unit circles in a triangle of side S)";
std::string_view convention_name(Convention c);

// d <-> r: r = d / (2 (1 + sqrt3 d)),  d = 2r / (1 - 2 sqrt3 r).
long double radius_from_d(long double d);
long double d_from_radius(long double r);
// d <-> S: S = 2/d + 2 sqrt3.
long double side_from_d(long double d);
long double d_from_side(long double s);
// Convert a value given in convention c to d, and back.
long double to_d(long double value, Convention c);
long double from_d(long double d, Convention c);

// A disk centre p of a packing with minimum distance d, given in the unit-triangle convention,
// as the same disk's centre in convention c (docs/conventions.md). The centres' triangle is the
// container shrunk by the disks' radius about its incentre:
//  * unit-triangle: p itself;
//  * radius: circles of radius r = radius_from_d(d) in the triangle (0,0) (1,0) (1/2, sqrt3/2);
//    their centres' triangle has side 1 - 2 sqrt3 r = 1 / (1 + sqrt3 d);
//  * unit-disk-side: circles of radius 1 in the triangle (0,0) (S,0) (S/2, S sqrt3/2) with
//    S = side_from_d(d); their centres' triangle has side S - 2 sqrt3 = 2 / d.
Vec2L point_in_convention(const Vec2L& p, long double d, Convention c);
// The side of the container the points of convention c lie in: 1, or S for unit-disk-side.
long double container_side(long double d, Convention c);

// Oler's bound L(n) >= t(n) = (-3 + sqrt(8n + 1)) / 2, and delta(n) = L(n) - t(n).
long double oler_bound(long long n);
long double oler_delta(long long n, long double L);

}  // namespace tripack
