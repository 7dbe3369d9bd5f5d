// Triangle geometry shared by every stage.
//
// Two coordinate systems appear in tripack:
//  * unit-triangle coordinates: vertices (0,0), (1,0), (1/2, sqrt3/2); a Packing lives here and its
//    minimum distance is d (docs/conventions.md);
//  * disk units: minimum distance 1 and triangle side L = 1/d; builders and the polisher work here
//    because bond equations are then |xi - xj| = 1.
#pragma once

#include <array>
#include <cmath>
#include <string_view>

namespace tripack {

template <class T>
struct Vec2T {
  T x{}, y{};
  constexpr Vec2T() = default;
  constexpr Vec2T(T x_, T y_) : x(x_), y(y_) {}
  template <class U>
  explicit constexpr Vec2T(const Vec2T<U>& o) : x(static_cast<T>(o.x)), y(static_cast<T>(o.y)) {}
  constexpr Vec2T operator+(const Vec2T& o) const { return {x + o.x, y + o.y}; }
  constexpr Vec2T operator-(const Vec2T& o) const { return {x - o.x, y - o.y}; }
  constexpr Vec2T operator*(T s) const { return {x * s, y * s}; }
  constexpr Vec2T operator/(T s) const { return {x / s, y / s}; }
  constexpr Vec2T operator-() const { return {-x, -y}; }
  Vec2T& operator+=(const Vec2T& o) {
    x += o.x;
    y += o.y;
    return *this;
  }
  Vec2T& operator-=(const Vec2T& o) {
    x -= o.x;
    y -= o.y;
    return *this;
  }
  constexpr bool operator==(const Vec2T&) const = default;
};

template <class T>
constexpr T dot(const Vec2T<T>& a, const Vec2T<T>& b) {
  return a.x * b.x + a.y * b.y;
}
template <class T>
T norm(const Vec2T<T>& a) {
  using std::hypot;
  return hypot(a.x, a.y);
}

using Vec2 = Vec2T<double>;
using Vec2L = Vec2T<long double>;

inline constexpr long double kSqrt3 = 1.732050807568877293527446341505872367L;

// The three sides of the triangle. The order is fixed: it is used as an index and in files.
enum class Side : int { Bottom = 0, Left = 1, Right = 2 };
inline constexpr std::array<Side, 3> kSides{Side::Bottom, Side::Left, Side::Right};
std::string_view side_name(Side s);

// Signed distance from p to side s of the triangle with side length `side` (positive inside).
// Inside the triangle all three are >= 0.
template <class T>
T wall_distance(const Vec2T<T>& p, Side s, T side) {
  const T h = static_cast<T>(kSqrt3) / 2;
  switch (s) {
    case Side::Bottom:
      return p.y;
    case Side::Left:
      return h * p.x - p.y / 2;
    case Side::Right:
      return h * (side - p.x) - p.y / 2;
  }
  return T(0);
}

// Inward unit normal of side s: the gradient of wall_distance with respect to p.
template <class T>
Vec2T<T> wall_normal(Side s) {
  const T h = static_cast<T>(kSqrt3) / 2;
  switch (s) {
    case Side::Bottom:
      return {T(0), T(1)};
    case Side::Left:
      return {h, T(-0.5)};
    case Side::Right:
      return {-h, T(-0.5)};
  }
  return {};
}

// p moved into the unit triangle: projected onto each side it lies outside of, pass after pass
// until one finds it inside, at most `passes` passes (near a 60-degree corner each projection
// onto one side leaves half the excursion outside the other).
template <class T>
void project_inside(Vec2T<T>& p, int passes) {
  for (int pass = 0; pass < passes; ++pass) {
    bool inside = true;
    for (Side side : kSides) {
      const T w = wall_distance(p, side, T(1));
      if (w < 0) {
        p = p - wall_normal<T>(side) * w;
        inside = false;
      }
    }
    if (inside) break;
  }
}

// Lattice directions used by every construction (disk units).
template <class T>
struct Directions {
  static constexpr T h = static_cast<T>(kSqrt3) / 2;
  static constexpr Vec2T<T> e0{T(1), T(0)};
  static constexpr Vec2T<T> e60{T(0.5), h};
  static constexpr Vec2T<T> e120{T(-0.5), h};
  static constexpr Vec2T<T> e180{T(-1), T(0)};
  static constexpr Vec2T<T> e240{T(-0.5), -h};
  static constexpr Vec2T<T> e300{T(0.5), -h};
};

}  // namespace tripack
