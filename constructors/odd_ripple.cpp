// Class 7: Delta(2k+1) + 1, the non-symmetric ripple with a depressed cage (docs/classes.md §7).
//
// Disk units. The top Delta(2k) hangs from the apex with sites S(i, j) = (L/2 - i/2 + j,
// (L - i) sqrt3/2). Its row 2k-2 has free disks B1 (j=1), B2 (j=2); its bottom ("anchor") row
// A_0..A_{2k-1} has A_1 (depressed) and A_3 free and the rattlers A_2, A_4, ..., A_{2k-2}. Below,
// the chain F0 R0 F1 F2 R1 F3 R2 ... R_{k-1} F_{k+1} (F on the floor, R raised).
//
// The 3k+10 contact equations in 3k+9 unknowns reduce to one unknown, L:
//  * R0 touches the corner F0 and A0; A0, R0 and A1 form a unit equilateral triangle, so A1
//    follows, and F1 = R0 + A1 - A0 lies on the floor for every L (the redundant equation);
//  * A0 S(2k-2,0) B1 A1 is a unit rhombus, so B1 = A1 + e60; then B2 touches B1 and S(2k-3,1),
//    A3 touches B2 and S(2k-2,3), F2 = F1 + e0, and R1 touches F2 and A3;
//  * from F3 on it is the ripple march: R_i touches F_{i+1} and A_{2i+1}, F_{i+2} sits on the
//    floor at distance 1 from R_i;
//  * the condition is F_{k+1} = (L, 0).
// Shooting on L solves it to long double in O(k). The whole bond system then goes to the polisher,
// which measures every residual (and would refine a poor start), and finish() re-detects the
// bonds from the geometry alone: they must reproduce the intended list exactly.
//
// The other modification (variant `other`, docs/odd-ripple-other.md: t16a33, t29a, t46a, t67b,
// t92b) has the same chain; B0 and B1 are free, A0 slides up the left wall, A2 sits on the floor
// disk F2, and the rattlers are A1, A4, ..., A_{2k-2}. Its 3k+8 equations reduce to two unknowns
// (A0's position on the wall inside, L outside), solved by nested shooting.
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "constructors/blocks.hpp"
#include "constructors/builders.hpp"
#include "constructors/registry.hpp"
#include "core/neighbours.hpp"
#include "polish/polish.hpp"

