#include "sim/billiards.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace tripack {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kH = 0.8660254037844386;  // sqrt3 / 2: height of the unit triangle
// Partner codes: >= 0 a disk, -1 - side a wall, then the four cell faces.
constexpr int kCrossXPlus = -4, kCrossXMinus = -5, kCrossYPlus = -6, kCrossYMinus = -7;
constexpr int kNoEvent = -8;

struct Event {
  double t;
  int i, j;
  std::uint32_t traj;  // traj[j] when predicted: j's trajectory unchanged since
};
// Indexed 4-ary min-heap with one slot per disk (its earliest predicted event), updated in place:
// no dead entries to pop, and the heap stays n long.
class EventQueue {
 public:
  void reset(int n) {
    h_.clear();
    pos_.assign(std::size_t(n), -1);
    ev_.assign(std::size_t(n), Event{kInf, 0, kNoEvent, 0});
  }
  bool empty() const { return h_.empty(); }
  const Event& top() const { return ev_[std::size_t(h_.front().i)]; }
  void set(const Event& e) {
    const std::size_t i = std::size_t(e.i);
    const double old = ev_[i].t;
    ev_[i] = e;
    if (pos_[i] < 0) {
      pos_[i] = int(h_.size());
      h_.push_back({e.t, e.i});
      up(std::size_t(pos_[i]));
    } else {
      h_[std::size_t(pos_[i])].t = e.t;
      e.t < old ? up(std::size_t(pos_[i])) : down(std::size_t(pos_[i]));
    }
  }
  void erase(int i) {
    const int k = pos_[std::size_t(i)];
    if (k < 0) return;
    pos_[std::size_t(i)] = -1;
    const Node last = h_.back();
    h_.pop_back();
    if (std::size_t(k) == h_.size()) return;
    place(std::size_t(k), last);
    up(std::size_t(k));
    down(std::size_t(pos_[std::size_t(last.i)]));
  }

 private:
  struct Node {
    double t;
    int i;
  };
  void place(std::size_t k, const Node& nd) {
    h_[k] = nd;
    pos_[std::size_t(nd.i)] = int(k);
  }
  void up(std::size_t k) {
    const Node nd = h_[k];
    while (k > 0) {
      const std::size_t p = (k - 1) / 4;
      if (h_[p].t <= nd.t) break;
      place(k, h_[p]);
      k = p;
    }
    place(k, nd);
  }
  void down(std::size_t k) {
    const Node nd = h_[k];
    const std::size_t n = h_.size();
    while (true) {
      const std::size_t c = 4 * k + 1;
      if (c >= n) break;
      std::size_t m = c;
      if (c + 4 <= n) {  // all four children: the first smallest, selected without branches
        const double t0 = h_[c].t, t1 = h_[c + 1].t, t2 = h_[c + 2].t, t3 = h_[c + 3].t;
        const bool s01 = t1 < t0, s23 = t3 < t2;
        const std::size_t m01 = c + std::size_t(s01), m23 = c + 2 + std::size_t(s23);
        const double t01 = std::min(t0, t1), t23 = std::min(t2, t3);
        m = m01 + (m23 - m01) * std::size_t(t23 < t01);
      } else {
        for (std::size_t q = c + 1; q < n; ++q)
          if (h_[q].t < h_[m].t) m = q;
      }
      if (h_[m].t >= nd.t) break;
      place(k, h_[m]);
      k = m;
    }
    place(k, nd);
  }
  std::vector<Node> h_;
  std::vector<int> pos_;
  std::vector<Event> ev_;
};

struct Disk {
  Vec2 x, v;  // at time t (lazy update)
  double t = 0;
  int cell = 0, slot = 0;
};

// Everything the engine needs, already in container units.
struct Setup {
  std::vector<Vec2> x, v;
  std::vector<char> pinned;
  double diam0 = 0, rate = 0, diam_cap = 0;
  std::uint64_t thermostat_every = 0;
  StopRules stop;
};

