// Delta(k+2)-2, the "sparse corner" pattern (docs/class6.md): GL1995's t43a, found best by
// billiards at n = 43 and 64 (k = 7, 9) and second or third at 26, 34, 53.
//
// Disk units, K = k+1 (the side is L = K - delta, delta > 0 small), m = floor(k/2),
// h = ceil(k/2) = k - m. Sites (i, j) of the hexagonal triangle of side K: row i from the apex,
// j = 0..i from the left. Four rigid lattice pieces and a short sparse chain:
//  * T = rows 0..h-1, a Delta(h) hanging from the apex (touches both side walls): A(i, j);
//  * M = rows h..2h-1 with i-h <= j <= h-1, an inverted Delta(h) under T, shifted by u_M;
//  * R = rows h..k-1 with j >= h, a Delta(m) against the right wall, slid down it by s e300;
//  * B = the sites with j <= i-h-1 (rows h+1..K), a Delta(m+1) in the bottom-left corner, on
//    the lattice of that corner: C(i, j);
//  * the chain under R: raised disks R_0..R_{m-1} in row K-1 and floor disks F_0..F_m, F_m in
//    the bottom-right corner; R_i touches F_i, F_{i+1} and the anchor A_i = R's site (k-1, h+i).
//    For odd k, F_0 is a free floor disk touching M's bottom vertex (K-1, m); for even k, M ends
//    one row higher and F_0 is B's last floor disk (K, m).
// Bonds: every lattice pair inside a piece; across pieces only T-M and M-B pairs along e240 (T
// over M, M over B) and M-R pairs along e0; the side walls of T, R, B and the floor under B; the
// chain's contacts. All other lattice pairs across the cracks are open (gaps ~ tau below). That is
// 3 Delta(k+1) bonds for every k, no rattlers.
//
// M touches T along e240 and B (whose lattice is the apex lattice moved by delta e60) along e240:
// u_M = (delta/2) e60 + tau e330 with tau^2 = delta - delta^2/4 (two unit circles whose centres
// are 2 - delta apart). M touches R along e0: |e0 + s e300 - u_M| = 1 fixes s. So tau fixes
// everything above the chain; the chain is marched from F_0 to the right and the one condition
// is F_m = (L, 0). tau is found by bisection in long double (tau = 4.6e-3 at k = 9, 2.5e-6 at
// k = 14: the corrections shrink super-exponentially in m, like the sparse-rows pattern's).
// The whole bond system then goes to the polisher, and finish() re-detects the bonds from the
// geometry alone: they must be exactly the intended ones.
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "constructors/blocks.hpp"
#include "constructors/builders.hpp"
#include "constructors/chain.hpp"
#include "constructors/registry.hpp"
#include "polish/polish.hpp"