namespace tripack {

namespace {

using D = Directions<long double>;

// Site j of row i of the top Delta(2k) (row 0 is the apex).
Vec2L site(long double L, long i, long j) {
  const long double ii = static_cast<long double>(i);
  return {L / 2 - ii / 2 + static_cast<long double>(j), (L - ii) * kSqrt3 / 2};
}

// The intersection of the unit circles about c1 and c2 closer to `hint`, if they meet.
std::optional<Vec2L> meet(const Vec2L& c1, const Vec2L& c2, const Vec2L& hint) {
  const Vec2L dv = c2 - c1;
  const long double q = dot(dv, dv);
  if (!(q < 4) || q == 0) return std::nullopt;
  const long double dist = std::sqrt(q);
  const long double h = std::sqrt(1 - q / 4);
  const Vec2L mid = (c1 + c2) / 2.0L;
  const Vec2L off = Vec2L(-dv.y, dv.x) * (h / dist);
  const Vec2L p = mid + off, m = mid - off;
  return dot(p - hint, p - hint) < dot(m - hint, m - hint) ? p : m;
}

// The positions of the free disks for a given side L.
struct Ripple {
  long double L = 0;
  std::vector<Vec2L> floor;   // F_0..F_{k+1}
  std::vector<Vec2L> raised;  // R_0..R_{k-1}
  Vec2L a1, a3, b1, b2;
};

// A raised disk touching the floor disk f and the disk a, on the right of f, and the next floor
// disk. Returns false if the geometry is impossible for this L.
bool raise(const Vec2L& f, const Vec2L& a, Vec2L& r, Vec2L& next_floor) {
  const auto m = meet(f, a, f + D::e0);
  if (!m || !(m->y > 0) || !(m->y < 1)) return false;
  r = *m;
  next_floor = {r.x + std::sqrt((1 - r.y) * (1 + r.y)), 0};
  return true;
}

// The ripple march from R_first on, for side L: R_i touches F_{i+1} and A_{2i+1}, F_{i+2} sits on
// the floor at distance 1 from R_i. Returns the mismatch F_{k+1}.x - L, or nullopt if a raised
// disk cannot be placed.
std::optional<long double> march_on(long k, long double L, long first, std::vector<Vec2L>& floor,
                                    std::vector<Vec2L>& raised) {
  for (long i = first; i < k; ++i) {
    const auto u = static_cast<std::size_t>(i);
    if (!raise(floor[u + 1], site(L, 2 * k - 1, 2 * i + 1), raised[u], floor[u + 2]))
      return std::nullopt;
  }
  return floor[static_cast<std::size_t>(k + 1)].x - L;
}

// Marches from the left corner for side L; returns F_{k+1}.x - L, or nullopt if the chain
// cannot be closed at this L.
std::optional<long double> march(long k, long double L, Ripple& c) {
  c.L = L;
  const long row = 2 * k - 1;  // the anchor row
  const Vec2L a0 = site(L, row, 0);
  c.floor[0] = {0, 0};
  if (!raise(c.floor[0], a0, c.raised[0], c.floor[1])) return std::nullopt;
  const auto a1 = meet(a0, c.raised[0], site(L, row, 1));
  if (!a1) return std::nullopt;
  c.a1 = *a1;
  c.b1 = c.a1 + D::e60;
  const auto b2 = meet(c.b1, site(L, row - 2, 1), site(L, row - 1, 2));
  if (!b2) return std::nullopt;
  c.b2 = *b2;
  const auto a3 = meet(c.b2, site(L, row - 1, 3), site(L, row, 3));
  if (!a3) return std::nullopt;
  c.a3 = *a3;
  c.floor[2] = c.floor[1] + D::e0;
  if (!raise(c.floor[2], c.a3, c.raised[1], c.floor[3])) return std::nullopt;
  return march_on(k, L, 2, c.floor, c.raised);
}

// Solves a shooting equation f(L) = 0, L = 2k - 1 + 2 x0 (x0 = A_0.x on the lattice), where
// f(L) is nullopt when the chain cannot be closed at L. The physical root is the first sign
// change scanning down from x0 = 1 (depressed cage: x0 = 0.786 at k = 3, 0.631 at k = 60, 0.598
// at k = 300; at x0 = 1/sqrt3 the anchor row is at height 1 and nothing fits below it). Above
// some x0 the chain cannot be closed (a raised disk would leave the band 0 < y < 1); for large k
// the mismatch changes sign within less than a scan step of that edge, so the edge is bisected as
// well. Leaves f's last evaluation at the returned L (the closer end of the final bracket).
long double shoot(long k, const std::function<std::optional<long double>(long double)>& march,
                  const std::string& what) {
  const long double base = static_cast<long double>(2 * k - 1);
  auto f = [&](long double x0) { return march(base + 2 * x0); };
  long double hi = 0, lo = 0, f_hi = 0, f_lo = 0;
  long double x_prev = 1, f_prev = 0;
  bool prev_valid = false, bracketed = false;
  for (int j = 1; j <= 500 && !bracketed; ++j) {
    const long double x = 1.0L - j * 1e-3L;
    const auto v = f(x);
    if (v && prev_valid && (*v > 0) != (f_prev > 0)) {
      lo = x;
      f_lo = *v;
      hi = x_prev;
      f_hi = f_prev;
      bracketed = true;
    } else if (v && !prev_valid) {
      // Entering the closable range: bisect towards its edge, watching for a sign change.
      long double edge = x_prev, inner = x;
      for (int it = 0; it < 100 && !bracketed; ++it) {
        const long double mid = (edge + inner) / 2;
        if (!(mid > inner && mid < edge)) break;
        const auto w = f(mid);
        if (!w) {
          edge = mid;
        } else if ((*w > 0) != (*v > 0)) {
          lo = x;
          f_lo = *v;
          hi = mid;
          f_hi = *w;
          bracketed = true;
        } else {
          inner = mid;
        }
      }
    }
    x_prev = x;
    prev_valid = v.has_value();
    if (v) f_prev = *v;
  }
  if (!bracketed) throw std::runtime_error(what + ": no root for k=" + std::to_string(k));
  // Bisection to the last bit: cheap, and it cannot be misled by rounding noise.
  for (int it = 0; it < 200; ++it) {
    const long double mid = (lo + hi) / 2;
    if (mid <= lo || mid >= hi) break;
    const auto v = f(mid);
    if (!v) throw std::runtime_error(what + ": chain breaks inside the bracket");
    if ((*v > 0) == (f_lo > 0)) {
      lo = mid;
      f_lo = *v;
    } else {
      hi = mid;
      f_hi = *v;
    }
  }
  const long double x = std::fabs(f_hi) < std::fabs(f_lo) ? hi : lo;
  f(x);
  return base + 2 * x;
}

// The free disks of a modification (Ripple or Other) for the side L that closes the chain:
// march(k, L, c) places them for one L, shoot finds L.
template <class Free>
Free solve_chain(long k, std::optional<long double> (*march)(long, long double, Free&),
                 const std::string& what) {
  Free c;
  c.floor.resize(static_cast<std::size_t>(k + 2));
  c.raised.resize(static_cast<std::size_t>(k));
  shoot(
      k, [&](long double L) { return march(k, L, c); }, what);
  return c;
}

Ripple solve_ripple(long k) {
  return solve_chain<Ripple>(k, march, "odd ripple");
}
// The other modification (docs/odd-ripple-other.md): the same chain F0 R0 F1 F2 R1 F3 ... below
// a top Delta(2k) whose row 2k-2 has B0 (j=0) and B1 (j=1) free and whose anchor row has A0 free
// on the left wall, A2 free (sitting on the floor disk F2) and the rattlers A1, A4, A6, ...,
// A_{2k-2}.
struct Other {
  long double L = 0;
  std::vector<Vec2L> floor;   // F_0..F_{k+1}
  std::vector<Vec2L> raised;  // R_0..R_{k-1}
  Vec2L a0, a2, b0, b1;
};

// The left cluster for side L and A0 = u e60 on the left wall: R0 touches the corner F0 and A0,
// F1 sits on the floor at distance 1 from R0 and F2 = F1 + e0; B0 touches A0 and S(2k-3,0), B1
// touches B0 and S(2k-2,2), A2 touches B1 and A3 = S(2k-1,3). Returns |A2 - F2|^2 - 1 (the
// cluster's closing contact), or nullopt if a pair of circles does not meet.
std::optional<long double> other_cluster(long k, long double L, long double u, Other& c) {
  const long m = 2 * k;
  c.a0 = D::e60 * u;
  const auto r0 = meet({0, 0}, c.a0, D::e0);
  if (!r0 || !(r0->y > 0) || !(r0->y < 1)) return std::nullopt;
  c.raised[0] = *r0;
  c.floor[0] = {0, 0};
  c.floor[1] = {r0->x + std::sqrt((1 - r0->y) * (1 + r0->y)), 0};
  c.floor[2] = c.floor[1] + D::e0;
  // The hints pick the intersection right of the line S(2k-3,0) A0 (B0 moves right and down),
  // and below the lines B0 S(2k-2,2) and B1 A3 (B1 and A2 are pushed down).
  const auto b0 = meet(c.a0, site(L, m - 3, 0), site(L, m - 2, 0) + Vec2L{0.1L, 0});
  if (!b0) return std::nullopt;
  c.b0 = *b0;
  const auto b1 = meet(c.b0, site(L, m - 2, 2), site(L, m - 2, 1) - Vec2L{0, 0.3L});
  if (!b1) return std::nullopt;
  c.b1 = *b1;
  const auto a2 = meet(c.b1, site(L, m - 1, 3), site(L, m - 1, 2) - Vec2L{0, 0.3L});
  if (!a2) return std::nullopt;
  c.a2 = *a2;
  const Vec2L g = c.a2 - c.floor[2];
  return dot(g, g) - 1;
}

// For side L: solves the left cluster for u, then marches R_i (touching F_{i+1} and A_{2i+1})
// and F_{i+2} for i = 1..k-1; returns F_{k+1}.x - L, or nullopt.
//
// At u = u_lat = L - 2k + 1 (A0 on its lattice site) A0 and S(2k-3,0) are 2 apart, so B0, B1
// and A2 sit on their sites and the closing residual is positive (A2 is about sqrt3 x0 high).
// Raising A0 along the wall pushes B0, B1 and A2 down and the residual falls through zero at
// u - u_lat = 0.027 (k = 2), 0.016 (k = 3), 3.8e-3 (k = 10), 2.3e-4 (k = 200); it rises again
// to a second, unphysical root at u - u_lat ~ 0.39 (k = 3), so the bracket is (u_lat, u_lat + 0.1].
std::optional<long double> other_march(long k, long double L, Other& c) {
  c.L = L;
  const long m = 2 * k;
  const long double u_lat = L - static_cast<long double>(m - 1);
  long double lo = u_lat, hi = u_lat + 0.1L;
  const auto g_hi = other_cluster(k, L, hi, c);
  if (!g_hi || !(*g_hi < 0)) return std::nullopt;
  // Near u_lat the circles about A0 and S(2k-3,0) barely meet (or not at all, by rounding): an
  // invalid cluster counts as the positive side.
  for (int it = 0; it < 200; ++it) {
    const long double mid = (lo + hi) / 2;
    if (mid <= lo || mid >= hi) break;
    const auto g = other_cluster(k, L, mid, c);
    if (!g || *g > 0)
      lo = mid;
    else
      hi = mid;
  }
  if (!other_cluster(k, L, hi, c)) return std::nullopt;
  return march_on(k, L, 1, c.floor, c.raised);
}

Other solve_other(long k) {
  return solve_chain<Other>(k, other_march, "odd ripple (other)");
}

}  // namespace

namespace {

// What both modifications share: the top Delta(2k) hanging from the apex on its lattice, a few of
// its disks moved off their sites, the bottom chain F0 R0 F1 F2 R1 F3 R2 ... R_{k-1} F_{k+1} with
// its floor, wall and chain contacts, and the finish (polish, rattlers dropped into their cages,
// the detected contacts checked against the intended ones).
class RippleFrame {
 public:
  RippleFrame(long k, long double L) : k_(k), m_(2 * k), L_(L), pat_(L) {
    top_ = pat_.add_triangle({L / 2, L * kSqrt3 / 2}, D::e240, D::e300, m_);
  }
  // Disk j of row i of the top Delta(2k): i - j steps along e240 and j along e300 from the apex.
  int site(long i, long j) const {
    return top_ + static_cast<int>(DiskUnitsPattern::index_in_triangle(m_, i - j, j));
  }
  long m() const { return m_; }
  // A_j and B_j (docs/classes.md §7): disk j of the top Delta(2k)'s bottom row (row 2k-1), and of
  // the row above it (row 2k-2).
  int a(long j) const { return site(m_ - 1, j); }
  int b(long j) const { return site(m_ - 2, j); }
  // The top Delta(2k) with a few disks moved off their sites and the rattlers taken out (see
  // keep_lattice_except), and the bottom chain below it (add_chain).
  void arrange(const std::vector<std::pair<int, Vec2L>>& moved, const std::vector<int>& rattlers,
               const std::vector<Vec2L>& floor, const std::vector<Vec2L>& raised) {
    keep_lattice_except(moved, rattlers);
    add_chain(floor, raised);
  }
  // The lattice contacts (pairs and side walls) of the disks that stay on their sites; then the
  // moved disks go to their places.
  void keep_lattice_except(const std::vector<std::pair<int, Vec2L>>& moved,
                           const std::vector<int>& rattlers) {
    std::vector<char> off(pat_.points().size(), 0);
    for (const auto& mv : moved) off[static_cast<std::size_t>(mv.first)] = 1;
    for (int r : rattlers) off[static_cast<std::size_t>(r)] = 1;
    bonds_ = find_contacts(pat_.points(), L_, kBondTolerance, off);
    for (const auto& [i, p] : moved) pat_.points()[static_cast<std::size_t>(i)] = p;
  }
  // The bottom chain and its contacts; floor(i) and raised(i) are F_i and R_i.
  void add_chain(const std::vector<Vec2L>& floor, const std::vector<Vec2L>& raised) {
    fl_.assign(static_cast<std::size_t>(k_ + 2), 0);
    ra_.assign(static_cast<std::size_t>(k_), 0);
    std::vector<int> chain;
    auto add_floor = [&](long i) {
      fl_[static_cast<std::size_t>(i)] = pat_.add(floor[static_cast<std::size_t>(i)]);
      chain.push_back(fl_[static_cast<std::size_t>(i)]);
    };
    auto add_raised = [&](long i) {
      ra_[static_cast<std::size_t>(i)] = pat_.add(raised[static_cast<std::size_t>(i)]);
      chain.push_back(ra_[static_cast<std::size_t>(i)]);
    };
    add_floor(0);
    add_raised(0);
    add_floor(1);
    for (long i = 1; i < k_; ++i) {
      add_floor(i + 1);
      add_raised(i);
    }
    add_floor(k_ + 1);
    for (std::size_t i = 0; i + 1 < chain.size(); ++i)
      bonds_.push_back(Bond::pair(chain[i], chain[i + 1]));
    for (int f : fl_) bonds_.push_back(Bond::wall(f, Side::Bottom));
    bonds_.push_back(Bond::wall(fl_.front(), Side::Left));
    bonds_.push_back(Bond::wall(fl_.back(), Side::Right));
  }
  int floor_disk(long i) const { return fl_[static_cast<std::size_t>(i)]; }
  int raised_disk(long i) const { return ra_[static_cast<std::size_t>(i)]; }
  void bond(int i, int j) { bonds_.push_back(Bond::pair(i, j)); }
  template <std::size_t N>
  void bond_all(const int (&pairs)[N][2]) {
    for (const auto& e : pairs) bond(e[0], e[1]);
  }
  void wall_bond(int i, Side side) { bonds_.push_back(Bond::wall(i, side)); }
  // The rattlers A_j of the top Delta(2k)'s bottom row: every other disk from A_first on, short
  // of the last two.
  void add_top_row_rattlers(std::vector<int>& rattlers, long first) const {
    for (long j = first; j < m_ - 1; j += 2) rattlers.push_back(a(j));
  }
  // Each raised disk R_i from R_first on touches A_{2i+1}, the bottom-row disk above it.
  void bond_raised_to_top_row(long first) {
    for (long i = first; i < k_; ++i) bond(raised_disk(i), a(2 * i + 1));
  }

