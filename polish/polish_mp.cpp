#include "polish/polish_mp.hpp"

// The MPFR C API rather than boost::multiprecision::mpfr_float: Boost 1.74's variable-precision
// mpfr_float propagates precision by rewriting a process-wide (not thread-local) default precision
// around every mixed operation, which is global state and not thread-safe. Here every number is
// initialized with an explicit precision and MPFR's own default is never read or changed.
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>

#include "polish/bond_system.hpp"
#include "polish/polish.hpp"

namespace tripack {

namespace {

constexpr mpfr_rnd_t kRnd = MPFR_RNDN;

// An MPFR number that owns its storage and keeps the precision it was created with.
class Mp {
 public:
  explicit Mp(mpfr_prec_t prec) { mpfr_init2(v_, prec); }
  Mp(const Mp& o) {
    mpfr_init2(v_, mpfr_get_prec(o.v_));
    mpfr_set(v_, o.v_, kRnd);
  }
  Mp(Mp&& o) noexcept {
    mpfr_init2(v_, MPFR_PREC_MIN);
    mpfr_swap(v_, o.v_);
  }
  Mp& operator=(const Mp& o) {
    if (this != &o) mpfr_set(v_, o.v_, kRnd);
    return *this;
  }
  Mp& operator=(Mp&& o) noexcept {
    mpfr_swap(v_, o.v_);
    return *this;
  }
  ~Mp() { mpfr_clear(v_); }
  mpfr_ptr get() { return v_; }
  mpfr_srcptr get() const { return v_; }

