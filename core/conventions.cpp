#include "core/conventions.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/geometry.hpp"

namespace tripack {

std::optional<Convention> parse_convention(std::string_view name) {
  if (name == "unit-triangle") return Convention::UnitTriangle;
  if (name == "radius") return Convention::Radius;
  if (name == "unit-disk-side") return Convention::UnitDiskSide;
  return std::nullopt;
}

Convention convention_from_option(std::string_view name) {
  if (const auto c = parse_convention(name)) return *c;
  throw std::invalid_argument("unknown convention '" + std::string(name) +
                              "' (unit-triangle, radius, unit-disk-side)");
}

std::string_view convention_name(Convention c) {
  static constexpr std::string_view kNames[] = {"unit-triangle", "radius", "unit-disk-side"};
  return kNames[static_cast<int>(c)];
}

long double radius_from_d(long double d) {
  return d / (2 * (1 + kSqrt3 * d));
}
long double d_from_radius(long double r) {
  return 2 * r / (1 - 2 * kSqrt3 * r);
}
long double side_from_d(long double d) {
  return 2 / d + 2 * kSqrt3;
}
long double d_from_side(long double s) {
  return 2 / (s - 2 * kSqrt3);
}

long double to_d(long double value, Convention c) {
  if (c == Convention::Radius) return d_from_radius(value);
  return c == Convention::UnitDiskSide ? d_from_side(value) : value;
}

long double from_d(long double d, Convention c) {
  if (c == Convention::Radius) return radius_from_d(d);
  return c == Convention::UnitDiskSide ? side_from_d(d) : d;
}

Vec2L point_in_convention(const Vec2L& p, long double d, Convention c) {
  const long double side = container_side(d, c);
  const Vec2L incentre = Vec2L{0.5L, kSqrt3 / 6} * side;
  switch (c) {
    case Convention::UnitTriangle:
      return p;
    case Convention::Radius:
      return incentre + (p - Vec2L{0.5L, kSqrt3 / 6}) / (1 + kSqrt3 * d);
    case Convention::UnitDiskSide:
      return incentre + (p - Vec2L{0.5L, kSqrt3 / 6}) * (2 / d);
  }
  return p;
}

long double container_side(long double d, Convention c) {
  return c == Convention::UnitDiskSide ? side_from_d(d) : 1.0L;
}

long double oler_bound(long long n) {
  return (-3.0L + std::sqrt(8.0L * static_cast<long double>(n) + 1.0L)) / 2.0L;
}

long double oler_delta(long long n, long double L) {
  return L - oler_bound(n);
}

}  // namespace tripack