  // The shooting start satisfies the system to a few ulp of the coordinates (5e-16 at k = 200).
  // Accept ~100 ulp (relative to L) rather than the polisher's default: refining further would
  // cost a sparse QR of the whole triangle here, and the caller's polish refines anyway. Then the
  // rattlers drop by `drop` into the cages the ripple opens, and the contacts detected from the
  // geometry must be the intended ones.
  Pattern finish(const std::vector<int>& rattlers, long double drop, const std::string& name) {
    std::sort(bonds_.begin(), bonds_.end());
    PolishOptions opt;
    opt.tolerance = 1e-17L;
    auto& pts = pat_.points();
    const PolishReport rep = polish_bond_system_disk_units(pts, L_, bonds_, rattlers, opt);
    if (!(rep.max_residual < 1e-13L))
      throw std::runtime_error(name + ": contact system not solved (residual " +
                               std::to_string(static_cast<double>(rep.max_residual)) + ")");
    pat_.set_side(L_);
    for (int r : rattlers) {
      pts[static_cast<std::size_t>(r)] -= Vec2L{0, drop};
      pat_.mark_rattler(r);
    }
    Pattern out = pat_.finish({});
    if (out.bonds != bonds_)
      throw std::logic_error(
          name + ": detected contacts differ from the intended ones for k=" + std::to_string(k_));
    return out;
  }