 private:
  mpfr_t v_;
};

// Disk-unit state: every centre (rattlers included, they stay fixed) and the side L.
struct State {
  std::vector<Mp> x, y;
  Mp L;
  State(std::size_t n, mpfr_prec_t prec) : x(n, Mp(prec)), y(n, Mp(prec)), L(prec) {}
};

// Scratch numbers for residual evaluation, allocated once.
struct Scratch {
  Mp h, t, u;  // h = sqrt(3)/2
  explicit Scratch(mpfr_prec_t prec) : h(prec), t(prec), u(prec) {
    mpfr_sqrt_ui(h.get(), 3, kRnd);
    mpfr_div_2ui(h.get(), h.get(), 1, kRnd);
  }
};

// Residuals of all bond equations into r, their largest magnitude into max_abs.
void residuals(const std::vector<Bond>& bonds, const State& s, Scratch& w, std::vector<Mp>& r,
               Mp& max_abs) {
  mpfr_set_zero(max_abs.get(), 1);
  for (std::size_t e = 0; e < bonds.size(); ++e) {
    const Bond& b = bonds[e];
    const auto a = static_cast<std::size_t>(b.a);
    mpfr_ptr out = r[e].get();
    if (!b.is_wall()) {
      const auto c = static_cast<std::size_t>(b.b);
      mpfr_sub(w.t.get(), s.x[a].get(), s.x[c].get(), kRnd);
      mpfr_sub(w.u.get(), s.y[a].get(), s.y[c].get(), kRnd);
      mpfr_hypot(out, w.t.get(), w.u.get(), kRnd);
      mpfr_sub_ui(out, out, 1, kRnd);
    } else {
      switch (b.side()) {
        case Side::Bottom:
          mpfr_set(out, s.y[a].get(), kRnd);
          break;
        case Side::Left:  // h x - y/2
          mpfr_mul(w.t.get(), w.h.get(), s.x[a].get(), kRnd);
          mpfr_div_2ui(w.u.get(), s.y[a].get(), 1, kRnd);
          mpfr_sub(out, w.t.get(), w.u.get(), kRnd);
          break;
        case Side::Right:  // h (L - x) - y/2
          mpfr_sub(w.t.get(), s.L.get(), s.x[a].get(), kRnd);
          mpfr_mul(w.t.get(), w.h.get(), w.t.get(), kRnd);
          mpfr_div_2ui(w.u.get(), s.y[a].get(), 1, kRnd);
          mpfr_sub(out, w.t.get(), w.u.get(), kRnd);
          break;
      }
    }
    if (mpfr_cmpabs(out, max_abs.get()) > 0) mpfr_abs(max_abs.get(), out, kRnd);
  }
}

// The residuals scaled by 2^-e (e = exponent of the largest) in double: at 300 digits they are
// ~1e-300, near double's underflow; the scale is undone exactly when the step is applied.
mpfr_exp_t scaled_residuals(const std::vector<Mp>& r, const Mp& max_abs, Eigen::VectorXd& rd) {
  const mpfr_exp_t e = mpfr_get_exp(max_abs.get());
  for (std::size_t i = 0; i < r.size(); ++i) {
    long ex = 0;
    const double m = mpfr_get_d_2exp(&ex, r[i].get(), kRnd);
    rd[static_cast<Eigen::Index>(i)] =
        std::ldexp(m, static_cast<int>(std::max<long>(ex - e, -2000)));
  }
  return e;
}

// out = in - dz * 2^e on the unknowns; rattlers are copied unchanged.
void apply_step(const State& in, State& out, const bond_system::Layout& lay,
                const Eigen::VectorXd& dz, mpfr_exp_t e, Mp& t) {
  auto sub = [&](mpfr_ptr o, mpfr_srcptr i, double v) {
    mpfr_set_d(t.get(), v, kRnd);  // exact: t has more than 53 bits
    mpfr_mul_2si(t.get(), t.get(), e, kRnd);
    mpfr_sub(o, i, t.get(), kRnd);
  };
  for (std::size_t i = 0; i < in.x.size(); ++i) {
    const int c = lay.column[i];
    if (c < 0) {
      mpfr_set(out.x[i].get(), in.x[i].get(), kRnd);
      mpfr_set(out.y[i].get(), in.y[i].get(), kRnd);
      continue;
    }
    sub(out.x[i].get(), in.x[i].get(), dz[c]);
    sub(out.y[i].get(), in.y[i].get(), dz[c + 1]);
  }
  sub(out.L.get(), in.L.get(), dz[lay.l_column]);
}

void factorize(Eigen::SPQR<bond_system::SpMat>& qr, const std::vector<Bond>& bonds,
               const std::vector<Vec2L>& x, const bond_system::Layout& lay) {
  const bond_system::SpMat J = bond_system::jacobian(bonds, x, lay);
  qr.compute(J);
  if (qr.info() != Eigen::Success) throw std::runtime_error("polish_multiprecision: QR failed");
}

std::vector<Vec2L> to_long_double(const State& s) {
  std::vector<Vec2L> x(s.x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = {mpfr_get_ld(s.x[i].get(), kRnd), mpfr_get_ld(s.y[i].get(), kRnd)};
  return x;
}

// v with `digits` significant digits in fixed notation (no exponent): d and L.
std::string significant(mpfr_srcptr v, int digits) {
  mpfr_exp_t e = 0;
  char* raw = mpfr_get_str(nullptr, &e, 10, static_cast<std::size_t>(digits), v, kRnd);
  std::string m(raw);
  mpfr_free_str(raw);
  std::string sign;
  if (!m.empty() && m[0] == '-') {
    sign = "-";
    m.erase(0, 1);
  }
  if (mpfr_zero_p(v)) return "0." + std::string(static_cast<std::size_t>(digits - 1), '0');
  // v = 0.m * 10^e
  if (e <= 0) return sign + "0." + std::string(static_cast<std::size_t>(-e), '0') + m;
  const auto ue = static_cast<std::size_t>(e);
  if (ue >= m.size()) return sign + m + std::string(ue - m.size(), '0');
  return sign + m.substr(0, ue) + "." + m.substr(ue);
}

// v in fixed notation with `decimals` decimals; a negative zero (a centre 1e-80 below its wall)
// prints as zero.
std::string fixed(mpfr_srcptr v, int decimals) {
  char* raw = nullptr;
  if (mpfr_asprintf(&raw, "%.*Rf", decimals, v) < 0) throw std::bad_alloc();
  std::string s(raw);
  mpfr_free_str(raw);
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

}  // namespace

MultiprecisionPolish polish_multiprecision(const Packing& start, const std::vector<Bond>& bonds,
                                           const std::vector<int>& rattlers, int digits) {
  if (digits < 1 || digits > 1000)
    throw std::invalid_argument("polish_multiprecision: digits must lie in 1..1000");
  if (!(start.d > 0)) throw std::invalid_argument("polish: packing has no positive d");
  const std::size_t n = start.size();
  bond_system::check_bonds(n, bonds);
  MultiprecisionPolish out;
  out.digits = digits;

  // Long double polish first: it brings the start to ~1e-19, two cheap steps from anything.
  long double L0 = 1.0L / start.d;
  std::vector<Vec2L> x0(n);
  for (std::size_t i = 0; i < n; ++i) x0[i] = start.points[i] * L0;
  const PolishReport rep = polish_bond_system_disk_units(x0, L0, bonds, rattlers);
  if (!rep.converged) {
    out.log10_max_residual = std::log10(static_cast<double>(rep.max_residual));
    return out;
  }

  // digits + 10 decimal digits of working precision: the residual floor stays 10^-10 below the
  // digits reported, leaving room for cond(J) in the error of the unknowns.
  const auto prec = static_cast<mpfr_prec_t>(std::ceil((digits + 10) * 3.3219280948873623)) + 8;
  const bond_system::Layout lay = bond_system::make_layout(n, rattlers);
  State s(n, prec), trial(n, prec);
  for (std::size_t i = 0; i < n; ++i) {
    mpfr_set_ld(s.x[i].get(), x0[i].x, kRnd);
    mpfr_set_ld(s.y[i].get(), x0[i].y, kRnd);
  }
  mpfr_set_ld(s.L.get(), L0, kRnd);

  Scratch w(prec);
  std::vector<Mp> r(bonds.size(), Mp(prec)), r_trial(bonds.size(), Mp(prec));
  Mp max_abs(prec), max_trial(prec), half(prec), tol(prec), target(prec), t(prec);
  residuals(bonds, s, w, r, max_abs);
  // Converged below 10^-(digits+3) L; iterate on towards 10^-(digits+8) L (cheap) so that the
  // digits reported are right even when the unknowns are a few orders worse than the residual.
  auto scaled_power = [&](Mp& v, int exponent10) {
    mpfr_set_si(v.get(), exponent10, kRnd);
    mpfr_exp10(v.get(), v.get(), kRnd);
    mpfr_mul(v.get(), v.get(), s.L.get(), kRnd);
  };
  scaled_power(target, -(digits + 8));

  Eigen::SPQR<bond_system::SpMat> qr;
  Eigen::VectorXd rd(static_cast<Eigen::Index>(bonds.size()));
  bool have_factor = false, fresh = false;
  // Each accepted step at least halves the residual, so this bound is never the binding one for
  // a healthy system; it only guards against a pathological slow crawl.
  const int max_iterations = 2 * (digits + 10) + 20;
  while (!bonds.empty() && mpfr_cmp(max_abs.get(), target.get()) > 0 &&
         out.iterations < max_iterations) {
    if (!have_factor) {
      factorize(qr, bonds, x0, lay);
      ++out.factorizations;
      have_factor = fresh = true;
    }
    const mpfr_exp_t e = scaled_residuals(r, max_abs, rd);
    const Eigen::VectorXd dz = qr.solve(rd);
    apply_step(s, trial, lay, dz, e, t);
    residuals(bonds, trial, w, r_trial, max_trial);
    ++out.iterations;
    mpfr_div_2ui(half.get(), max_abs.get(), 1, kRnd);
    const bool progress = mpfr_cmp(max_trial.get(), half.get()) < 0;
    if (mpfr_cmp(max_trial.get(), max_abs.get()) < 0) {
      std::swap(s, trial);
      std::swap(r, r_trial);
      std::swap(max_abs, max_trial);
      scaled_power(target, -(digits + 8));
    }
    if (!progress) {
      // A fresh factorization that cannot halve the residual: the floor, or no solution here.
      if (fresh) break;
      // Otherwise the factorization went stale (the state moved): refactor once at the state.
      factorize(qr, bonds, to_long_double(s), lay);
      ++out.factorizations;
      fresh = true;
      continue;
    }
    fresh = false;
  }

  scaled_power(tol, -(digits + 3));
  out.converged = mpfr_cmp(max_abs.get(), tol.get()) <= 0;
  scaled_power(t, -(digits + 10));
  mpfr_max(t.get(), t.get(), max_abs.get(), kRnd);
  mpfr_log10(t.get(), t.get(), kRnd);
  out.log10_max_residual = mpfr_get_d(t.get(), kRnd);
  if (!out.converged) return out;

  mpfr_ui_div(t.get(), 1, s.L.get(), kRnd);
  out.d = significant(t.get(), digits);
  out.L = significant(s.L.get(), digits);
  // Rattlers keep their start coordinates in the unit triangle, as in polish_bond_system.
  std::vector<char> is_rattler(n, 0);
  for (int i : rattlers) is_rattler[static_cast<std::size_t>(i)] = 1;
  out.points.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 2; ++c) {
      if (is_rattler[i]) {
        mpfr_set_ld(t.get(), c == 0 ? start.points[i].x : start.points[i].y, kRnd);
      } else {
        mpfr_div(t.get(), (c == 0 ? s.x[i] : s.y[i]).get(), s.L.get(), kRnd);
      }
      out.points[i][static_cast<std::size_t>(c)] = fixed(t.get(), digits);
    }
  }
  return out;
}

}  // namespace tripack