namespace tripack {

namespace {

using D = Directions<long double>;
constexpr Vec2L kE330{kSqrt3 / 2, -0.5L};

enum class Piece { None, T, M, R, B };

struct Corner {
  long k = 0, m = 0, h = 0, K = 0;
  long double tau = 0, delta = 0, L = 0;
  Vec2L uM, uR;
  std::vector<Vec2L> floor;   // F_0..F_m
  std::vector<Vec2L> raised;  // R_0..R_{m-1}
};

// Site (i, j) of the lattice hanging from the apex of the triangle of side L.
Vec2L apex_site(long double L, long i, long j) {
  const auto ii = static_cast<long double>(i);
  return {L / 2 - ii / 2 + static_cast<long double>(j), (L - ii) * kSqrt3 / 2};
}

// Site (i, j) of the lattice of the bottom-left corner (side K).
Vec2L corner_site(long K, long i, long j) {
  const auto up = static_cast<long double>(K - i);
  return {static_cast<long double>(j) + up / 2, up * kSqrt3 / 2};
}

// Everything for a given tau; returns F_m.x - L, or nullopt if the chain cannot be built.
std::optional<long double> march(Corner& c, long double tau) {
  c.tau = tau;
  c.delta = 2 * tau * tau / (1 + std::sqrt((1 - tau) * (1 + tau)));
  c.L = static_cast<long double>(c.K) - c.delta;
  c.uM = D::e60 * (c.delta / 2) + kE330 * tau;
  // |e0 + s e300 - u_M| = 1: s^2 + 2 b s - q = 0 with b = (e0 - u_M).e300, q = 1 - |e0 - u_M|^2.
  const long double b = dot(D::e0 - c.uM, D::e300);
  const long double q = 2 * c.uM.x - dot(c.uM, c.uM);
  if (!(b * b + q >= 0)) return std::nullopt;
  const long double s = q / (b + std::sqrt(b * b + q));
  c.uR = D::e300 * s;
  if (c.k % 2) {
    const Vec2L mb = apex_site(c.L, c.K - 1, c.m) + c.uM;
    if (!(mb.y > 0 && mb.y < 1)) return std::nullopt;
    c.floor[0] = {mb.x + std::sqrt((1 - mb.y) * (1 + mb.y)), 0};
  } else {
    c.floor[0] = corner_site(c.K, c.K, c.m);
  }
  for (long i = 0; i < c.m; ++i) {
    const auto u = static_cast<std::size_t>(i);
    const auto r = unit_circles_left(apex_site(c.L, c.K - 2, c.h + i) + c.uR, c.floor[u]);
    if (!r || !(r->y > 0 && r->y < 1)) return std::nullopt;
    c.raised[u] = *r;
    c.floor[u + 1] = {r->x + std::sqrt((1 - r->y) * (1 + r->y)), 0};
  }
  return c.floor[static_cast<std::size_t>(c.m)].x - c.L;
}

// The root is the first sign change of the residual going up from tau = 0 (the lattice):
// tau = 0.048 at k = 5, 4.6e-3 at k = 9, 1.1e-8 at k = 17. Scanned on a logarithmic grid, then
// bisected to the last bit.
Corner solve(long k) {
  Corner c;
  c.k = k;
  c.m = k / 2;
  c.h = k - c.m;
  c.K = k + 1;
  c.floor.resize(static_cast<std::size_t>(c.m + 1));
  c.raised.resize(static_cast<std::size_t>(c.m));
  // At tau = 0 the chain is the lattice itself (F_0 and A_0 exactly 2 apart): start above it.
  long double lo = 0, hi = 0, f_lo = 0;
  bool valid = false, bracketed = false;
  for (int j = 0; j <= 8 * 24 && !bracketed; ++j) {  // tau = 1e-24 .. 1
    const long double t = std::pow(10.0L, -24.0L + static_cast<long double>(j) / 8);
    const auto v = march(c, t);
    if (!v) {
      if (valid) break;
      continue;
    }
    if (valid && (*v > 0) != (f_lo > 0)) {
      hi = t;
      bracketed = true;
    } else {
      lo = t;
      f_lo = *v;
      valid = true;
    }
  }
  if (!bracketed) throw std::runtime_error("sparse corner: no root for k=" + std::to_string(k));
  for (int it = 0; it < 300; ++it) {
    const long double mid = (lo + hi) / 2;
    if (mid <= lo || mid >= hi) break;
    const auto v = march(c, mid);
    if (!v) throw std::runtime_error("sparse corner: chain breaks inside the bracket");
    if ((*v > 0) == (f_lo > 0)) {
      lo = mid;
      f_lo = *v;
    } else {
      hi = mid;
    }
  }
  const long double f_hi = *march(c, hi);
  march(c, std::fabs(f_hi) < std::fabs(f_lo) ? hi : lo);
  return c;
}

}  // namespace

Pattern build_sparse_corner(long k) {
  if (k < 3) throw std::invalid_argument("Delta(k+2)-2 (sparse corner) needs k >= 3");
  const Corner c = solve(k);
  const long m = c.m, h = c.h, K = c.K;
  long double L = c.L;

  auto piece = [&](long i, long j) {
    if (i < 0 || j < 0 || j > i || i > K) return Piece::None;
    if (i <= h - 1) return Piece::T;
    if (i <= K - 2) return j <= i - h - 1 ? Piece::B : (j <= h - 1 ? Piece::M : Piece::R);
    if (i == K - 1) return j <= m - 1 ? Piece::B : (k % 2 && j == m ? Piece::M : Piece::None);
    return j <= m ? Piece::B : Piece::None;  // the floor row
  };

  DiskUnitsPattern pat(L);
  std::vector<std::vector<int>> index(static_cast<std::size_t>(K + 1));
  for (long i = 0; i <= K; ++i) {
    auto& row = index[static_cast<std::size_t>(i)];
    row.assign(static_cast<std::size_t>(i + 1), -1);
    for (long j = 0; j <= i; ++j) {
      Vec2L p;
      switch (piece(i, j)) {
        case Piece::None:
          continue;
        case Piece::T:
          p = apex_site(L, i, j);
          break;
        case Piece::M:
          p = apex_site(L, i, j) + c.uM;
          break;
        case Piece::R:
          p = apex_site(L, i, j) + c.uR;
          break;
        case Piece::B:
          p = corner_site(K, i, j);
          break;
      }
      row[static_cast<std::size_t>(j)] = pat.add(p);
    }
  }
  auto at = [&](long i, long j) {
    return index[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
  };

  std::vector<Bond> bonds;
  for (long i = 0; i <= K; ++i) {
    for (long j = 0; j <= i; ++j) {
      const Piece p = piece(i, j);
      if (p == Piece::None) continue;
      // Lower and right lattice neighbours: e0 (i, j+1), e240 (i+1, j), e300 (i+1, j+1).
      const long nb[3][2] = {{i, j + 1}, {i + 1, j}, {i + 1, j + 1}};
      for (int dir = 0; dir < 3; ++dir) {
        const Piece q = piece(nb[dir][0], nb[dir][1]);
        if (q == Piece::None) continue;
        const bool bonded = p == q || (dir == 1 && p == Piece::T && q == Piece::M) ||
                            (dir == 1 && p == Piece::M && q == Piece::B) ||
                            (dir == 0 && p == Piece::M && q == Piece::R);
        if (bonded) bonds.push_back(Bond::pair(at(i, j), at(nb[dir][0], nb[dir][1])));
      }
      if (j == 0 && (p == Piece::T || p == Piece::B))
        bonds.push_back(Bond::wall(at(i, j), Side::Left));
      if (j == i && (p == Piece::T || p == Piece::R))
        bonds.push_back(Bond::wall(at(i, j), Side::Right));
      if (i == K) bonds.push_back(Bond::wall(at(i, j), Side::Bottom));
    }
  }
  // The chain: F_0 (new for odd k, B's (K, m) for even k), then R_i, F_{i+1}.
  std::vector<int> fl(static_cast<std::size_t>(m + 1)), ra(static_cast<std::size_t>(m));
  if (k % 2) {
    fl[0] = pat.add(c.floor[0]);
    bonds.push_back(Bond::wall(fl[0], Side::Bottom));
    bonds.push_back(Bond::pair(fl[0], at(K - 1, m)));
  } else {
    fl[0] = at(K, m);
  }
  for (long i = 0; i < m; ++i) {
    const auto u = static_cast<std::size_t>(i);
    ra[u] = pat.add(c.raised[u]);
    fl[u + 1] = pat.add(c.floor[u + 1]);
    bonds.push_back(Bond::wall(fl[u + 1], Side::Bottom));
    bonds.push_back(Bond::pair(ra[u], fl[u]));
    bonds.push_back(Bond::pair(ra[u], fl[u + 1]));
    bonds.push_back(Bond::pair(ra[u], at(K - 2, h + i)));
  }
  bonds.push_back(Bond::wall(fl.back(), Side::Right));
  std::sort(bonds.begin(), bonds.end());

  // The shooting start meets the system to a few ulp; the polisher confirms it (and would refine
  // a poor start), then finish() re-detects the contacts from the geometry alone.
  PolishOptions opt;
  opt.tolerance = 1e-17L;
  const PolishReport rep = polish_bond_system_disk_units(pat.points(), L, bonds, {}, opt);
  if (!(rep.max_residual < 1e-13L))
    throw std::runtime_error("sparse corner: contact system not solved for k=" + std::to_string(k) +
                             " (residual " + std::to_string(static_cast<double>(rep.max_residual)) +
                             ")");
  pat.set_side(L);
  Pattern out = pat.finish({});
  if (out.bonds != bonds)
    throw std::logic_error("sparse corner: detected contacts differ from the intended ones for k=" +
                           std::to_string(k));
  return out;
}

namespace {
const BuilderRegistration kSparseCorner{
    "sparse-corner", [](const BuilderCall& c) { return build_sparse_corner(c.k); }};
}  // namespace

}  // namespace tripack
