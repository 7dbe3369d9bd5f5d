#include "analysis/interior_relax.hpp"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "analysis/sparse_cholesky.hpp"
#include "core/neighbours.hpp"

namespace tripack {

namespace {

using SpMat = Eigen::SparseMatrix<double>;

// Everything below is in disk units: the start's minimum distance is 1, the side is L.
// A step moves no coordinate by more than kMaxMove, and the barrier keeps every pair within
// D + kReach and every wall within kReach: a pair outside the list closes by at most
// 2 sqrt2 kMaxMove < kReach - kMaxGain per step, so it can never become the closest.
constexpr long double kMaxMove = 0.1L;
constexpr long double kMaxGain = 0.01L;
constexpr long double kReach = 0.3L;

// One barrier term: the pair (i, j), or disk i and a wall (j = -1 - side).
struct Term {
  int i, j;
  bool operator==(const Term&) const = default;
  bool wall() const { return j < 0; }
  Side side() const { return static_cast<Side>(-1 - j); }
};

struct State {
  std::vector<Vec2L> x;
  long double D = 0;
};

std::vector<Term> near_terms(const State& s, long double L) {
  std::vector<Term> terms;
  for_each_pair_within(s.x, s.D + kReach, [&](int i, int j, long double) {
    terms.push_back({i, j});
  });
  for (std::size_t i = 0; i < s.x.size(); ++i)
    for (Side side : kSides)
      if (wall_distance(s.x[i], side, L) <= kReach)
        terms.push_back({static_cast<int>(i), -1 - static_cast<int>(side)});
  return terms;
}

long double slack(const Term& term, const State& s, long double L) {
  const auto& p = s.x[static_cast<std::size_t>(term.i)];
  if (term.wall()) return wall_distance(p, term.side(), L);
  return norm(p - s.x[static_cast<std::size_t>(term.j)]) - s.D;
}

// F_t over the given terms, less t D_base (t D alone would be ~1e16 at the end, where long
// double resolves it only to ~1e-3, the size of the Newton decrements to be compared); -inf
// outside the barrier's domain.
long double barrier_value(const std::vector<Term>& terms, const State& s, long double t,
                          long double L, long double D_base) {
  long double f = t * (s.D - D_base);
  for (const auto& term : terms) {
    const long double v = slack(term, s, L);
    if (!(v > 0)) return -std::numeric_limits<long double>::infinity();
    f += std::log(v);
  }
  return f;
}

struct NewtonStep {
  Eigen::VectorXd y;     // displacement, 2 per disk
  double gain = 0;       // change of D
  double decrement = 0;  // gradient . step: twice the predicted increase of F_t
  bool ok = false;
};

// The Gauss-Newton step of F_t: K [y; gain] = grad with K = sum over terms of a a^T / s^2 (a the
// term's gradient in (x, D)), positive definite once 1e-15 of its largest diagonal is added
// (disks with no near term would make it singular; 1e-12 slowed the sliding of nearly floppy
// rows: 527 instead of 112 Newton steps for a billiards end state at n = 1000). The D row and
// column are dense, so they are eliminated through a Schur complement: two solves with one
// factorization. Which one depends on n (per Newton step, 2026-11-28, one thread): Eigen's
// simplicial LL^T is faster up to tens of thousands of disks (n = 1000: 2.3 against 5.0 ms;
// n = 5048: 30 against 64 ms; n = 20,098: 257 against 411 ms), CHOLMOD's supernodal LL^T above
// (n = 80,198: 2.7 against 3.1 s; n = 100,577: 2.4 against 3.2 s for Eigen's LDL^T). The
// fill-reducing ordering is computed again only when the terms changed since the last step
// (`same_terms`). The simplicial Cholesky below SparseCholesky::kSupernodalFrom unknowns.
using Cholesky = SparseCholesky;
NewtonStep newton_step(const std::vector<Term>& terms, bool same_terms, const State& s,
                       long double t, long double L, Cholesky& cholesky) {
  const auto n = static_cast<Eigen::Index>(s.x.size());
  Eigen::VectorXd gx = Eigen::VectorXd::Zero(2 * n), k = Eigen::VectorXd::Zero(2 * n);
  double gD = static_cast<double>(t), kappa = 0;
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(terms.size() * 16);
  auto block = [&](Eigen::Index r, Eigen::Index c, double ux, double uy, double w) {
    triplets.emplace_back(r, c, w * ux * ux);
    triplets.emplace_back(r, c + 1, w * ux * uy);
    triplets.emplace_back(r + 1, c, w * uy * ux);
    triplets.emplace_back(r + 1, c + 1, w * uy * uy);
  };
  for (const auto& term : terms) {
    const long double v = slack(term, s, L);
    const double inv = static_cast<double>(1 / v), inv2 = inv * inv;
    const Eigen::Index a = 2 * term.i;
    if (term.wall()) {
      const auto nrm = wall_normal<double>(term.side());
      gx[a] += nrm.x * inv;
      gx[a + 1] += nrm.y * inv;
      block(a, a, nrm.x, nrm.y, inv2);
      continue;
    }
    const Eigen::Index b = 2 * term.j;
    const Vec2L dv = s.x[static_cast<std::size_t>(term.i)] - s.x[static_cast<std::size_t>(term.j)];
    const Vec2L u = dv / norm(dv);
    const double ux = static_cast<double>(u.x), uy = static_cast<double>(u.y);
    gx[a] += ux * inv;
    gx[a + 1] += uy * inv;
    gx[b] -= ux * inv;
    gx[b + 1] -= uy * inv;
    gD -= inv;
    k[a] -= ux * inv2;
    k[a + 1] -= uy * inv2;
    k[b] += ux * inv2;
    k[b + 1] += uy * inv2;
    kappa += inv2;
    block(a, a, ux, uy, inv2);
    block(b, b, ux, uy, inv2);
    block(a, b, ux, uy, -inv2);
    block(b, a, ux, uy, -inv2);
  }
  for (Eigen::Index c = 0; c < 2 * n; ++c) triplets.emplace_back(c, c, 0.0);  // every diagonal
  SpMat K(2 * n, 2 * n);
  K.setFromTriplets(triplets.begin(), triplets.end());
  const double regularization = 1e-15 * std::max(1.0, K.diagonal().maxCoeff());
  for (Eigen::Index c = 0; c < 2 * n; ++c) K.coeffRef(c, c) += regularization;
  NewtonStep step;
  if (!same_terms) cholesky.analyze_pattern(K);
  cholesky.factorize(K);
  if (!cholesky.succeeded()) return step;
  const Eigen::VectorXd z1 = cholesky.solve(gx), z2 = cholesky.solve(k);
  const double schur = kappa - k.dot(z2);
  if (!(schur > 0)) return step;
  step.gain = (gD - k.dot(z1)) / schur;
  step.y = z1 - step.gain * z2;
  step.decrement = gx.dot(step.y) + gD * step.gain;
  step.ok = std::isfinite(step.decrement) && step.decrement >= 0;
  return step;
}

// Backtracking along the step from the largest length the move caps allow: the first length
// whose F_t rises by a tenth of the predicted rate (Armijo). False if none does.
bool line_search(const std::vector<Term>& terms, State& s, const NewtonStep& step, long double t,
                 long double L) {
  const long double largest = step.y.cwiseAbs().maxCoeff();
  long double alpha = 1;
  if (largest * alpha > kMaxMove) alpha = kMaxMove / largest;
  if (std::fabs(step.gain) * alpha > kMaxGain) alpha = kMaxGain / std::fabs(step.gain);
  const long double f0 = barrier_value(terms, s, t, L, s.D);
  if (!std::isfinite(f0)) return false;
  State trial = s;
  for (int halving = 0; halving < 60; ++halving, alpha /= 2) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      trial.x[i].x = s.x[i].x + alpha * step.y[static_cast<Eigen::Index>(2 * i)];
      trial.x[i].y = s.x[i].y + alpha * step.y[static_cast<Eigen::Index>(2 * i + 1)];
    }
    trial.D = s.D + alpha * step.gain;
    const long double f = barrier_value(terms, trial, t, L, s.D);
    if (f >= f0 + 0.1L * alpha * step.decrement) {
      s = std::move(trial);
      return true;
    }
  }
  return false;
}

}  // namespace

