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

#include "core/neighbours.hpp"
#include "polish/bond_system.hpp"
#include "polish/polish.hpp"

namespace tripack {

namespace {

constexpr mpfr_rnd_t kRnd = MPFR_RNDN;

// An MPFR number that owns its storage and keeps its precision (the one it was created with, or
// the last reset) through assignments.
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
  // A new precision; the value is lost (NaN).
  void reset(mpfr_prec_t prec) { mpfr_set_prec(v_, prec); }
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

// The working precision in bits for `digits` significant digits: 10 guard digits and 8 bits.
mpfr_prec_t working_bits(int digits) {
  return static_cast<mpfr_prec_t>(std::ceil((digits + 10) * 3.3219280948873623)) + 8;
}

// v (nonzero) = m 2^e with 0.5 <= |m| < 1: e. A zero's is taken as -2^40, below every
// precision's resolution yet far from overflowing the exponent arithmetic below.
mpfr_exp_t exponent(mpfr_srcptr v) {
  return mpfr_zero_p(v) ? -(mpfr_exp_t{1} << 40) : mpfr_get_exp(v);
}

// Scratch numbers for residual evaluation: p bits for the results, `exact` bits for differences
// of coordinates (enough to hold them exactly; see state_bits).
struct Scratch {
  Mp h, t, u, n, dx, dy, term, nr;  // h = sqrt(3)/2
  mpfr_prec_t p = 0;
  Scratch(mpfr_prec_t bits, mpfr_prec_t exact)
      : h(bits), t(bits), u(bits), n(bits), dx(exact), dy(exact), term(64), nr(64) {
    set_prec(bits, exact);
  }
  void set_prec(mpfr_prec_t bits, mpfr_prec_t exact) {
    p = bits;
    for (Mp* m : {&h, &t, &u, &n}) m->reset(bits);
    dx.reset(exact);
    dy.reset(exact);
    mpfr_sqrt_ui(h.get(), 3, kRnd);
    mpfr_div_2ui(h.get(), h.get(), 1, kRnd);
  }
};

// The bits that hold every coordinate of s exactly, and their differences (Newton corrections
// end in fixed point, so the state's lowest bit only moves down by what each step adds).
mpfr_prec_t state_bits(const State& s) {
  mpfr_exp_t high = mpfr_get_exp(s.L.get()), low = high - 64;  // at least 64 bits
  auto see = [&](mpfr_srcptr v) {
    if (mpfr_zero_p(v)) return;
    high = std::max(high, mpfr_get_exp(v));
    low = std::min(low, mpfr_get_exp(v) - static_cast<mpfr_exp_t>(mpfr_min_prec(v)));
  };
  for (const Mp& v : s.x) see(v.get());
  for (const Mp& v : s.y) see(v.get());
  see(s.L.get());
  return static_cast<mpfr_prec_t>(high - low + 3);
}

// Residuals of all bond equations into r (at the scratch's p bits: to ~2^(l_exp - p) absolute,
// whatever the state's precision), their largest magnitude into max_abs. A pair bond's residual
// |a - b| - 1 is computed as sqrt(1 + N) - 1 with N = |a - b|^2 - 1, by the binomial series
// N/2 - N^2/8 + N^3/16 - ... whose k-th term is needed only to the bits it has above 2^-(p+8):
// near the solution (|N| below 2^-(p/2)) N/2 alone. So a residual costs two squares of numbers
// of the state's bits (about half of p), no square root at p bits.
void residuals(const std::vector<Bond>& bonds, const State& s, Scratch& w, std::vector<Mp>& r,
               Mp& max_abs) {
  mpfr_set_zero(max_abs.get(), 1);
  const auto p = static_cast<mpfr_exp_t>(w.p);
  for (std::size_t e = 0; e < bonds.size(); ++e) {
    const Bond& b = bonds[e];
    const auto a = static_cast<std::size_t>(b.a);
    mpfr_ptr out = r[e].get();
    if (!b.is_wall()) {
      const auto c = static_cast<std::size_t>(b.b);
      mpfr_sub(w.dx.get(), s.x[a].get(), s.x[c].get(), kRnd);
      mpfr_sub(w.dy.get(), s.y[a].get(), s.y[c].get(), kRnd);
      mpfr_sqr(w.t.get(), w.dx.get(), kRnd);
      mpfr_sqr(w.u.get(), w.dy.get(), kRnd);
      mpfr_add(w.n.get(), w.t.get(), w.u.get(), kRnd);
      mpfr_sub_ui(w.n.get(), w.n.get(), 1, kRnd);
      const mpfr_exp_t en = exponent(w.n.get());
      if (en > -8) {  // far from a solution: the square root itself
        mpfr_add_ui(w.t.get(), w.n.get(), 1, kRnd);
        mpfr_sqrt(w.t.get(), w.t.get(), kRnd);
        mpfr_sub_ui(out, w.t.get(), 1, kRnd);
      } else {
        mpfr_div_2ui(out, w.n.get(), 1, kRnd);
        // term k + 1 = term k * N (1 - 2k) / (2k + 2), term 1 = N/2; |term k| < 2^(k en).
        for (long k = 1;; ++k) {
          const mpfr_exp_t need = p + 8 + (k + 1) * en;
          if (need <= 0) break;
          const auto bits = static_cast<mpfr_prec_t>(std::max<mpfr_exp_t>(need, 32));
          if (k == 1) {
            w.term.reset(bits);
            mpfr_div_2ui(w.term.get(), w.n.get(), 1, kRnd);
          } else {
            mpfr_prec_round(w.term.get(), bits, kRnd);
          }
          w.nr.reset(bits);
          mpfr_set(w.nr.get(), w.n.get(), kRnd);
          mpfr_mul(w.term.get(), w.term.get(), w.nr.get(), kRnd);
          mpfr_mul_si(w.term.get(), w.term.get(), 1 - 2 * k, kRnd);
          mpfr_div_ui(w.term.get(), w.term.get(), static_cast<unsigned long>(2 * k + 2), kRnd);
          mpfr_add(out, out, w.term.get(), kRnd);
        }
      }
    } else {
      switch (b.side()) {
        case Side::Bottom:
          mpfr_set(out, s.y[a].get(), kRnd);
          break;
        case Side::Left:  // h x - y/2
          mpfr_set(w.dx.get(), s.x[a].get(), kRnd);
          mpfr_mul(w.t.get(), w.h.get(), w.dx.get(), kRnd);
          mpfr_div_2ui(w.u.get(), s.y[a].get(), 1, kRnd);
          mpfr_sub(out, w.t.get(), w.u.get(), kRnd);
          break;
        case Side::Right:  // h (L - x) - y/2
          mpfr_sub(w.dx.get(), s.L.get(), s.x[a].get(), kRnd);
          mpfr_mul(w.t.get(), w.h.get(), w.dx.get(), kRnd);
          mpfr_div_2ui(w.u.get(), s.y[a].get(), 1, kRnd);
          mpfr_sub(out, w.t.get(), w.u.get(), kRnd);
          break;
      }
    }
    if (mpfr_cmpabs(out, max_abs.get()) > 0) mpfr_abs(max_abs.get(), out, kRnd);
  }
}

// A GMP integer that owns its storage.
class Z {
 public:
  Z() { mpz_init(v_); }
  Z(const Z& o) { mpz_init_set(v_, o.v_); }
  Z(Z&& o) noexcept {
    mpz_init(v_);
    mpz_swap(v_, o.v_);
  }
  Z& operator=(const Z& o) {
    mpz_set(v_, o.v_);
    return *this;
  }
  Z& operator=(Z&& o) noexcept {
    mpz_swap(v_, o.v_);
    return *this;
  }
  ~Z() { mpz_clear(v_); }
  mpz_ptr get() { return v_; }
  mpz_srcptr get() const { return v_; }