// kGrowth, kThermostat, kPinned: which effects are compiled in. Absent effects are constant-folded
// away (rate 0, no rescaling, no pinned tests on the hot path).
template <bool kGrowth, bool kThermostat, bool kPinned>
class Engine {
 public:
  Engine(Setup s, const BilliardsOptions& o) : opt_(o), stop_(s.stop), n_(int(s.x.size())) {
    if constexpr (kGrowth) g_ = s.rate;
    if constexpr (kThermostat) every_ = s.thermostat_every;
    if constexpr (kPinned) pinned_ = s.pinned;
    diam0_ = s.diam0;
    disks_.resize(std::size_t(n_));
    traj_.assign(std::size_t(n_), 0);
    for (int i = 0; i < n_; ++i) {
      disks_[std::size_t(i)].x = s.x[std::size_t(i)];
      disks_[std::size_t(i)].v = is_pinned(i) ? Vec2{} : s.v[std::size_t(i)];
    }
    build_cells(std::max(s.diam_cap, s.diam0));
    block_ = std::max<std::uint64_t>(20 * std::uint64_t(n_), 2000);
    if constexpr (kPinned) pin_limit_ = pinned_limit();
  }

  BilliardsResult run() {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    BilliardsResult r;
    r.kinetic_energy_start = kinetic_energy();
    energy_target_ = 2 * r.kinetic_energy_start;
    block_energy_ = energy_target_;
    rebuild_heap();
    std::uint64_t since_sync = 0, since_rescale = 0, stalls = 0;
    double next_progress = opt_.progress_seconds;
    double block_diam = diameter(0);
    auto stop = [&](const char* why, bool jammed) {
      r.stop_reason = why;
      r.jammed = jammed;
    };
    while (true) {
      if (heap_.empty()) {
        stop("no more events", false);
        break;
      }
      const Event e = heap_.top();
      if constexpr (kPinned) {
        if (e.t > pin_limit_ && kGrowth) {
          now_ = std::max(now_, pin_limit_);
          stop("pinned disks touch", true);
          break;
        }
      }
      auto& di = disks_[std::size_t(e.i)];
      now_ = e.t;
      if (e.j >= 0 && e.traj != traj_[std::size_t(e.j)]) {  // partner changed course: re-plan
        predict(e.i);
        continue;
      }
      ++r.events;
      ++since_sync;
      if (e.j >= 0) {
        collide(e.i, e.j);
        ++r.collisions;
        ++since_rescale;
        record(r, e.i, e.j);
        predict(e.i);
        predict(e.j);
      } else if (e.j >= -3) {
        advance(di);
        bounce(e.i, static_cast<Side>(-1 - e.j));
        ++r.collisions;
        ++since_rescale;
        record(r, e.i, e.j);
        predict(e.i);
      } else {
        cross(e.i, e.j);
        predict(e.i);
      }
      if (opt_.check_every_event) r.max_overlap = std::max(r.max_overlap, max_overlap());
      if (r.events >= stop_.max_events) {
        stop("max events", false);
        break;
      }
      if (stop_.max_collisions && r.collisions >= stop_.max_collisions) {
        stop("max collisions", false);
        break;
      }
      if ((r.events & 4095) == 0) {
        const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        if (elapsed > stop_.max_seconds) {
          stop("max seconds", false);
          break;
        }
        if (opt_.progress && elapsed >= next_progress) {
          next_progress = elapsed + opt_.progress_seconds;
          opt_.progress({r.events, r.collisions, elapsed, diameter(now_), gap_});
        }
      }
      const bool rescale = kThermostat && since_rescale >= every_;
      if (since_sync >= block_ || rescale) {
        block_time_ += now_;
        sync();
        if constexpr (kGrowth) {
          if (since_sync >= block_) {
            const double d = diameter(0);
            const double e2 = (block_energy_ + 2 * kinetic_energy()) / 2;  // mean sum v^2
            // Free-volume estimate (2D): reduced pressure p = sum(D J) / (2 N kT dt) with
            // kT = <v^2>/2, and 1 - D/D_jam = 2/p = 2 sum(v^2) dt / sum(D J).
            if (virial_ > 0 && g_ > 0) gap_ = 2 * e2 * block_time_ / virial_;
            if (gap_ < stop_.relative_gap) {
              stop("relative gap reached", true);
              break;
            }
            // Growth below rounding for several blocks: the precision limit of double.
            const bool stalled =
                g_ > 0 && d - block_diam <= 8 * std::numeric_limits<double>::epsilon() * d;
            stalls = stalled ? stalls + 1 : 0;
            if (stalls >= 3) {
              stop("growth stalled at the precision limit", true);
              break;
            }
            block_diam = d;
            virial_ = 0;
            block_time_ = 0;
            since_sync = 0;
            block_energy_ = -1;
          }
        } else {
          since_sync = 0;
        }
        if (rescale) {
          thermostat();
          since_rescale = 0;
        }
        if (block_energy_ < 0) block_energy_ = 2 * kinetic_energy();
        rebuild_heap();
      }
    }
    sync();
    r.max_overlap = std::max(r.max_overlap, max_overlap());
    r.time = t_base_;
    r.diameter = diameter(0);
    r.relative_gap = gap_;
    r.kinetic_energy_end = kinetic_energy();
    r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    for (const auto& d : disks_) {
      r.positions.push_back(d.x);
      r.velocities.push_back(d.v);
    }
    return r;
  }

