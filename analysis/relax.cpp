#include "analysis/relax.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>

#include "analysis/linear_program.hpp"
#include "core/neighbours.hpp"

namespace tripack {

namespace {

long double true_min_distance(const std::vector<Vec2L>& pts, long double hint) {
  // Every minimum pair is within the old minimum's reach; widen until something is found.
  for (long double r = hint * 1.5L;; r *= 2) {
    const long double m = min_pair_distance(pts, r);
    if (std::isfinite(m)) return m;
  }
}

struct Row {
  Bond bond;
};

}  // namespace

RelaxReport relax_packing(Packing& pk, const RelaxOptions& opt) {
  const std::size_t n = pk.size();
  if (n < 2) throw std::invalid_argument("relax needs at least two disks");
  RelaxReport rep;
  // Start inside: project any centre outside onto the triangle (twice, for the corners). Then the
  // zero step is feasible and d can only grow.
  for (auto& p : pk.points) project_inside(p, 2);
  long double d = true_min_distance(pk.points, pk.d > 0 ? pk.d : 1);
  rep.d_start = d;
  long double trust = opt.trust;

  for (int it = 0; it < opt.max_iterations; ++it) {
    ++rep.iterations;
    const long double box = trust * d;
    // Variables are displacements in units of the box (and the gain likewise), so the LP solver's
    // fixed tolerances (~1e-7) are relative to the step: the accuracy improves as the box shrinks.
    const long double reach = 3 * box + 1e-9L * d;  // a pair can close by at most 2 sqrt2 box
    LinearProgram lp;
    lp.set_scaling(false);
    for (std::size_t i = 0; i < n; ++i) {
      lp.add_column(-1, 1, 0);
      lp.add_column(-1, 1, 0);
    }
    // The gain may be negative only through LP round-off; leaving it free keeps the LP feasible.
    const int gain = lp.add_column(-LinearProgram::kInf, LinearProgram::kInf, 1);
    std::vector<Row> rows;
    for_each_pair_within(pk.points, d + reach, [&](int i, int j, long double r) {
      const Vec2L u =
          (pk.points[static_cast<std::size_t>(i)] - pk.points[static_cast<std::size_t>(j)]) / r;
      const double ux = static_cast<double>(u.x), uy = static_cast<double>(u.y);
      // r + box u.(yi - yj) >= d + box g
      lp.add_row(static_cast<double>((d - r) / box), LinearProgram::kInf,
                 {{2 * i, ux}, {2 * i + 1, uy}, {2 * j, -ux}, {2 * j + 1, -uy}, {gain, -1.0}});
      rows.push_back({Bond::pair(i, j)});
    });
    for (std::size_t i = 0; i < n; ++i) {
      for (Side s : kSides) {
        const long double w = wall_distance(pk.points[i], s, 1.0L);
        if (w > reach) continue;
        const auto nrm = wall_normal<double>(s);
        const int c = 2 * static_cast<int>(i);
        lp.add_row(static_cast<double>(-w / box), LinearProgram::kInf,
                   {{c, nrm.x}, {c + 1, nrm.y}});
        rows.push_back({Bond::wall(static_cast<int>(i), s)});
      }
    }
    rep.lp_columns = lp.columns();
    rep.lp_rows = lp.rows();
    const auto sol = lp.solve(true);
    if (sol.status != LinearProgram::Status::Optimal)
      throw std::runtime_error("relax: the step LP failed (status " +
                               std::to_string(static_cast<int>(sol.status)) + ")");

    // Contacts and forces of this LP (the last one is reported).
    rep.active.clear();
    rep.forces.clear();
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const double f = std::fabs(sol.dual[r]);
      if (f > 1e-9) {
        rep.active.push_back(rows[r].bond);
        rep.forces.push_back(f);
      }
    }

    const long double predicted = sol.x[static_cast<std::size_t>(gain)] * box;
    if (predicted < opt.stationary * d) {
      rep.converged = true;
      break;
    }
    // Take the step; keep it only if the true minimum distance grew (the LP is solved to ~1e-10,
    // so its feasibility is trusted only that far).
    std::vector<Vec2L> trial = pk.points;
    long double step = 0;
    for (std::size_t i = 0; i < n; ++i) {
      trial[i].x += sol.x[2 * i] * box;
      trial[i].y += sol.x[2 * i + 1] * box;
      step = std::max({step, std::fabs(sol.x[2 * i] * box), std::fabs(sol.x[2 * i + 1] * box)});
      project_inside(trial[i], 1);  // rounding-level excursions back inside
    }
    const long double d_trial = true_min_distance(trial, d);
    if (opt.on_step) opt.on_step(rep.iterations, std::max(d, d_trial));
    if (d_trial > d) {
      pk.points = std::move(trial);
      d = d_trial;
      // Size the next box by how far the loaded contacts still are from touching: near the optimum
      // that is far below the last step (convergence is quadratic), and a box much larger than the
      // remaining gain makes a badly scaled, massively degenerate LP (16 s instead of 0.1 s at
      // n = 991). Grow it again when a step was stopped by the box.
      long double open = 0;
      for (const auto& b : rep.active) {
        const auto& p = pk.points[static_cast<std::size_t>(b.a)];
        const long double gap = b.is_wall()
                                    ? wall_distance(p, b.side(), 1.0L)
                                    : norm(p - pk.points[static_cast<std::size_t>(b.b)]) - d;
        open = std::max(open, std::fabs(gap) / d);
      }
      const bool hit_box = step >= 0.99L * box;
      trust = std::clamp(std::max(16 * open, hit_box ? 4 * trust : 0.0L), opt.min_trust, opt.trust);
    } else {
      trust /= 4;
      if (trust < opt.min_trust) break;
    }
  }
  std::vector<std::pair<Bond, long double>> contacts;
  for (std::size_t a = 0; a < rep.active.size(); ++a)
    contacts.emplace_back(rep.active[a], rep.forces[a]);
  std::sort(contacts.begin(), contacts.end());
  for (std::size_t a = 0; a < contacts.size(); ++a)
    std::tie(rep.active[a], rep.forces[a]) = contacts[a];
  pk.d = d;
  rep.d_end = d;
  return rep;
}

}  // namespace tripack