 private:
  mpz_t v_;
};

// z = round(v 2^-unit) (to within one unit): v in fixed point with unit 2^unit.
void to_fixed(mpfr_srcptr v, mpfr_exp_t unit, Z& z) {
  if (mpfr_zero_p(v)) {
    mpz_set_ui(z.get(), 0);
    return;
  }
  const mpfr_exp_t e = mpfr_get_z_2exp(z.get(), v) - unit;  // v = z 2^(e + unit) exactly
  if (e >= 0)
    mpz_mul_2exp(z.get(), z.get(), static_cast<mp_bitcnt_t>(e));
  else
    mpz_fdiv_q_2exp(z.get(), z.get(), static_cast<mp_bitcnt_t>(-e));
}

// The Jacobian of the bond equations at a state, in fixed point, as terms: row e of J times a
// vector v is the sum over the row's terms of jv 2^-q (v[plus] - v[minus]) (a missing column
// counts as 0). A pair bond a-b has two, u_x (x_a - x_b) and u_y (y_a - y_b) with u the unit
// vector from b to a (a rattler's column missing); a wall bond the wall's normal on (x, y), and
// for the right side sqrt3/2 (L - x). The pattern is fixed, the values are recomputed at each
// Newton step to the precision that step needs (about half the working precision at the last).
struct FixedJacobian {
  struct Term {
    int plus = -1, minus = -1;
  };
  std::vector<int> row_start;  // terms of row e: row_start[e] .. row_start[e + 1] - 1
  std::vector<Term> terms;
  std::vector<Z> jv;
  mpfr_prec_t q = 0;

  FixedJacobian(const std::vector<Bond>& bonds, const bond_system::Layout& lay) {
    row_start.push_back(0);
    for (const Bond& b : bonds) {
      const int ca = lay.column[static_cast<std::size_t>(b.a)];
      auto column = [](int c, int offset) { return c < 0 ? -1 : c + offset; };
      if (b.is_wall()) {
        switch (b.side()) {
          case Side::Bottom:  // y
            if (ca >= 0) terms.push_back({ca + 1, -1});
            break;
          case Side::Left:  // h x - y/2
            if (ca >= 0) terms.insert(terms.end(), {{ca, -1}, {ca + 1, -1}});
            break;
          case Side::Right:  // h (L - x) - y/2
            terms.push_back({lay.l_column, column(ca, 0)});
            if (ca >= 0) terms.push_back({ca + 1, -1});
            break;
        }
      } else {
        const int cb = lay.column[static_cast<std::size_t>(b.b)];
        if (ca >= 0 || cb >= 0)
          terms.insert(terms.end(),
                       {{column(ca, 0), column(cb, 0)}, {column(ca, 1), column(cb, 1)}});
      }
      row_start.push_back(static_cast<int>(terms.size()));
    }
    jv.resize(terms.size());
  }