InteriorRelaxReport interior_relax(Packing& pk, const InteriorRelaxOptions& opt) {
  const std::size_t n = pk.size();
  if (n < 2) throw std::invalid_argument("relax needs at least two disks");
  InteriorRelaxReport rep;
  // Centres projected inside (until inside), then shrunk towards the centroid by a relative 1e-9
  // so that every wall slack is strictly positive.
  std::vector<Vec2L> start = pk.points;
  for (auto& p : start) project_inside(p, 80);
  const long double d0 = min_pair_distance(start, pk.d > 0 ? 1.5L * pk.d : 1.0L);
  if (!(d0 > 0) || !std::isfinite(d0)) throw std::invalid_argument("relax: coincident disks");
  rep.d_start = d0;
  const long double L = 1 / d0;
  const Vec2L centroid{0.5L, std::sqrt(3.0L) / 6};
  State s;
  for (const auto& p : start) s.x.push_back((centroid + (p - centroid) * (1 - 1e-9L)) * L);
  s.D = (1 - 1e-9L) * (1 - opt.start_margin);

  // t starts where D is centred: d F_t / d D = t - sum 1/s_pairs = 0.
  long double t = 0;
  for (const auto& term : near_terms(s, L))
    if (!term.wall()) t += 1 / slack(term, s, L);
  Cholesky cholesky(2 * static_cast<Eigen::Index>(n),
                    opt.supernodal ? 0 : SparseCholesky::kSupernodalFrom);
  std::vector<Term> last_terms;
  for (; rep.newton_steps < opt.max_newton_steps; t *= opt.t_factor) {
    ++rep.stages;
    bool centred = false;
    const int stage_steps = rep.stages == 1 ? opt.max_first_stage_steps : opt.max_stage_steps;
    for (int in_stage = 0; in_stage < stage_steps && rep.newton_steps < opt.max_newton_steps;
         ++in_stage) {
      const std::vector<Term> terms = near_terms(s, L);
      rep.constraints = static_cast<int>(terms.size());
      const bool same_terms = terms == last_terms;
      const NewtonStep step = newton_step(terms, same_terms, s, t, L, cholesky);
      if (!same_terms) last_terms = terms;
      ++rep.newton_steps;
      if (!step.ok) break;
      // The decrement is twice the predicted increase of F_t, so D is within ~decrement / t of
      // the stage's centre, far inside the barrier's own gap m / t when the decrement is below
      // 1e-6 m. (An absolute 1e-3 stalled at n = 100,577: m = 3e5 terms leave a decrement of
      // 1.3e-3 that rounding no longer reduces.)
      if (step.decrement < std::max(1e-3, 1e-6 * static_cast<double>(terms.size()))) {
        centred = true;
        break;
      }
      if (!line_search(terms, s, step, t, L)) break;
      if (opt.on_step) opt.on_step(rep.newton_steps, s.D * d0);
    }
    if (!centred) break;
    if (rep.constraints / t < opt.final_gap) {
      rep.converged = true;
      break;
    }
  }
  std::vector<Vec2L> relaxed(n);
  for (std::size_t i = 0; i < n; ++i) relaxed[i] = s.x[i] / L;
  const long double d = min_pair_distance(relaxed, 1.5L * d0);
  // Stopped before regaining the start's d (a stage failed early): keep the start.
  pk.points = d >= d0 ? std::move(relaxed) : std::move(start);
  pk.d = std::max(d, d0);
  rep.d_end = pk.d;
  return rep;
}

}  // namespace tripack