 private:
  long k_, m_;
  long double L_;
  DiskUnitsPattern pat_;
  int top_ = 0;
  std::vector<int> fl_, ra_;
  std::vector<Bond> bonds_;
};

}  // namespace

Pattern build_odd_ripple_depressed(long k) {
  if (k < 3) throw std::invalid_argument("Delta(2k+1)+1 (depressed cage) needs k >= 3");
  const Ripple c = solve_ripple(k);
  RippleFrame f(k, c.L);
  const int a0 = f.a(0), a1 = f.a(1), a3 = f.a(3), b1 = f.b(1), b2 = f.b(2);
  std::vector<int> rattlers;  // A2, A4, ..., A_{2k-2}
  f.add_top_row_rattlers(rattlers, 2);
  f.arrange({{a1, c.a1}, {a3, c.a3}, {b1, c.b1}, {b2, c.b2}}, rattlers, c.floor, c.raised);
  // The contacts of the depressed cage (docs/classes.md §7).
  const int r0 = f.raised_disk(0), r1 = f.raised_disk(1), f1 = f.floor_disk(1);
  // c1: disk 1 of row 2k-3.
  const int b0 = f.b(0), b3 = f.b(3), c1 = f.site(f.m() - 3, 1);
  const int cage[][2] = {{r0, a0}, {r0, a1}, {f1, a1}, {a1, a0}, {a1, b1},  // the depressed disk A1
                         {b1, b0}, {b1, b2}, {b2, c1}, {b2, a3},            // B1, B2 (row 2k-2)
                         {a3, b3}, {a3, r1}};                               // A3
  f.bond_all(cage);
  f.bond_raised_to_top_row(2);
  return f.finish(rattlers, 0.2L, "odd ripple");
}

Pattern build_odd_ripple_other(long k) {
  if (k < 2) throw std::invalid_argument("Delta(2k+1)+1 (other modification) needs k >= 2");
  const Other c = solve_other(k);
  RippleFrame f(k, c.L);
  const int a0 = f.a(0), a2 = f.a(2), a3 = f.a(3), b0 = f.b(0), b1 = f.b(1);
  std::vector<int> rattlers{f.a(1)};  // A1, A4, A6, ..., A_{2k-2}
  f.add_top_row_rattlers(rattlers, 4);
  f.arrange({{a0, c.a0}, {a2, c.a2}, {b0, c.b0}, {b1, c.b1}}, rattlers, c.floor, c.raised);
  // The cage contacts (docs/odd-ripple-other.md).
  const int r0 = f.raised_disk(0), f2 = f.floor_disk(2);
  // c0: disk 0 of row 2k-3.
  const int b2 = f.b(2), c0 = f.site(f.m() - 3, 0);
  f.wall_bond(a0, Side::Left);
  const int cage[][2] = {{r0, a0}, {a0, b0}, {b0, c0},   // A0 slides up the left wall
                         {b0, b1}, {b1, b2},             // B0, B1 (row 2k-2)
                         {b1, a2}, {a2, a3}, {a2, f2}};  // A2 sits on the floor disk F2
  f.bond_all(cage);
  f.bond_raised_to_top_row(1);
  // k = 2: R1 also touches A2 (F2 R1 A3 A2 is a rhombus with the unit diagonal A2 R1; the
  // geometry forces it, it is not an equation of the solve).
  if (k == 2) f.bond(f.raised_disk(1), a2);
  return f.finish(rattlers, 0.25L, "odd ripple (other)");
}

namespace {
const BuilderRegistration kOddRipple{
    "odd-ripple", [](const BuilderCall& c) {
      return c.variant == "other" ? build_odd_ripple_other(c.k) : build_odd_ripple_depressed(c.k);
    }};
}  // namespace

}  // namespace tripack