  // The values at state s, whose residuals r are below 2^e, to 2^-bits. A pair bond's length is
  // 1 + r_e, so u = (a - b) / (1 + r_e) = (a - b)(1 - r_e + r_e^2) to 2^(3e): no square root and
  // no division at `bits` bits, only products by r_e - r_e^2 at the few bits it has beyond 2^e.
  void evaluate(const std::vector<Bond>& bonds, const State& s, const std::vector<Mp>& r,
                mpfr_exp_t e, mpfr_prec_t bits) {
    q = bits;
    const auto small = static_cast<mpfr_prec_t>(std::max<mpfr_exp_t>(64, bits + e + 16));
    Mp h(bits + 8), d(bits + 8), f(small), g(small);
    mpfr_sqrt_ui(h.get(), 3, kRnd);
    mpfr_div_2ui(h.get(), h.get(), 1, kRnd);
    const auto unit = static_cast<mpfr_exp_t>(-bits);
    Z h_fixed, half;
    to_fixed(h.get(), unit, h_fixed);
    mpz_set_ui(half.get(), 1);
    mpz_mul_2exp(half.get(), half.get(), static_cast<mp_bitcnt_t>(bits - 1));
    for (std::size_t k = 0; k < bonds.size(); ++k) {
      const Bond& b = bonds[k];
      const auto i = static_cast<std::size_t>(row_start[k]);
      if (i == static_cast<std::size_t>(row_start[k + 1])) continue;
      const auto a = static_cast<std::size_t>(b.a);
      if (b.is_wall()) {
        switch (b.side()) {
          case Side::Bottom:  // y
            mpz_mul_2exp(jv[i].get(), half.get(), 1);
            break;
          case Side::Left:  // h x - y/2
            mpz_set(jv[i].get(), h_fixed.get());
            mpz_neg(jv[i + 1].get(), half.get());
            break;
          case Side::Right:  // h (L - x) - y/2
            mpz_set(jv[i].get(), h_fixed.get());
            if (i + 1 < static_cast<std::size_t>(row_start[k + 1]))
              mpz_neg(jv[i + 1].get(), half.get());
            break;
        }
        continue;
      }
      const auto c = static_cast<std::size_t>(b.b);
      mpfr_sqr(f.get(), r[k].get(), kRnd);
      mpfr_sub(f.get(), r[k].get(), f.get(), kRnd);  // f = r_e - r_e^2
      for (std::size_t axis = 0; axis < 2; ++axis) {
        const auto& coordinate = axis == 0 ? s.x : s.y;
        mpfr_sub(d.get(), coordinate[a].get(), coordinate[c].get(), kRnd);
        mpfr_mul(g.get(), d.get(), f.get(), kRnd);
        mpfr_sub(d.get(), d.get(), g.get(), kRnd);
        to_fixed(d.get(), unit, jv[i + axis]);
      }
    }
  }
};

// v 2^pos added to the non-negative number held in `limbs` (least significant first, wide enough
// for every sum it will hold): an O(1) update whatever the width, carries aside.
void add_at(std::vector<mp_limb_t>& limbs, unsigned long v, mpfr_exp_t pos) {
  static_assert(sizeof(mp_limb_t) == 8 && GMP_NUMB_BITS == 64, "64-bit limbs");
  auto i = static_cast<std::size_t>(pos / 64);
  const auto shift = static_cast<unsigned>(pos % 64);
  const mp_limb_t parts[2] = {v << shift, shift ? v >> (64 - shift) : 0};
  mp_limb_t carry = 0;
  for (int p = 0; p < 2 || carry; ++p, ++i) {
    if (i >= limbs.size()) throw std::logic_error("polish_multiprecision: correction overflow");
    const mp_limb_t add = (p < 2 ? parts[p] : 0);
    const mp_limb_t old = limbs[i];
    limbs[i] = old + add + carry;
    carry = (limbs[i] < old || (carry && limbs[i] == old)) ? 1 : 0;
  }
}

// The integer held in `limbs` (a read-only view of them, normalized).
void view_of(const std::vector<mp_limb_t>& limbs, mpz_t view) {
  auto size = static_cast<mp_size_t>(limbs.size());
  while (size > 0 && limbs[static_cast<std::size_t>(size - 1)] == 0) --size;
  mpz_roinit_n(view, limbs.data(), size);
}

// Solves J dz = r in the least-squares sense to an absolute accuracy of about 2^tau by iterative
// refinement with the double factorization qr of (a double rounding of) J. Each sweep solves for
// the correction of the current linear residual rs = r - J dz in double and subtracts J times it.
// All of it in fixed point with unit 2^(tau - 64): the correction is a vector of 62-bit integers
// times a power of two, so a sweep costs one multiply-add of a 64-bit word into each nonzero of J
// (truncated to the bits above the unit) - linear in the precision and shrinking as rs shrinks,
// where a residual evaluation takes square roots at full precision. It gains
// log10(1 / (cond(J) 1e-16)) digits (~14 for these systems), `gain` bits as last seen (0 before
// any: updated here). Stops when what is left, the last correction less `gain` bits, is below
// 2^tau, or when a correction would not halve the last (the least-squares residual of an
// over-determined system, or the double factorization's limit for an ill-conditioned one): that
// one is dropped. dz is set exactly (its precision as needed). Returns the sweeps applied.
int refine(const FixedJacobian& J, const Eigen::SPQR<bond_system::SpMat>& qr,
           const std::vector<Mp>& r, mpfr_exp_t tau, std::vector<Mp>& dz, Eigen::VectorXd& rd,
           int max_sweeps, mpfr_exp_t& gain) {
  const mpfr_exp_t unit = tau - 64;
  const std::size_t m = r.size(), unknowns = dz.size();
  std::vector<Z> rs(m);
  for (std::size_t e = 0; e < m; ++e) to_fixed(r[e].get(), unit, rs[e]);
  // dz = (plus - minus) 2^unit, each a fixed-width limb array sized at the first correction.
  std::vector<std::vector<mp_limb_t>> plus(unknowns), minus(unknowns);
  std::vector<long> ci(unknowns);
  Z acc;
  mpz_t view;
  mpfr_exp_t last = 0;  // exponent of the last correction
  int sweeps = 0;
  while (sweeps < max_sweeps) {
    // The linear residual scaled by 2^-es into double (at 10^-300 and below double would
    // underflow); the scale is undone exactly below.
    mpfr_exp_t es = 0;
    bool any = false;
    for (const Z& z : rs)
      if (mpz_sgn(z.get()) != 0) {
        const auto top = static_cast<mpfr_exp_t>(mpz_sizeinbase(z.get(), 2)) + unit;
        es = any ? std::max(es, top) : top;
        any = true;
      }
    if (!any) break;
    for (std::size_t e = 0; e < m; ++e) {
      long ex = 0;
      const double mant = mpz_get_d_2exp(&ex, rs[e].get());
      rd[static_cast<Eigen::Index>(e)] =
          mant == 0
              ? 0
              : std::ldexp(mant, static_cast<int>(std::max<mpfr_exp_t>(ex + unit - es, -2000)));
    }
    const Eigen::VectorXd c = qr.solve(rd);
    const double cmax = c.cwiseAbs().maxCoeff();
    if (!(cmax > 0) || !std::isfinite(cmax)) break;
    int cexp = 0;
    std::frexp(cmax, &cexp);
    const mpfr_exp_t correction = cexp + es;      // the correction is below 2^correction
    if (sweeps > 0 && correction >= last) break;  // not halving: dropped
    if (sweeps > 0) gain = last - correction;
    // The correction c 2^es = ci 2^ce with |ci| <= 2^61 (so a difference of two fits a long).
    const mpfr_exp_t ce = correction - 61;
    for (std::size_t k = 0; k < unknowns; ++k)
      ci[k] = std::lround(std::ldexp(c[static_cast<Eigen::Index>(k)], 61 - cexp));
    if (sweeps == 0) {  // corrections halve from here on: their sum stays below 2^(correction+1)
      const auto limbs =
          static_cast<std::size_t>(std::max<mpfr_exp_t>(correction + 2 - unit, 1)) / 64 + 2;
      for (std::size_t k = 0; k < unknowns; ++k) {
        plus[k].assign(limbs, 0);
        minus[k].assign(limbs, 0);
      }
    }
    for (std::size_t k = 0; k < unknowns; ++k) {
      if (ci[k] == 0) continue;
      unsigned long v = static_cast<unsigned long>(ci[k] < 0 ? -ci[k] : ci[k]);
      mpfr_exp_t pos = ce - unit;
      if (pos < 0) {  // below the unit: truncated
        v = -pos >= 64 ? 0 : v >> -pos;
        pos = 0;
      }
      if (v) add_at(ci[k] < 0 ? minus[k] : plus[k], v, pos);
    }
    // rs -= J ci 2^ce. jv (ci[plus] - ci[minus]) 2^(ce - q) is needed to 2^unit only: the limbs
    // of jv below 2^(unit - ce + q - 62) are left out (each product's error stays below one unit).
    const mpfr_exp_t skip_bits = unit - ce + J.q - 62;
    const mp_size_t skip = skip_bits > 0 ? static_cast<mp_size_t>(skip_bits / 64) : 0;
    const mpfr_exp_t shift = ce - J.q + 64 * static_cast<mpfr_exp_t>(skip) - unit;
    for (std::size_t e = 0; e < m; ++e) {
      const int begin = J.row_start[e], end = J.row_start[e + 1];
      mpz_set_ui(acc.get(), 0);
      for (int i = begin; i < end; ++i) {
        const auto& term = J.terms[static_cast<std::size_t>(i)];
        const long cv = (term.plus >= 0 ? ci[static_cast<std::size_t>(term.plus)] : 0) -
                        (term.minus >= 0 ? ci[static_cast<std::size_t>(term.minus)] : 0);
        if (cv == 0) continue;
        const mpz_srcptr j = J.jv[static_cast<std::size_t>(i)].get();
        const auto size = static_cast<mp_size_t>(mpz_size(j));
        if (size <= skip) continue;
        mpz_roinit_n(view, mpz_limbs_read(j) + skip, mpz_sgn(j) < 0 ? skip - size : size - skip);
        if (cv > 0)
          mpz_addmul_ui(acc.get(), view, static_cast<unsigned long>(cv));
        else
          mpz_submul_ui(acc.get(), view, static_cast<unsigned long>(-cv));
      }
      if (mpz_sgn(acc.get()) == 0) continue;
      if (shift >= 0)
        mpz_mul_2exp(acc.get(), acc.get(), static_cast<mp_bitcnt_t>(shift));
      else
        mpz_tdiv_q_2exp(acc.get(), acc.get(), static_cast<mp_bitcnt_t>(-shift));
      mpz_sub(rs[e].get(), rs[e].get(), acc.get());
    }
    ++sweeps;
    last = correction;
    // Done when what is left, the next correction (this one times the last gain), is below
    // 2^tau: one sweep fewer than waiting for a correction below 2^tau.
    if (correction - gain <= tau) break;
  }
  mpz_t p, n;
  for (std::size_t k = 0; k < unknowns; ++k) {
    if (sweeps == 0) {
      dz[k].reset(MPFR_PREC_MIN);
      mpfr_set_zero(dz[k].get(), 1);
      continue;
    }
    view_of(plus[k], p);
    view_of(minus[k], n);
    mpz_sub(acc.get(), p, n);
    const auto bits = static_cast<mpfr_prec_t>(mpz_sizeinbase(acc.get(), 2));
    dz[k].reset(std::max<mpfr_prec_t>(bits, MPFR_PREC_MIN));
    mpfr_set_z_2exp(dz[k].get(), acc.get(), unit, kRnd);  // exact
  }
  return sweeps;
}

void factorize(Eigen::SPQR<bond_system::SpMat>& qr, const std::vector<Bond>& bonds,
               const std::vector<Vec2L>& x, const bond_system::Layout& lay) {
  const bond_system::SpMat J = bond_system::jacobian(bonds, x, lay);
  qr.compute(J);
  if (qr.info() != Eigen::Success) throw std::runtime_error("polish_multiprecision: QR failed");
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

// trial = s - dz on the unknowns; rattlers are copied unchanged.
void newton_trial(State& trial, const State& s, const std::vector<Mp>& dz,
                  const bond_system::Layout& lay) {
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const int c = lay.column[i];
    if (c < 0) {
      mpfr_set(trial.x[i].get(), s.x[i].get(), kRnd);
      mpfr_set(trial.y[i].get(), s.y[i].get(), kRnd);
      continue;
    }
    mpfr_sub(trial.x[i].get(), s.x[i].get(), dz[static_cast<std::size_t>(c)].get(), kRnd);
    mpfr_sub(trial.y[i].get(), s.y[i].get(), dz[static_cast<std::size_t>(c) + 1].get(), kRnd);
  }
  mpfr_sub(trial.L.get(), s.L.get(), dz[static_cast<std::size_t>(lay.l_column)].get(), kRnd);
}

// The converged state into out: d and L to `digits` significant digits, the centres in the unit
// triangle with `digits` decimals.
void write_solution(MultiprecisionPolish& out, const State& s, const Packing& start,
                    const std::vector<int>& rattlers, int digits, mpfr_prec_t prec) {
  const std::size_t n = s.x.size();
  Mp d(prec), t(prec);
  mpfr_ui_div(d.get(), 1, s.L.get(), kRnd);
  out.d = significant(d.get(), digits);
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
        // x d rather than x / L: a product costs a third of a quotient, and the 10 guard digits
        // absorb the extra rounding.
        mpfr_mul(t.get(), (c == 0 ? s.x[i] : s.y[i]).get(), d.get(), kRnd);
      }
      out.points[i][static_cast<std::size_t>(c)] = fixed(t.get(), digits);
    }
  }
}

}  // namespace