 private:
  bool is_pinned(int i) const {
    if constexpr (kPinned)
      return pinned_[std::size_t(i)] != 0;
    else
      return (void)i, false;
  }
  double diameter(double t) const {
    if constexpr (kGrowth)
      return diam0_ + g_ * t;
    else
      return (void)t, diam0_;
  }
  double rate() const {
    if constexpr (kGrowth)
      return g_;
    else
      return 0;
  }
  Vec2 position(const Disk& d) const { return d.x + d.v * (now_ - d.t); }
  void advance(Disk& d) {
    d.x += d.v * (now_ - d.t);
    d.t = now_;
  }
  double kinetic_energy() const {
    double e = 0;
    for (const auto& d : disks_) e += dot(d.v, d.v) / 2;
    return e;
  }

  // --- cells: a grid over the bounding box, cell side >= the largest diameter allowed ---
  void build_cells(double size) {
    cell_size_ = size * (1 + 1e-9) + 1e-300;
    mx_ = std::max(1, int(1.0 / cell_size_));
    my_ = std::max(1, int(kH / cell_size_));
    wx_ = 1.0 / mx_;
    wy_ = kH / my_;
    cell_count_.assign(std::size_t(mx_) * std::size_t(my_), 0);
    cell_cap_ = 8;
    nb_.assign(9 * std::size_t(cell_cap_), 0);
    cell_list_.assign(cell_count_.size() * std::size_t(cell_cap_), 0);
    for (int i = 0; i < n_; ++i) {
      auto& d = disks_[std::size_t(i)];
      const int cx = std::clamp(int(d.x.x / wx_), 0, mx_ - 1);
      const int cy = std::clamp(int(d.x.y / wy_), 0, my_ - 1);
      insert(i, cy * mx_ + cx);
    }
  }
  // Cells are stored flat: cell c holds cell_count_[c] disks at cell_list_[c * cell_cap_ ...].
  // A full cell doubles the capacity of all (order within each cell kept).
  void grow_cells() {
    const int cap = 2 * cell_cap_;
    std::vector<int> list(cell_count_.size() * std::size_t(cap));
    for (std::size_t c = 0; c < cell_count_.size(); ++c)
      std::copy_n(cell_list_.begin() + std::ptrdiff_t(c * std::size_t(cell_cap_)), cell_count_[c],
                  list.begin() + std::ptrdiff_t(c * std::size_t(cap)));
    cell_list_.swap(list);
    cell_cap_ = cap;
    nb_.assign(9 * std::size_t(cap), 0);
  }
  const int* cell_begin(int c) const {
    return cell_list_.data() + std::size_t(c) * std::size_t(cell_cap_);
  }
  void insert(int i, int c) {
    if (cell_count_[std::size_t(c)] == cell_cap_) grow_cells();
    const int k = cell_count_[std::size_t(c)]++;
    cell_list_[std::size_t(c) * std::size_t(cell_cap_) + std::size_t(k)] = i;
    disks_[std::size_t(i)].cell = c;
    disks_[std::size_t(i)].slot = k;
  }
  void remove(int i) {
    auto& d = disks_[std::size_t(i)];
    int* list = cell_list_.data() + std::size_t(d.cell) * std::size_t(cell_cap_);
    const int last = list[--cell_count_[std::size_t(d.cell)]];
    list[d.slot] = last;
    disks_[std::size_t(last)].slot = d.slot;
  }
  void cross(int i, int code) {
    auto& d = disks_[std::size_t(i)];
    advance(d);
    int cx = d.cell % mx_, cy = d.cell / mx_;
    if (code == kCrossXPlus) ++cx;
    if (code == kCrossXMinus) --cx;
    if (code == kCrossYPlus) ++cy;
    if (code == kCrossYMinus) --cy;
    remove(i);
    insert(i, cy * mx_ + cx);
  }

