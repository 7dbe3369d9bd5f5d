#include "constructors/chain.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace tripack {

std::optional<Vec2L> unit_circles_left(const Vec2L& c1, const Vec2L& c2) {
  const Vec2L dv = c2 - c1;
  const long double dist = norm(dv);
  if (!(dist < 2) || dist == 0) return std::nullopt;
  const long double h = std::sqrt((1 - dist / 2) * (1 + dist / 2));
  const Vec2L u = dv / dist;
  return (c1 + c2) / 2.0L + Vec2L(-u.y, u.x) * h;
}

namespace {

// March from the symmetry axis to the left corner for a given X. Fills chain.floor / raised for
// indices on the left half (and the axis). Returns F_0.x, which must vanish, or nullopt if X is
// geometrically impossible.
std::optional<long double> march_left(RippleChain& c, long double X) {
  c.X = X;
  c.L = static_cast<long double>((c.q - 1) * c.step) + 2 * X;
  const long double mid = c.L / 2;
  int i;
  if (c.q % 2 == 1) {
    const int m = (c.q - 1) / 2;
    const long double ry = kSqrt3 * X - 1;  // R_m sits right under A_m
    if (!(ry < 1) || ry <= 0) return std::nullopt;
    c.raised[static_cast<std::size_t>(m)] = {mid, ry};
    c.floor[static_cast<std::size_t>(m)] = {mid - std::sqrt((1 - ry) * (1 + ry)), 0};
    i = m - 1;
  } else {
    const int m = c.q / 2;
    c.floor[static_cast<std::size_t>(m)] = {mid, 0};
    i = m - 1;
  }
  for (; i >= 0; --i) {
    // R_i touches F_{i+1} and A_i; it lies below-left of the segment F_{i+1} -> A_i.
    auto r = unit_circles_left(c.floor[static_cast<std::size_t>(i + 1)], c.anchor(i));
    if (!r || !(r->y < 1) || r->y <= 0) return std::nullopt;
    c.raised[static_cast<std::size_t>(i)] = *r;
    c.floor[static_cast<std::size_t>(i)] = {r->x - std::sqrt((1 - r->y) * (1 + r->y)), 0};
  }
  return c.floor[0].x;
}

}  // namespace

RippleChain solve_ripple_chain(int q, int step) {
  if (q < 1 || (step != 1 && step != 2))
    throw std::invalid_argument("ripple chain needs q >= 1 and step 1 or 2");
  RippleChain c;
  c.q = q;
  c.step = step;
  c.floor.assign(static_cast<std::size_t>(q + 1), {});
  c.raised.assign(static_cast<std::size_t>(q), {});

  // The physical root is the largest X < 1 (docs/classes.md §4a), and f = F_0.x grows with X. For
  // long chains (step 2, q >= ~250) the march from the axis cannot even be completed slightly
  // above the root (some floor disk ends more than 2 from its anchor): that side counts as
  // f > 0, and bisection then closes in on the root from both sides.
  // At X = 1 the residual is within rounding of zero when the root is closer to 1 than long
  // double resolves (step 1, q >= 11); then X = 1 is the root to working precision.
  const long double noise = 64 * std::numeric_limits<long double>::epsilon() * (q + 1) * step;
  auto too_large = [&](long double x) {
    const auto f = march_left(c, x);
    return !f || *f > 0;
  };
  const auto f_one = march_left(c, 1.0L);
  if (f_one && std::fabs(*f_one) <= noise) {
    march_left(c, 1.0L);
  } else {
    if (!too_large(1.0L))
      throw std::runtime_error("ripple chain: residual negative at X = 1 for q=" +
                               std::to_string(q));
    long double hi = 1.0L, lo = 0;
    bool bracketed = false;
    for (int j = 1; j <= 700 && !bracketed; ++j) {  // down to X = 0.3
      const long double x = 1.0L - j * 1e-3L;
      if (too_large(x))
        hi = x;
      else {
        lo = x;
        bracketed = true;
      }
    }
    if (!bracketed)
      throw std::runtime_error("ripple chain: no root for q=" + std::to_string(q) +
                               " step=" + std::to_string(step));
    // Bisection to the last bit: the march is cheap and bisection cannot be fooled by noise.
    for (int it = 0; it < 200; ++it) {
      const long double mid = (lo + hi) / 2;
      if (mid <= lo || mid >= hi) break;
      (too_large(mid) ? hi : lo) = mid;
    }
    const auto f_lo = march_left(c, lo);
    const auto f_hi = march_left(c, hi);
    const bool use_hi = f_hi && std::fabs(*f_hi) < std::fabs(*f_lo);
    const long double f = use_hi ? *f_hi : *f_lo;
    march_left(c, use_hi ? hi : lo);
    // The corner is set exactly below, which moves the first contact by f: it must be tiny.
    if (!(std::fabs(f) <= 1e-12L))
      throw std::runtime_error("ripple chain: q=" + std::to_string(q) +
                               " cannot be closed in long double (residual " +
                               std::to_string(static_cast<double>(f)) + ")");
  }
  // The corner is exactly at the origin by the equation; mirror the left half to the right.
  c.floor[0] = {0, 0};
  for (int i = 0; i < q; ++i) {
    const int j = q - 1 - i;
    if (j > i)
      c.raised[static_cast<std::size_t>(j)] = {c.L - c.raised[static_cast<std::size_t>(i)].x,
                                               c.raised[static_cast<std::size_t>(i)].y};
  }
  for (int i = 0; i <= q; ++i) {
    const int j = q - i;
    if (j > i)
      c.floor[static_cast<std::size_t>(j)] = {c.L - c.floor[static_cast<std::size_t>(i)].x, 0};
  }
  return c;
}

}  // namespace tripack