namespace tripack {

namespace {

// The constraints on a rattler's centre (px, py) in the unit triangle: each neighbour's distance
// minus d (constraint k >= 0) and the distance to each side (-1 floor, -2 left, -3 right); the
// clearance is their minimum.
struct Cage {
  std::vector<const Mp*> qx, qy;  // neighbour centres
  mpfr_prec_t prec;
  Mp d, root3, t, u, v, w;
  Cage(mpfr_prec_t p, const std::string& d_text) : prec(p), d(p), root3(p), t(p), u(p), v(p), w(p) {
    mpfr_set_str(d.get(), d_text.c_str(), 10, kRnd);
    mpfr_sqrt_ui(root3.get(), 3, kRnd);
  }
  // Constraint c's value at (px, py) into out.
  void value(int c, const Mp& px, const Mp& py, Mp& out) {
    if (c >= 0) {
      mpfr_sub(u.get(), px.get(), qx[static_cast<std::size_t>(c)]->get(), kRnd);
      mpfr_sub(v.get(), py.get(), qy[static_cast<std::size_t>(c)]->get(), kRnd);
      mpfr_hypot(out.get(), u.get(), v.get(), kRnd);
      mpfr_sub(out.get(), out.get(), d.get(), kRnd);
    } else if (c == -1) {
      mpfr_set(out.get(), py.get(), kRnd);
    } else {
      if (c == -2)
        mpfr_set(t.get(), px.get(), kRnd);
      else
        mpfr_ui_sub(t.get(), 1, px.get(), kRnd);
      mpfr_mul(t.get(), t.get(), root3.get(), kRnd);
      mpfr_sub(t.get(), t.get(), py.get(), kRnd);
      mpfr_div_ui(out.get(), t.get(), 2, kRnd);
    }
  }
  int constraints() const { return static_cast<int>(qx.size()); }
  void clearance(const Mp& px, const Mp& py, Mp& out) {
    mpfr_set_inf(out.get(), 1);
    for (int k = -3; k < constraints(); ++k) {
      value(k, px, py, w);
      mpfr_min(out.get(), out.get(), w.get(), kRnd);
    }
  }
  // Unit gradient of constraint c at (px, py), in double (a search direction only).
  std::pair<double, double> gradient(int c, const Mp& px, const Mp& py) {
    if (c == -1) return {0, 1};
    if (c == -2) return {std::sqrt(3.0) / 2, -0.5};
    if (c == -3) return {-std::sqrt(3.0) / 2, -0.5};
    const double gx =
        mpfr_get_d(px.get(), kRnd) - mpfr_get_d(qx[static_cast<std::size_t>(c)]->get(), kRnd);
    const double gy =
        mpfr_get_d(py.get(), kRnd) - mpfr_get_d(qy[static_cast<std::size_t>(c)]->get(), kRnd);
    const double g = std::hypot(gx, gy);
    return g > 0 ? std::pair{gx / g, gy / g} : std::pair{0.0, 0.0};
  }
};

}  // namespace

double centre_rattlers_multiprecision(MultiprecisionPolish& polish,
                                      const std::vector<int>& rattlers) {
  if (rattlers.empty() || !polish.converged) return std::numeric_limits<double>::infinity();
  const int digits = polish.digits;
  const auto prec = static_cast<mpfr_prec_t>(std::ceil((digits + 10) * 3.3219280948873623)) + 8;
  const std::size_t n = polish.points.size();
  std::vector<Mp> x(n, Mp(prec)), y(n, Mp(prec));
  std::vector<double> xd(n), yd(n);
  for (std::size_t i = 0; i < n; ++i) {
    mpfr_set_str(x[i].get(), polish.points[i][0].c_str(), 10, kRnd);
    mpfr_set_str(y[i].get(), polish.points[i][1].c_str(), 10, kRnd);
    xd[i] = mpfr_get_d(x[i].get(), kRnd);
    yd[i] = mpfr_get_d(y[i].get(), kRnd);
  }
  const double d_double = std::stod(polish.d);
  Mp floor_step(prec), h(prec), best(prec), trial_c(prec), tx(prec), ty(prec), band(prec), c(prec);
  mpfr_set_si(floor_step.get(), -(digits + 4), kRnd);
  mpfr_exp10(floor_step.get(), floor_step.get(), kRnd);
  double smallest = std::numeric_limits<double>::infinity();
  for (int r : rattlers) {
    const auto ri = static_cast<std::size_t>(r);
    Cage cage(prec, polish.d);
    for (std::size_t j = 0; j < n; ++j)
      if (j != ri && std::hypot(xd[j] - xd[ri], yd[j] - yd[ri]) < 2.5 * d_double) {
        cage.qx.push_back(&x[j]);
        cage.qy.push_back(&y[j]);
      }
    Mp& px = x[ri];
    Mp& py = y[ri];
    cage.clearance(px, py, best);
    mpfr_set_d(h.get(), 0.25 * d_double, kRnd);
    for (int moves = 0; mpfr_cmp(h.get(), floor_step.get()) > 0; ++moves) {
      // Directions: 8 fixed, the gradients of the constraints within 2h of the minimum, and the
      // bisectors of every pair of them (the ridge between two active constraints).
      std::vector<std::pair<double, double>> dirs{{1, 0},
                                                  {-1, 0},
                                                  {0, 1},
                                                  {0, -1},
                                                  {M_SQRT1_2, M_SQRT1_2},
                                                  {-M_SQRT1_2, M_SQRT1_2},
                                                  {M_SQRT1_2, -M_SQRT1_2},
                                                  {-M_SQRT1_2, -M_SQRT1_2}};
      mpfr_mul_2ui(band.get(), h.get(), 1, kRnd);
      mpfr_add(band.get(), band.get(), best.get(), kRnd);
      std::vector<std::pair<double, double>> active;
      for (int k = -3; k < cage.constraints(); ++k) {
        cage.value(k, px, py, c);
        if (mpfr_cmp(c.get(), band.get()) <= 0) active.push_back(cage.gradient(k, px, py));
      }
      for (std::size_t a = 0; a < active.size(); ++a) {
        dirs.push_back(active[a]);
        for (std::size_t b = a + 1; b < active.size(); ++b) {
          const double bx = active[a].first + active[b].first;
          const double by = active[a].second + active[b].second;
          const double g = std::hypot(bx, by);
          if (g > 1e-12) dirs.push_back({bx / g, by / g});
        }
      }
      bool moved = false;
      for (const auto& [dx, dy] : dirs) {
        mpfr_mul_d(tx.get(), h.get(), dx, kRnd);
        mpfr_add(tx.get(), tx.get(), px.get(), kRnd);
        mpfr_mul_d(ty.get(), h.get(), dy, kRnd);
        mpfr_add(ty.get(), ty.get(), py.get(), kRnd);
        cage.clearance(tx, ty, trial_c);
        if (mpfr_cmp(trial_c.get(), best.get()) > 0) {
          mpfr_swap(best.get(), trial_c.get());
          mpfr_set(px.get(), tx.get(), kRnd);
          mpfr_set(py.get(), ty.get(), kRnd);
          moved = true;
        }
      }
      if (!moved || moves == 64) {
        mpfr_div_2ui(h.get(), h.get(), 1, kRnd);
        moves = 0;
      }
    }
    smallest = std::min(smallest, mpfr_get_d(best.get(), kRnd) / d_double);
    polish.points[ri] = {fixed(px.get(), digits), fixed(py.get(), digits)};
  }
  return smallest;
}

std::string radius_or_side_from_d(const std::string& d, bool radius, int digits) {
  const auto prec = static_cast<mpfr_prec_t>(std::ceil((digits + 10) * 3.3219280948873623)) + 8;
  Mp dv(prec), root3(prec), t(prec);
  if (mpfr_set_str(dv.get(), d.c_str(), 10, kRnd) != 0)
    throw std::invalid_argument("not a decimal number: '" + d + "'");
  mpfr_sqrt_ui(root3.get(), 3, kRnd);
  if (radius) {  // r = d / (2 (1 + sqrt3 d))
    mpfr_mul(t.get(), root3.get(), dv.get(), kRnd);
    mpfr_add_ui(t.get(), t.get(), 1, kRnd);
    mpfr_mul_ui(t.get(), t.get(), 2, kRnd);
    mpfr_div(t.get(), dv.get(), t.get(), kRnd);
  } else {  // S = 2 / d + 2 sqrt3
    mpfr_ui_div(t.get(), 2, dv.get(), kRnd);
    mpfr_mul_ui(root3.get(), root3.get(), 2, kRnd);
    mpfr_add(t.get(), t.get(), root3.get(), kRnd);
  }
  return significant(t.get(), digits);
}

std::string oler_delta_from_L(const std::string& L, long long n) {
  const auto point = L.find('.');
  const int decimals = point == std::string::npos ? 0 : static_cast<int>(L.size() - point - 1);
  const int digits = decimals + static_cast<int>(point == std::string::npos ? L.size() : point);
  const auto prec = static_cast<mpfr_prec_t>(std::ceil((digits + 10) * 3.3219280948873623)) + 8;
  Mp Lv(prec), t(prec);
  if (mpfr_set_str(Lv.get(), L.c_str(), 10, kRnd) != 0)
    throw std::invalid_argument("not a decimal number: '" + L + "'");
  mpfr_set_si(t.get(), 8 * n + 1, kRnd);
  mpfr_sqrt(t.get(), t.get(), kRnd);
  mpfr_sub_ui(t.get(), t.get(), 3, kRnd);
  mpfr_div_ui(t.get(), t.get(), 2, kRnd);
  mpfr_sub(t.get(), Lv.get(), t.get(), kRnd);
  return fixed(t.get(), decimals);
}

}  // namespace tripack