  // --- prediction ---
  // Time from now until disks at relative position dx, relative velocity dv touch, both
  // diameters D growing at g: |dx + dv t|^2 = (D + g t)^2. kInf when they never touch or not
  // before `best` (then the square root is skipped: t >= c / (-2b) when a >= 0).
  static double pair_time(Vec2 dx, Vec2 dv, double D, double g, double best) {
    // The cheap rejections are combined without branches (each one alone is data-dependent and
    // unpredictable); only pairs that may beat `best` take the branch to the square root.
    const double b = dot(dx, dv) - g * D;
    const double a = dot(dv, dv) - g * g;
    const double c0 = dot(dx, dx) - D * D;
    // c <= 0: touching (or rounding overlap); with b < 0 the root below is exactly 0 (now).
    const double c = c0 > 0 ? c0 : 0;
    const bool grows_slower = a >= 0;
    const bool never = (grows_slower & (b >= 0)) | (grows_slower & (c >= -2 * b * best));
    if (never) return kInf;
    const double disc = b * b - a * c;
    if (disc < 0) return kInf;
    if (b < 0) return c / (-b + std::sqrt(disc));  // no cancellation
    return (b + std::sqrt(disc)) / -a;             // a < 0: growth outruns separation
  }

  void predict(int i) {
    auto& di = disks_[std::size_t(i)];
    if (is_pinned(i)) return;
    const Vec2 xi = position(di);
    const double D = diameter(now_), g = rate();
    double best = kInf;
    int partner = kNoEvent;
    for (Side side : kSides) {
      const double w = std::max(wall_distance(xi, side, 1.0) - D / 2, 0.0);
      const double denom = g / 2 - dot(di.v, wall_normal<double>(side));
      if (denom > 0 && w < best * denom) {
        best = w / denom;
        partner = -1 - int(side);
      }
    }
    const int cx = di.cell % mx_, cy = di.cell / mx_;
    {  // leaving the cell
      const double lo_x = cx * wx_, lo_y = cy * wy_;
      if (di.v.x > 0 && cx < mx_ - 1) {
        const double t = std::max((lo_x + wx_ - xi.x) / di.v.x, 0.0);
        if (t < best) best = t, partner = kCrossXPlus;
      } else if (di.v.x < 0 && cx > 0) {
        const double t = std::max((lo_x - xi.x) / di.v.x, 0.0);
        if (t < best) best = t, partner = kCrossXMinus;
      }
      if (di.v.y > 0 && cy < my_ - 1) {
        const double t = std::max((lo_y + wy_ - xi.y) / di.v.y, 0.0);
        if (t < best) best = t, partner = kCrossYPlus;
      } else if (di.v.y < 0 && cy > 0) {
        const double t = std::max((lo_y - xi.y) / di.v.y, 0.0);
        if (t < best) best = t, partner = kCrossYMinus;
      }
    }
    // Gather the neighbours (same order as a cell-by-cell scan) into one list first.
    int* nb = nb_.data();
    int m = 0, own = 0;  // own: i's place in the list
    const int x0 = std::max(cx - 1, 0), x1 = std::min(cx + 1, mx_ - 1);
    for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, my_ - 1); ++y)
      for (int x = x0; x <= x1; ++x) {
        const int c = y * mx_ + x;
        const int count = cell_count_[std::size_t(c)];
        if (count <= 8) [[likely]]
          std::memcpy(nb + m, cell_begin(c), 8 * sizeof(int));
        else
          std::memcpy(nb + m, cell_begin(c), std::size_t(count) * sizeof(int));
        if (c == di.cell) own = m + di.slot;
        m += count;
      }
    const Vec2 vi = di.v;
    const double now = now_;
    auto scan = [&](int k0, int k1) {
      for (int k = k0; k < k1; ++k) {
        const int j = nb[k];
        const auto& dj = disks_[std::size_t(j)];
        const double t = pair_time(dj.x + dj.v * (now - dj.t) - xi, dj.v - vi, D, g, best);
        if (t < best) best = t, partner = j;
      }
    };
    scan(0, own);
    scan(own + 1, m);
    if (partner == kNoEvent) return heap_.erase(i);
    heap_.set({now_ + best, i, partner, partner >= 0 ? traj_[std::size_t(partner)] : 0});
  }

  // --- collisions ---
  // Lubachevsky's rule: reflect the normal velocity in the frame of the growing surface, so the
  // relative normal speed becomes 2g - u >= g (elastic when g = 0), and never less than the rate
  // the gap must open at to keep touching disks apart.
  // The elastic part is written as a projection on the unnormalised contact vector (-q/r2, or
  // -2 vn/|n|^2 for walls): exact energy conservation up to unbiased rounding, while a rounded unit
  // normal would drift the energy systematically (1e-12 per 1e6 collisions).
  void collide(int i, int j) {
    auto& a = disks_[std::size_t(i)];
    auto& b = disks_[std::size_t(j)];
    advance(a);
    advance(b);
    const Vec2 dx = b.x - a.x;
    const double r2 = dot(dx, dx), q = dot(b.v - a.v, dx);
    const double dist = std::sqrt(r2), u = q / dist, g = rate();
    const double target = std::max(2 * g - u, g * diameter(now_) / dist);
    if (target > u) {
      [[maybe_unused]] const double e0 = dot(a.v, a.v) + dot(b.v, b.v);
      // Velocity change of each free disk along dx: elastic part plus the growth extra
      // (zero when g = 0 and the pair approaches).
      const double k = -q / r2 + (target + u) / (2 * dist);
      if (is_pinned(i))
        b.v += dx * (2 * k);
      else if (is_pinned(j))
        a.v -= dx * (2 * k);
      else {
        a.v -= dx * k;
        b.v += dx * k;
      }
      if constexpr (!kGrowth) {  // remove the rounding bias of the energy (~0.4 ulp a collision)
        // v (1 + delta), added rather than multiplied: a factor next to 1 rounds with a bias.
        const double e1 = dot(a.v, a.v) + dot(b.v, b.v), delta = (e0 - e1) / (2 * e1);
        a.v += a.v * delta;
        b.v += b.v * delta;
      }
      // Virial r . dp: the momentum k dist moved across distance D (twice against a pinned disk).
      virial_ += diameter(now_) * k * dist * (is_pinned(i) || is_pinned(j) ? 2 : 1);
    }
    ++traj_[std::size_t(i)];
    ++traj_[std::size_t(j)];
  }
  void bounce(int i, Side side) {
    auto& d = disks_[std::size_t(i)];
    const Vec2 nrm = wall_normal<double>(side);
    const double vn = dot(d.v, nrm), g = rate();
    const double target = std::max(g - vn, g / 2);
    if (target > vn) {
      [[maybe_unused]] const double e0 = dot(d.v, d.v);
      d.v += nrm * (-2 * vn / dot(nrm, nrm) + (target + vn));
      if constexpr (!kGrowth) {
        const double e1 = dot(d.v, d.v);
        d.v += d.v * ((e0 - e1) / (2 * e1));
      }
      virial_ += diameter(now_) * (target - vn);
    }
    ++traj_[std::size_t(i)];
  }
  void record(BilliardsResult&, int i, int j) {
    if (!opt_.trace) return;
    const auto& d = disks_[std::size_t(i)];
    opt_.trace->push_back({t_base_ + now_, i, j, d.x, d.v});
  }

  // --- bookkeeping ---
  // Bring every disk to now and restart the clock at 0 (event times stay small, so collisions
  // 1e-14 apart near jamming are still resolved).
  void sync() {
    for (auto& d : disks_) {
      advance(d);
      d.t = 0;
    }
    diam0_ = diameter(now_);
    t_base_ += now_;
    if constexpr (kPinned) pin_limit_ -= now_;
    now_ = 0;
    if (diam0_ > cell_size_) {  // only when the start was already larger than the cap
      build_cells(2 * diam0_);
    }
  }
  void rebuild_heap() {
    heap_.reset(n_);
    for (int i = 0; i < n_; ++i) predict(i);
  }
  void thermostat() {
    const double e = 2 * kinetic_energy();
    if (e <= 0 || energy_target_ <= 0) return;
    const double s = std::sqrt(energy_target_ / e);
    for (auto& d : disks_) d.v = d.v * s;
    for (auto& t : traj_) ++t;
  }
  // Largest overlap (relative to the diameter) among pairs and walls, positions at now.
  double max_overlap() const {
    const double D = diameter(now_);
    if (D <= 0) return 0;
    double worst = 0;
    for (int i = 0; i < n_; ++i) {
      const auto& di = disks_[std::size_t(i)];
      const Vec2 xi = position(di);
      for (Side s : kSides) worst = std::max(worst, D / 2 - wall_distance(xi, s, 1.0));
      const int cx = di.cell % mx_, cy = di.cell / mx_;
      for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, my_ - 1); ++y)
        for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, mx_ - 1); ++x)
          for (int k = 0; k < cell_count_[std::size_t(y * mx_ + x)]; ++k)
            if (const int j = cell_begin(y * mx_ + x)[k]; j > i)
              worst = std::max(worst, D - norm(position(disks_[std::size_t(j)]) - xi));
    }
    return worst / D;
  }
  // Pinned pairs and pinned disks on walls cannot move apart: growth must stop when they touch.
  double pinned_limit() const {
    double dmax = kInf;
    for (int i = 0; i < n_; ++i) {
      if (!is_pinned(i)) continue;
      const Vec2 xi = disks_[std::size_t(i)].x;
      for (Side s : kSides) dmax = std::min(dmax, 2 * wall_distance(xi, s, 1.0));
      for (int j = i + 1; j < n_; ++j)
        if (is_pinned(j)) dmax = std::min(dmax, norm(disks_[std::size_t(j)].x - xi));
    }
    if (rate() <= 0 || dmax == kInf) return kInf;
    return std::max(dmax - diam0_, 0.0) / rate();
  }

  BilliardsOptions opt_;
  StopRules stop_;
  int n_;
  std::vector<Disk> disks_;
  std::vector<std::uint32_t> traj_;
  std::vector<char> pinned_;
  std::vector<int> cell_list_, cell_count_;
  int cell_cap_ = 8;
  std::vector<int> nb_;  // predict's neighbour list: 9 cells of cell_cap_
  EventQueue heap_;
  double cell_size_ = 0, wx_ = 1, wy_ = 1;
  int mx_ = 1, my_ = 1;
  double g_ = 0, diam0_ = 0, now_ = 0, t_base_ = 0, pin_limit_ = kInf;
  std::uint64_t every_ = 0, block_ = 0;
  double virial_ = 0, block_time_ = 0, gap_ = 1, energy_target_ = 0, block_energy_ = 0;
};

