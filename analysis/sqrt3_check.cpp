#include "analysis/sqrt3_check.hpp"

// CGAL stays in this translation unit: its headers cost ~20 s to compile.
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Sqrt_extension.h>
#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/neighbours.hpp"

namespace tripack {
namespace {

// a + b sqrt3 in CGAL's exact Q(sqrt3). No interval filter: the coefficients are small integers,
// for which the exact sign test (signs of a and b, then a^2 against 3 b^2) is cheaper than
// building intervals, and every bond is a zero that a filter could not decide anyway.
template <class NT>
using Surd = CGAL::Sqrt_extension<NT, NT, CGAL::Tag_false, CGAL::Tag_false>;
// Integer coefficients for exact disks (GMP integers skip the rationals' gcd work); rationals
// only when a numerically placed rattler is involved.
using Z = CGAL::Gmpz;
using Q = CGAL::Gmpq;

static_assert(sizeof(long) == sizeof(long long), "HalfSurd3 coefficients go through long");
static_assert(std::numeric_limits<long double>::digits <= 64, "rattler coordinates -> 64 bits");

template <class NT>
Surd<NT> surd(const NT& a, const NT& b) {
  return Surd<NT>(a, b, NT(3));
}

template <class NT>
Surd<NT> surd(const HalfSurd3& h) {  // 2h = p + q sqrt3
  return surd(NT(static_cast<long>(h.p)), NT(static_cast<long>(h.q)));
}

template <class NT>
Surd<NT> times_sqrt3(const Surd<NT>& v) {
  return surd(NT(3) * v.a1(), v.a0());
}

// A point at twice its disk-unit coordinates: every exact one then has integer coefficients.
template <class NT>
struct Twice {
  Surd<NT> x, y;
};

// 4 (|dx, dy|^2 - 1) for (dx, dy) = twice a difference of points: its sign is that of dist - 1.
template <class NT>
Surd<NT> gap4(const Surd<NT>& dx, const Surd<NT>& dy) {
  return dx * dx + dy * dy - Surd<NT>(NT(4));
}

// 4 times the signed distance of P to side s (2L = twice the side).
template <class NT>
Surd<NT> wall4(const Twice<NT>& P, const Surd<NT>& L2, Side s) {
  switch (s) {
    case Side::Bottom:
      return P.y + P.y;
    case Side::Left:
      return times_sqrt3(P.x) - P.y;
    case Side::Right:
      return times_sqrt3(L2 - P.x) - P.y;
  }
  return {};
}

// The exact rational value of a long double: significand (<= 64 bits) times a power of 2.
Q sqrt3_rational(long double v) {
  if (v == 0) return Q(0);
  int e = 0;
  const long double m = std::frexp(std::fabs(v), &e);  // |v| = m 2^e, 1/2 <= m < 1
  const auto significand = static_cast<unsigned long>(std::ldexp(m, 64));
  mpq_t t;
  mpq_init(t);
  mpq_set_ui(t, significand, 1);
  if (e >= 64)
    mpq_mul_2exp(t, t, static_cast<mp_bitcnt_t>(e - 64));
  else
    mpq_div_2exp(t, t, static_cast<mp_bitcnt_t>(64 - e));
  if (v < 0) mpq_neg(t, t);
  Q r(t);
  mpq_clear(t);
  return r;
}

// A double near a + b sqrt3 without cancellation: when a and b have opposite signs,
// (a^2 - 3b^2) / (a - b sqrt3) has an exact numerator and a denominator of like-signed terms.
template <class NT>
double approx_value(const Surd<NT>& v) {
  const NT &a = v.a0(), &b = v.a1();
  if (CGAL::sign(a) * CGAL::sign(b) >= 0) return CGAL::to_double(v);
  return CGAL::to_double(NT(a * a - NT(3) * b * b)) /
         (CGAL::to_double(a) - CGAL::to_double(b) * std::sqrt(3.0));
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

class Checker {
 public:
  explicit Checker(const Pattern& pat) : pat_(pat), ex_(*pat.sqrt3) {}

  Sqrt3CheckReport run() {
    if (consistent() && bonds_hold() && walls_open() && pairs_open()) rep_.ok = true;
    return rep_;
  }

 private:
  bool fail(std::string msg) {
    if (rep_.failure.empty()) rep_.failure = std::move(msg);
    return false;
  }
  bool known(int i) const { return ex_.known[static_cast<std::size_t>(i)] != 0; }
  const Sqrt3Point& ep(int i) const { return ex_.points[static_cast<std::size_t>(i)]; }

  template <class NT>
  Twice<NT> twice(int i) const {
    if (known(i)) return {surd<NT>(ep(i).x), surd<NT>(ep(i).y)};
    if constexpr (std::is_same_v<NT, Q>) {
      const Vec2L& p = du_[static_cast<std::size_t>(i)];
      return {surd(Q(2) * sqrt3_rational(p.x), Q(0)), surd(Q(2) * sqrt3_rational(p.y), Q(0))};
    }
    throw std::logic_error("sqrt3_check: integer path for a disk without exact coordinates");
  }

  // The exact sign of 4 (dist^2 - 1) between disks i and j; its value in *approx on request (only
  // for failure messages: the checks themselves never round).
  CGAL::Sign pair_sign(int i, int j, double* approx = nullptr) const {
    if (known(i) && known(j)) {
      // Coefficients are below 2^61 (checked), so these int64 differences are exact.
      const Sqrt3Point d = ep(i) - ep(j);
      const Surd<Z> g = gap4(surd<Z>(d.x), surd<Z>(d.y));
      if (approx) *approx = approx_value(g);
      return CGAL::sign(g);
    }
    const Twice<Q> a = twice<Q>(i), b = twice<Q>(j);
    const Surd<Q> g = gap4(a.x - b.x, a.y - b.y);
    if (approx) *approx = approx_value(g);
    return CGAL::sign(g);
  }

  // The exact sign of 4 times the wall distance of disk i to side s (value in *approx on request).
  CGAL::Sign wall_sign(int i, Side s, double* approx = nullptr) const {
    if (known(i)) {
      const Surd<Z> w = wall4(twice<Z>(i), surd<Z>(ex_.L), s);
      if (approx) *approx = approx_value(w);
      return CGAL::sign(w);
    }
    const Surd<Q> w = wall4(twice<Q>(i), surd<Q>(ex_.L), s);
    if (approx) *approx = approx_value(w);
    return CGAL::sign(w);
  }

  // The exact data describe this packing, and fit the integer path.
  bool consistent() {
    const long double L = ex_.L.value();
    if (!(std::fabs(L * pat_.packing.d - 1) < 1e-12L))
      return fail("exact L = " + num(static_cast<double>(L)) +
                  " is not 1/d = " + num(static_cast<double>(1 / pat_.packing.d)));
    constexpr long long kMax = 1LL << 61;
    auto small = [](const HalfSurd3& h) {
      return h.p < kMax && h.p > -kMax && h.q < kMax && h.q > -kMax;
    };
    if (!small(ex_.L)) return fail("exact L has coefficients beyond 2^61");
    const std::size_t n = pat_.packing.size();
    du_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2L p = pat_.packing.points[i] * L;
      du_[i] = p;
      if (!ex_.known[i]) continue;
      const Sqrt3Point& e = ex_.points[i];
      if (!small(e.x) || !small(e.y))
        return fail("disk " + std::to_string(i) + ": exact coefficients beyond 2^61");
      const Vec2L v = e.value();
      if (std::fabs(v.x - p.x) > 1e-9L || std::fabs(v.y - p.y) > 1e-9L)
        return fail("disk " + std::to_string(i) + ": exact position (" +
                    num(static_cast<double>(v.x)) + ", " + num(static_cast<double>(v.y)) +
                    ") is not the packing's (" + num(static_cast<double>(p.x)) + ", " +
                    num(static_cast<double>(p.y)) + ") in disk units");
      du_[i] = v;
    }
    return true;
  }

  bool bonds_hold() {
    const auto n = static_cast<int>(pat_.packing.size());
    wall_bonds_.assign(static_cast<std::size_t>(n), 0);
    for (const Bond& b : pat_.bonds) {
      if (b.a < 0 || b.a >= n || b.b >= n || b.b == b.a || b.b < -3)
        return fail("bond (" + std::to_string(b.a) + ", " + std::to_string(b.b) +
                    ") is not a valid bond for " + std::to_string(n) + " disks");
      const std::string name =
          "bond " + std::to_string(b.a) + "-" +
          (b.is_wall() ? std::string(side_name(b.side())) : std::to_string(b.b));
      double approx = 0;
      if (b.is_wall()) {
        if (wall_sign(b.a, b.side()) != CGAL::ZERO) {
          wall_sign(b.a, b.side(), &approx);
          return fail(name + ": wall distance " + num(approx / 4) + " is not exactly 0");
        }
        wall_bonds_[static_cast<std::size_t>(b.a)] |= 1 << static_cast<int>(b.side());
      } else {
        if (pair_sign(b.a, b.b) != CGAL::ZERO) {
          pair_sign(b.a, b.b, &approx);
          return fail(name + ": squared distance - 1 = " + num(approx / 4) + ", not exactly 0");
        }
        pair_bonds_.push_back(key(b.a, b.b));
      }
      ++rep_.bonds_checked;
    }
    std::sort(pair_bonds_.begin(), pair_bonds_.end());
    return true;
  }

  // Every side without a wall bond is strictly away: this also proves every centre inside.
  bool walls_open() {
    const auto n = static_cast<int>(pat_.packing.size());
    for (int i = 0; i < n; ++i) {
      for (Side s : kSides) {
        if (wall_bonds_[static_cast<std::size_t>(i)] & (1 << static_cast<int>(s))) continue;
        if (wall_sign(i, s) != CGAL::POSITIVE) {
          double approx = 0;
          wall_sign(i, s, &approx);
          return fail("disk " + std::to_string(i) + ": distance " + num(approx / 4) + " to the " +
                      std::string(side_name(s)) + " side is not > 0 (no wall bond)");
        }
        ++rep_.gaps_checked;
      }
    }
    return true;
  }

  // Pairs farther than 1.5 in long double are farther than 1 beyond any rounding doubt.
  bool pairs_open() {
    bool ok = true;
    for_each_pair_within(du_, 1.5L, [&](int i, int j, long double) {
      if (!ok || std::binary_search(pair_bonds_.begin(), pair_bonds_.end(), key(i, j))) return;
      if (pair_sign(i, j) != CGAL::POSITIVE) {
        double approx = 0;
        pair_sign(i, j, &approx);
        ok = fail("disks " + std::to_string(i) + " and " + std::to_string(j) +
                  ": squared distance - 1 = " + num(approx / 4) + ", not > 0 (no bond)");
        return;
      }
      ++rep_.gaps_checked;
    });
    return ok;
  }

  static std::uint64_t key(int i, int j) {
    const auto lo = static_cast<std::uint64_t>(std::min(i, j));
    const auto hi = static_cast<std::uint64_t>(std::max(i, j));
    return lo << 32 | hi;
  }

  const Pattern& pat_;
  const Sqrt3DiskUnits& ex_;
  Sqrt3CheckReport rep_;
  std::vector<Vec2L> du_;  // disk units, long double: the candidate search
  std::vector<unsigned char> wall_bonds_;
  std::vector<std::uint64_t> pair_bonds_;
};

}  // namespace

Sqrt3CheckReport sqrt3_check(const Pattern& pattern) {
  if (!pattern.sqrt3) throw std::invalid_argument("sqrt3_check: the pattern has no Q(sqrt3) data");
  const std::size_t n = pattern.packing.size();
  if (pattern.sqrt3->points.size() != n || pattern.sqrt3->known.size() != n)
    throw std::invalid_argument("sqrt3_check: exact data for " +
                                std::to_string(pattern.sqrt3->points.size()) +
                                " disks, packing has " + std::to_string(n));
  return Checker(pattern).run();
}

}  // namespace tripack