MultiprecisionPolish polish_multiprecision(const Packing& start, const std::vector<Bond>& bonds,
                                           const std::vector<int>& rattlers, int digits) {
  if (digits < 1 || digits > kMaxMultiprecisionDigits)
    throw std::invalid_argument("polish_multiprecision: digits must lie in 1.." +
                                std::to_string(kMaxMultiprecisionDigits));
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
  // digits reported, leaving room for cond(J) in the error of the unknowns. The state is kept at
  // that precision throughout; residuals, the Jacobian and the linear solves are computed at the
  // precision each Newton step needs.
  const mpfr_prec_t prec = working_bits(digits);
  const bond_system::Layout lay = bond_system::make_layout(n, rattlers);
  State s(n, prec), trial(n, prec);
  for (std::size_t i = 0; i < n; ++i) {
    mpfr_set_ld(s.x[i].get(), x0[i].x, kRnd);
    mpfr_set_ld(s.y[i].get(), x0[i].y, kRnd);
  }
  mpfr_set_ld(s.L.get(), L0, kRnd);
  // Coordinates are below L = 2^l_exp in magnitude: p bits give residuals to 2^(l_exp - p).
  const mpfr_exp_t l_exp = mpfr_get_exp(s.L.get());
  // The precision whose residuals are accurate enough for the Newton step after one that starts
  // from a residual ~2^e: that step ends near 2^(2e), the next aims at 2^(4e) and needs its
  // right-hand side to 2^(4e - 24).
  auto residual_bits = [&](mpfr_exp_t e) {
    return static_cast<mpfr_prec_t>(std::clamp<mpfr_exp_t>(l_exp - 4 * e + 24, 64, prec));
  };

  // Differences of coordinates exactly (see state_bits), or to 2^-(p+7) when that is fewer bits.
  auto difference_bits = [&](const State& st, mpfr_prec_t p) {
    return std::min(state_bits(st),
                    p + static_cast<mpfr_prec_t>(std::max<mpfr_exp_t>(l_exp, 0)) + 8);
  };

  mpfr_prec_t r_bits = residual_bits(-64);  // the long double start: ~2^-63
  Scratch w(r_bits, difference_bits(s, r_bits));
  std::vector<Mp> r(bonds.size(), Mp(r_bits)), r_trial(bonds.size(), Mp(r_bits));
  // Magnitudes and thresholds to 64 bits: only compared (exp10 and log10 at the working
  // precision would cost more than a Newton step).
  Mp max_abs(64), max_trial(64), tol(64), target(64), small(64);
  residuals(bonds, s, w, r, max_abs);
  // Converged below 10^-(digits+3) L; iterate on towards 10^-(digits+8) L (cheap) so that the
  // digits reported are right even when the unknowns are a few orders worse than the residual.
  auto scaled_power = [&](Mp& v, int exponent10) {
    mpfr_set_si(v.get(), exponent10, kRnd);
    mpfr_exp10(v.get(), v.get(), kRnd);
    mpfr_mul(v.get(), v.get(), s.L.get(), kRnd);
  };
  scaled_power(target, -(digits + 8));
  auto residuals_at_working_precision = [&] {
    w.set_prec(prec, difference_bits(s, prec));
    for (Mp& v : r) v.reset(prec);
    residuals(bonds, s, w, r, max_abs);
  };

  Eigen::SPQR<bond_system::SpMat> qr;
  FixedJacobian J(bonds, lay);
  mpfr_exp_t gain = 0;  // bits gained by a refinement sweep, as last seen (none yet)
  std::vector<Mp> dz(static_cast<std::size_t>(lay.unknowns), Mp(64));
  Eigen::VectorXd rd(static_cast<Eigen::Index>(bonds.size()));
  // Each accepted step at least halves the residual, so this bound is never the binding one for
  // a healthy system; it only guards against a pathological slow crawl.
  const int max_iterations = 2 * (digits + 10) + 20;
  while (!bonds.empty() && out.iterations < max_iterations) {
    if (mpfr_cmp(max_abs.get(), target.get()) <= 0) {
      if (r_bits == prec) break;
      // Below the target at a precision too low to tell: evaluate at the working precision.
      r_bits = prec;
      residuals_at_working_precision();
      continue;
    }
    if (out.factorizations == 0) {
      // The double Jacobian at the long double solution: within 1e-18 of J at the MPFR one,
      // below double's resolution, so it is never refactorized.
      factorize(qr, bonds, x0, lay);
      ++out.factorizations;
    }
    // Newton from a residual ~2^e: the step should end near 2^(2e), so it is solved to 2^tau,
    // 16 bits below that (or the residuals' own accuracy, or the working precision's floor).
    const mpfr_exp_t e = exponent(max_abs.get());
    const mpfr_exp_t tau = std::max({2 * e - 16, l_exp - r_bits + 8, l_exp - prec + 8});
    // The Jacobian, the correction and the linear residual are needed to 2^tau relative to a
    // residual ~2^e, with 40 bits of room for cond(J).
    const auto q = static_cast<mpfr_prec_t>(std::clamp<mpfr_exp_t>(e - tau + 40, 64, prec));
    J.evaluate(bonds, s, r, e, q);
    out.sweeps += refine(J, qr, r, tau, dz, rd, static_cast<int>(e - tau) + 20, gain);
    newton_trial(trial, s, dz, lay);
    const mpfr_prec_t next_bits = residual_bits(e);
    w.set_prec(next_bits, difference_bits(trial, next_bits));
    for (Mp& v : r_trial) v.reset(next_bits);
    residuals(bonds, trial, w, r_trial, max_trial);
    ++out.iterations;
    // A step that cannot halve the residual: its floor, or no solution here.
    mpfr_mul_2si(small.get(), max_trial.get(), 1, kRnd);
    const bool progress = mpfr_cmp(small.get(), max_abs.get()) < 0;
    if (mpfr_cmp(max_trial.get(), max_abs.get()) < 0) {
      std::swap(s, trial);
      std::swap(r, r_trial);
      std::swap(max_abs, max_trial);
      r_bits = next_bits;
      scaled_power(target, -(digits + 8));
    }
    if (!progress) break;
  }
  // Stopped early: the verdict at the working precision.
  if (!bonds.empty() && r_bits < prec) residuals_at_working_precision();

  scaled_power(tol, -(digits + 3));
  out.converged = mpfr_cmp(max_abs.get(), tol.get()) <= 0;
  scaled_power(small, -(digits + 10));
  mpfr_max(small.get(), small.get(), max_abs.get(), kRnd);
  mpfr_log10(small.get(), small.get(), kRnd);
  out.log10_max_residual = mpfr_get_d(small.get(), kRnd);
  if (out.converged) write_solution(out, s, start, rattlers, digits, prec);
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
  const mpfr_prec_t prec = working_bits(digits);
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
  const mpfr_prec_t prec = working_bits(digits);
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
  const mpfr_prec_t prec = working_bits(digits);
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

namespace tripack {

namespace {

// A converged polish read back at its working precision: every centre and d, in the unit
// triangle, plus sqrt(3)/2 for the walls.
struct ReadBack {
  mpfr_prec_t prec;
  std::vector<Mp> x, y;
  Mp d, h;
  std::vector<Vec2L> rounded;  // each coordinate rounded to long double
  explicit ReadBack(const MultiprecisionPolish& polish)
      : prec(working_bits(polish.digits)), d(prec), h(prec) {
    if (!polish.converged)
      throw std::invalid_argument("multiprecision evaluation of a polish that did not converge");
    const std::size_t n = polish.points.size();
    x.assign(n, Mp(prec));
    y.assign(n, Mp(prec));
    rounded.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      mpfr_set_str(x[i].get(), polish.points[i][0].c_str(), 10, kRnd);
      mpfr_set_str(y[i].get(), polish.points[i][1].c_str(), 10, kRnd);
      rounded[i] = {mpfr_get_ld(x[i].get(), kRnd), mpfr_get_ld(y[i].get(), kRnd)};
    }
    mpfr_set_str(d.get(), polish.d.c_str(), 10, kRnd);
    mpfr_sqrt_ui(h.get(), 3, kRnd);
    mpfr_div_2ui(h.get(), h.get(), 1, kRnd);
  }
  // Signed distance of centre i to side s into out (unit triangle).
  void wall(std::size_t i, Side s, Mp& out, Mp& t) const {
    switch (s) {
      case Side::Bottom:
        mpfr_set(out.get(), y[i].get(), kRnd);
        return;
      case Side::Left:  // h x - y/2
        mpfr_mul(out.get(), h.get(), x[i].get(), kRnd);
        break;
      case Side::Right:  // h (1 - x) - y/2
        mpfr_ui_sub(t.get(), 1, x[i].get(), kRnd);
        mpfr_mul(out.get(), h.get(), t.get(), kRnd);
        break;
    }
    mpfr_div_2ui(t.get(), y[i].get(), 1, kRnd);
    mpfr_sub(out.get(), out.get(), t.get(), kRnd);
  }
  // Centre a minus centre c into (dx, dy), its length into length.
  void difference(std::size_t a, std::size_t c, Mp& dx, Mp& dy, Mp& length) const {
    mpfr_sub(dx.get(), x[a].get(), x[c].get(), kRnd);
    mpfr_sub(dy.get(), y[a].get(), y[c].get(), kRnd);
    mpfr_hypot(length.get(), dx.get(), dy.get(), kRnd);
  }
  // Gap of bond b in units of d into out.
  void gap(const Bond& b, Mp& out, Mp& t, Mp& u) const {
    const auto a = static_cast<std::size_t>(b.a);
    if (b.is_wall()) {
      wall(a, b.side(), out, t);
    } else {
      difference(a, static_cast<std::size_t>(b.b), t, u, out);
      mpfr_sub(out.get(), out.get(), d.get(), kRnd);
    }
    mpfr_div(out.get(), out.get(), d.get(), kRnd);
  }
  // Unit direction of bond b (pair: from b.b to b.a; wall: inward normal) into (ux, uy).
  void direction(const Bond& b, Mp& ux, Mp& uy, Mp& t) const {
    const auto a = static_cast<std::size_t>(b.a);
    if (b.is_wall()) {
      switch (b.side()) {
        case Side::Bottom:
          mpfr_set_zero(ux.get(), 1);
          mpfr_set_ui(uy.get(), 1, kRnd);
          return;
        case Side::Left:
          mpfr_set(ux.get(), h.get(), kRnd);
          break;
        case Side::Right:
          mpfr_neg(ux.get(), h.get(), kRnd);
          break;
      }
      mpfr_set_si_2exp(uy.get(), -1, -1, kRnd);
      return;
    }
    difference(a, static_cast<std::size_t>(b.b), ux, uy, t);
    mpfr_div(ux.get(), ux.get(), t.get(), kRnd);
    mpfr_div(uy.get(), uy.get(), t.get(), kRnd);
  }
};

}  // namespace

PreciseGaps precise_gaps(const MultiprecisionPolish& polish, const std::vector<Bond>& bonds,
                         const std::vector<int>& rattlers) {
  const ReadBack s(polish);
  const std::size_t n = s.x.size();
  std::vector<Bond> sorted = bonds;
  std::sort(sorted.begin(), sorted.end());
  std::vector<char> loose(n, 1);  // a rattler, or a disk without bonds
  for (const Bond& b : sorted) {
    loose[static_cast<std::size_t>(b.a)] = 0;
    if (!b.is_wall()) loose[static_cast<std::size_t>(b.b)] = 0;
  }
  for (int r : rattlers) loose[static_cast<std::size_t>(r)] = 1;
  PreciseGaps out;
  Mp g(s.prec), t(s.prec), u(s.prec);
  auto visit = [&](const Bond& b, bool near_loose) {
    s.gap(b, g, t, u);
    const long double v = mpfr_get_ld(g.get(), kRnd);
    if (std::binary_search(sorted.begin(), sorted.end(), b))
      out.bond_floor = std::max(out.bond_floor, std::fabs(v));
    else
      out.gaps.push_back({b, v, near_loose});
  };
  long double d = mpfr_get_ld(s.d.get(), kRnd);
  for_each_pair_within(s.rounded, d * 1.25L, [&](int i, int j, long double) {
    visit(Bond::pair(i, j),
          loose[static_cast<std::size_t>(i)] || loose[static_cast<std::size_t>(j)]);
  });
  for (std::size_t i = 0; i < n; ++i)
    for (Side side : kSides)
      if (wall_distance(s.rounded[i], side, 1.0L) < 0.25L * d)
        visit(Bond::wall(static_cast<int>(i), side), loose[i]);
  // Bonds farther apart than the neighbour search reaches (a polish that moved far) still count.
  for (const Bond& b : sorted) {
    s.gap(b, g, t, u);
    out.bond_floor = std::max(out.bond_floor, std::fabs(mpfr_get_ld(g.get(), kRnd)));
  }
  std::sort(out.gaps.begin(), out.gaps.end(),
            [](const PreciseGap& a, const PreciseGap& b) { return a.gap < b.gap; });
  return out;
}

Packing rounded_packing(const MultiprecisionPolish& polish) {
  const ReadBack s(polish);
  return {s.rounded, mpfr_get_ld(s.d.get(), kRnd)};
}

std::vector<Vec2L> precise_directions(const MultiprecisionPolish& polish,
                                      const std::vector<Bond>& bonds) {
  const ReadBack s(polish);
  Mp ux(s.prec), uy(s.prec), t(s.prec);
  std::vector<Vec2L> out;
  out.reserve(bonds.size());
  for (const Bond& b : bonds) {
    s.direction(b, ux, uy, t);
    out.push_back({mpfr_get_ld(ux.get(), kRnd), mpfr_get_ld(uy.get(), kRnd)});
  }
  return out;
}

PreciseBalance balance_multiprecision(
    const MultiprecisionPolish& polish, const std::vector<Bond>& bonds,
    const std::vector<int>& rattlers, const std::vector<long double>& forces,
    const std::vector<long double>& weights,
    const std::function<std::vector<long double>(const std::vector<long double>&)>& solve) {
  const ReadBack s(polish);
  const std::size_t n = s.x.size(), m = bonds.size();
  if (forces.size() != m || (!weights.empty() && weights.size() != m))
    throw std::invalid_argument("balance_multiprecision: one force and weight per bond");
  std::vector<int> col(n, 0);
  for (int r : rattlers) col[static_cast<std::size_t>(r)] = -1;
  int columns = 0;
  for (auto& c : col)
    if (c == 0) {
      c = columns;
      columns += 2;
    }
  // The directions and the forces at the working precision.
  std::vector<Mp> ux(m, Mp(s.prec)), uy(m, Mp(s.prec)), f(m, Mp(s.prec)), w(m, Mp(s.prec));
  Mp t(s.prec), v(s.prec), pair_sum(s.prec);
  for (std::size_t e = 0; e < m; ++e) {
    s.direction(bonds[e], ux[e], uy[e], t);
    mpfr_set_ld(f[e].get(), forces[e], kRnd);
    mpfr_set_ld(w[e].get(), weights.empty() ? 1.0L : weights[e], kRnd);
  }
  std::vector<Mp> r(static_cast<std::size_t>(columns), Mp(s.prec));
  std::vector<long double> rl(static_cast<std::size_t>(columns));
  auto column = [&](int disk) { return col[static_cast<std::size_t>(disk)]; };
  // r = G^T f (the net force on every non-rattler); returns max |r|.
  auto net = [&]() {
    for (Mp& c : r) mpfr_set_zero(c.get(), 1);
    for (std::size_t e = 0; e < m; ++e) {
      const Bond& b = bonds[e];
      for (int side = 0; side < 2; ++side) {
        const int disk = side == 0 ? b.a : b.b;
        if (disk < 0) continue;
        const int c = column(disk);
        if (c < 0) continue;
        const auto cu = static_cast<std::size_t>(c);
        mpfr_mul(t.get(), f[e].get(), ux[e].get(), kRnd);
        (side == 0 ? mpfr_add : mpfr_sub)(r[cu].get(), r[cu].get(), t.get(), kRnd);
        mpfr_mul(t.get(), f[e].get(), uy[e].get(), kRnd);
        (side == 0 ? mpfr_add : mpfr_sub)(r[cu + 1].get(), r[cu + 1].get(), t.get(), kRnd);
      }
    }
    long double largest = 0;
    for (std::size_t c = 0; c < r.size(); ++c) {
      rl[c] = mpfr_get_ld(r[c].get(), kRnd);
      largest = std::max(largest, std::fabs(rl[c]));
    }
    return largest;
  };
  // The pair forces' sum, for the scale of the residual (forces are compared after scaling).
  auto pair_total = [&]() {
    mpfr_set_zero(pair_sum.get(), 1);
    for (std::size_t e = 0; e < m; ++e)
      if (!bonds[e].is_wall()) mpfr_add(pair_sum.get(), pair_sum.get(), f[e].get(), kRnd);
    return mpfr_get_ld(pair_sum.get(), kRnd);
  };
  PreciseBalance out;
  long double total = pair_total();
  if (!(total > 0)) throw std::invalid_argument("balance_multiprecision: no positive pair force");
  long double residual = net();
  out.start_residual = residual / total;
  // The floor: the working precision's resolution of forces of size ~1 (digits + 10 decimal
  // digits are carried; the directions are exact to about 10^-digits).
  const long double floor = std::pow(10.0L, -static_cast<long double>(polish.digits));
  const int max_sweeps = 4 * (polish.digits + 10) + 20;
  while (out.sweeps < max_sweeps && residual / total > floor) {
    const std::vector<long double> yv = solve(rl);
    if (yv.size() != rl.size()) throw std::logic_error("balance_multiprecision: bad solve size");
    // f -= W G y: row e of G y is u_e . (y_a - y_b) (a wall's: n . y_a), in MPFR.
    for (std::size_t e = 0; e < m; ++e) {
      const Bond& b = bonds[e];
      const int ca = column(b.a), cb = b.is_wall() ? -1 : column(b.b);
      if (ca < 0 && cb < 0) continue;
      mpfr_set_zero(v.get(), 1);
      for (int side = 0; side < 2; ++side) {
        const int c = side == 0 ? ca : cb;
        if (c < 0) continue;
        const auto cu = static_cast<std::size_t>(c);
        mpfr_set_ld(t.get(), yv[cu], kRnd);
        mpfr_mul(t.get(), t.get(), ux[e].get(), kRnd);
        (side == 0 ? mpfr_add : mpfr_sub)(v.get(), v.get(), t.get(), kRnd);
        mpfr_set_ld(t.get(), yv[cu + 1], kRnd);
        mpfr_mul(t.get(), t.get(), uy[e].get(), kRnd);
        (side == 0 ? mpfr_add : mpfr_sub)(v.get(), v.get(), t.get(), kRnd);
      }
      mpfr_mul(v.get(), v.get(), w[e].get(), kRnd);
      mpfr_sub(f[e].get(), f[e].get(), v.get(), kRnd);
    }
    ++out.sweeps;
    const long double next = net();
    if (!(next < residual / 2)) {  // no longer halving: the floor of this solve
      residual = next;
      break;
    }
    residual = next;
  }
  // Pair forces summing to 1.
  total = pair_total();
  out.forces.resize(m);
  for (std::size_t e = 0; e < m; ++e) {
    mpfr_div(f[e].get(), f[e].get(), pair_sum.get(), kRnd);
    out.forces[e] = mpfr_get_ld(f[e].get(), kRnd);
  }
  out.residual = net();
  out.converged = out.residual <= floor;
  return out;
}

}  // namespace tripack