template <bool G, bool T, bool P>
BilliardsResult run_engine(Setup s, const BilliardsOptions& o) {
  return Engine<G, T, P>(std::move(s), o).run();
}

// Upper bound of the container diameter from Oler's bound (d <= 1/t(n)); the cell size.
double diameter_cap(int n) {
  if (n == 1) return 1 / std::sqrt(3.0);  // the inscribed disk
  const double t = (-3 + std::sqrt(8.0 * n + 1)) / 2;
  const double d = std::min(1.0, 1 / t);
  return d / (1 + std::sqrt(3.0) * d);
}

}  // namespace

BilliardsResult run_billiards(const Scene& scene, std::mt19937_64& rng,
                              const BilliardsOptions& options) {
  validate_scene(scene);
  const int n = scene.n;
  Setup s;
  s.stop = scene.stop;
  s.diam_cap = diameter_cap(n);
  s.pinned.assign(std::size_t(n), 0);
  for (int i : scene.pinned) s.pinned[std::size_t(i)] = 1;
  std::uniform_real_distribution<double> u01(0, 1);
  if (scene.points.empty()) {
    s.diam0 = 0;
    for (int i = 0; i < n; ++i) {  // uniform in the triangle: fold the unit rhombus
      double a = u01(rng), b = u01(rng);
      if (a + b > 1) a = 1 - a, b = 1 - b;
      s.x.push_back({a + b / 2, b * kH});
    }
  } else {
    const long double diam = diameter_from_d(scene.start_d);
    const long double r = diam / 2, side = 1 - kSqrt3 * diam;
    s.diam0 = double(diam);
    for (const auto& p : scene.points)
      s.x.push_back(Vec2(Vec2L{kSqrt3 * r + p.x * side, r + p.y * side}));
  }
  if (!scene.velocities.empty()) {
    s.v = scene.velocities;
  } else {
    for (int i = 0; i < n; ++i) {
      const double phi = 2 * M_PI * u01(rng);
      s.v.push_back({std::cos(phi), std::sin(phi)});
    }
  }
  const bool G = scene.growth && scene.growth->rate > 0;
  const bool T = scene.thermostat.has_value();
  const bool P = !scene.pinned.empty();
  if (G) s.rate = scene.growth->rate;
  if (T) s.thermostat_every = scene.thermostat->every ? scene.thermostat->every : 10 * n;
  if (!T) s.thermostat_every = std::numeric_limits<std::uint64_t>::max();

  BilliardsResult r;
  const int key = (G || options.all_policies ? 4 : 0) | (T || options.all_policies ? 2 : 0) |
                  (P || options.all_policies ? 1 : 0);
  switch (key) {
    case 0:
      r = run_engine<false, false, false>(std::move(s), options);
      break;
    case 1:
      r = run_engine<false, false, true>(std::move(s), options);
      break;
    case 2:
      r = run_engine<false, true, false>(std::move(s), options);
      break;
    case 3:
      r = run_engine<false, true, true>(std::move(s), options);
      break;
    case 4:
      r = run_engine<true, false, false>(std::move(s), options);
      break;
    case 5:
      r = run_engine<true, false, true>(std::move(s), options);
      break;
    case 6:
      r = run_engine<true, true, false>(std::move(s), options);
      break;
    default:
      r = run_engine<true, true, true>(std::move(s), options);
      break;
  }
  // Map the centres' triangle (inset by diam/2) onto the unit triangle.
  const long double diam = r.diameter, rad = diam / 2, side = 1 - kSqrt3 * diam;
  r.packing.d = d_from_diameter(diam);
  for (const auto& x : r.positions)
    r.packing.points.push_back({(x.x - kSqrt3 * rad) / side, (x.y - rad) / side});
  return r;
}

}  // namespace tripack
