#include "polish/polish.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "polish/bond_system.hpp"

namespace tripack {

namespace bond_system {

Layout make_layout(std::size_t n, const std::vector<int>& rattlers) {
  Layout lay;
  lay.column.assign(n, 0);
  for (int r : rattlers) lay.column.at(static_cast<std::size_t>(r)) = -1;
  int c = 0;
  for (auto& col : lay.column) {
    if (col == 0) {
      col = c;
      c += 2;
    }
  }
  lay.l_column = c;
  lay.unknowns = c + 1;
  return lay;
}

void check_bonds(std::size_t n, const std::vector<Bond>& bonds) {
  for (const auto& b : bonds) {
    if (b.a < 0 || static_cast<std::size_t>(b.a) >= n ||
        (!b.is_wall() && static_cast<std::size_t>(b.b) >= n))
      throw std::invalid_argument("polish: bond refers to a disk that does not exist");
  }
}

SpMat jacobian(const std::vector<Bond>& bonds, const std::vector<Vec2L>& x, const Layout& lay) {
  std::vector<Eigen::Triplet<double, SuiteSparse_long>> t;
  t.reserve(bonds.size() * 5);
  for (std::size_t e = 0; e < bonds.size(); ++e) {
    const auto row = static_cast<SuiteSparse_long>(e);
    const auto& b = bonds[e];
    const int ca = lay.column[static_cast<std::size_t>(b.a)];
    if (b.is_wall()) {
      const auto nrm = wall_normal<double>(b.side());
      if (ca >= 0) {
        t.emplace_back(row, ca, nrm.x);
        t.emplace_back(row, ca + 1, nrm.y);
      }
      if (b.side() == Side::Right) t.emplace_back(row, lay.l_column, kSqrt3 / 2);
      continue;
    }
    const int cb = lay.column[static_cast<std::size_t>(b.b)];
    const Vec2L dv = x[static_cast<std::size_t>(b.a)] - x[static_cast<std::size_t>(b.b)];
    const long double len = norm(dv);
    const double ux = static_cast<double>(dv.x / len), uy = static_cast<double>(dv.y / len);
    if (ca >= 0) {
      t.emplace_back(row, ca, ux);
      t.emplace_back(row, ca + 1, uy);
    }
    if (cb >= 0) {
      t.emplace_back(row, cb, -ux);
      t.emplace_back(row, cb + 1, -uy);
    }
  }
  SpMat J(static_cast<SuiteSparse_long>(bonds.size()), lay.unknowns);
  J.setFromTriplets(t.begin(), t.end());
  J.makeCompressed();
  return J;
}

}  // namespace bond_system

namespace {

using bond_system::Layout;
using bond_system::SpMat;

long double residual(const Bond& b, const std::vector<Vec2L>& x, long double L) {
  const auto& p = x[static_cast<std::size_t>(b.a)];
  if (b.is_wall()) return wall_distance(p, b.side(), L);
  return norm(p - x[static_cast<std::size_t>(b.b)]) - 1.0L;
}

void residuals(const std::vector<Bond>& bonds, const std::vector<Vec2L>& x, long double L,
               Eigen::VectorXd& r, long double& max_abs, long double& sum_sq) {
  max_abs = 0;
  sum_sq = 0;
  for (std::size_t e = 0; e < bonds.size(); ++e) {
    const long double v = residual(bonds[e], x, L);
    r[static_cast<Eigen::Index>(e)] = static_cast<double>(v);
    max_abs = std::max(max_abs, std::fabs(v));
    sum_sq += v * v;
  }
}

void apply_step(std::vector<Vec2L>& x, long double& L, const Layout& lay, const Eigen::VectorXd& dz,
                long double scale) {
  for (std::size_t i = 0; i < x.size(); ++i) {
    const int c = lay.column[i];
    if (c < 0) continue;
    x[i].x -= scale * static_cast<long double>(dz[c]);
    x[i].y -= scale * static_cast<long double>(dz[c + 1]);
  }
  L -= scale * static_cast<long double>(dz[lay.l_column]);
}

}  // namespace

PolishReport polish_bond_system_disk_units(std::vector<Vec2L>& x, long double& L,
                                           const std::vector<Bond>& bonds,
                                           const std::vector<int>& rattlers,
                                           const PolishOptions& options) {
  PolishReport rep;
  const Layout lay = bond_system::make_layout(x.size(), rattlers);
  bond_system::check_bonds(x.size(), bonds);
  rep.unknowns = lay.unknowns;
  rep.equations = static_cast<int>(bonds.size());
  if (bonds.empty()) {
    rep.converged = true;
    return rep;
  }
  Eigen::VectorXd r(static_cast<Eigen::Index>(bonds.size()));
  long double max_abs = 0, sum_sq = 0;
  residuals(bonds, x, L, r, max_abs, sum_sq);

  const long double tol = options.tolerance * std::max(1.0L, L);
  Eigen::SPQR<SpMat> qr;
  bool have_factor = false;
  bool fresh_factor = false;
  for (int it = 0; it < options.max_iterations && max_abs > tol; ++it) {
    // Newton with a reused factorization converges linearly at rate ~ (change in J); refactor
    // whenever the residual is not small or the reused factor stops paying off.
    if (!have_factor || max_abs > 1e-8L) {
      const SpMat J = bond_system::jacobian(bonds, x, lay);
      qr.compute(J);
      if (qr.info() != Eigen::Success) throw std::runtime_error("polish: sparse QR failed");
      rep.rank = static_cast<int>(qr.rank());
      ++rep.factorizations;
      have_factor = true;
      fresh_factor = true;
    }
    const Eigen::VectorXd dz = qr.solve(r);
    ++rep.iterations;
    // Backtracking line search on the sum of squares.
    long double scale = 1;
    bool improved = false;
    for (int ls = 0; ls < 40; ++ls) {
      auto xt = x;
      long double Lt = L;
      apply_step(xt, Lt, lay, dz, scale);
      Eigen::VectorXd rt(r.size());
      long double mt = 0, st = 0;
      residuals(bonds, xt, Lt, rt, mt, st);
      if (st < sum_sq) {
        x = std::move(xt);
        L = Lt;
        r = std::move(rt);
        max_abs = mt;
        improved = sum_sq - st > 1e-3L * sum_sq;  // meaningful progress
        sum_sq = st;
        break;
      }
      scale /= 2;
    }
    if (!improved) {
      if (fresh_factor) break;  // at the rounding floor (or stuck): nothing more to gain
      have_factor = false;      // stale factorization: refactor once before giving up
      continue;
    }
    fresh_factor = false;
  }
  rep.max_residual = max_abs;
  // Converged: at the requested tolerance, or stopped at a rounding floor within 1e-16 (relative)
  // of consistency, ~1000 long double roundings. Anything larger means the bond system has no
  // solution near the start: a false bond with a true gap of 1e-14 d (sparse-rows k = 9 has such
  // near contacts) must not pass.
  rep.converged = max_abs <= std::max(tol, 1e-16L * std::max(1.0L, L));
  return rep;
}

PolishReport polish_bond_system(Packing& packing, const std::vector<Bond>& bonds,
                                const std::vector<int>& rattlers, const PolishOptions& options) {
  if (!(packing.d > 0)) throw std::invalid_argument("polish: packing has no positive d");
  long double L = 1.0L / packing.d;
  std::vector<Vec2L> x(packing.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = packing.points[i] * L;
  auto rep = polish_bond_system_disk_units(x, L, bonds, rattlers, options);
  // Rattlers are not unknowns: keep them where they were relative to the triangle.
  std::vector<char> is_rattler(x.size(), 0);
  for (int r : rattlers) is_rattler[static_cast<std::size_t>(r)] = 1;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!is_rattler[i]) packing.points[i] = x[i] / L;
  }
  packing.d = 1.0L / L;
  return rep;
}

}  // namespace tripack
