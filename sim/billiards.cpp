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
// Partner codes: >= 0 a disk, -1 - side a wall, then a neighbourhood update.
constexpr int kUpdate = -4;
constexpr int kNoEvent = -5;

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
  // Restart the clock: every time minus dt (monotone, so the heap order holds).
  void shift(double dt) {
    for (auto& nd : h_) nd.t -= dt;
    for (auto& e : ev_) e.t -= dt;
  }
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

// Hot per-disk state: the position at time t is x0 + v t (engine clock). No per-disk time: a
// position costs one multiply-add, and 32 bytes keep two disks in a cache line.
struct Disk {
  Vec2 x0, v;
};

// Collision times of disk i (position xi at `now`, velocity vi) with its m neighbours
// disks[list[k]] (positions at their own times), all diameters D growing at g:
// |dx + dv t|^2 = (D + g t)^2, kInf when they never touch. Branch-free, so the loop vectorises
// (whether a pair approaches is data-dependent, and a branch on it mispredicts often): both
// cancellation-free forms of the root are computed and one is selected. The AVX2 clone is chosen
// at load time where the CPU has it (no FMA: every clone rounds alike). m is a multiple of 4 and
// list[k] a valid index up to it; the extra lanes are ignored.
__attribute__((target_clones("avx2", "default"))) void pair_times(
    int m, const Disk* __restrict disks, const int* __restrict list, Vec2 xi, Vec2 vi, double now,
    double D, double g, double* __restrict t) {
  for (int k = 0; k < m; ++k) {
    const Disk& dj = disks[list[k]];
    const double px = dj.x0.x + dj.v.x * now - xi.x;
    const double py = dj.x0.y + dj.v.y * now - xi.y;
    const double ux = dj.v.x - vi.x, uy = dj.v.y - vi.y;
    const double b = px * ux + py * uy - g * D;
    const double a = ux * ux + uy * uy - g * g;
    const double c0 = px * px + py * py - D * D;
    // c <= 0: touching (or rounding overlap); approaching, the root is then exactly 0 (now).
    const double c = std::max(c0, 0.0);
    const double disc = b * b - a * c;
    const double root = std::sqrt(std::max(disc, 0.0));
    // Approaching (b < 0): c / (root - b). Receding but growth outruns it (a < 0):
    // (b + root) / -a. Otherwise (receding faster than growth, or a miss: disc < 0) never.
    // Every operation runs on every lane; only values are selected (what lets it vectorise).
    const bool approaching = b < 0;
    const double num = approaching ? c : b + root;
    const double den = approaching ? root - b : -a;
    const double q = num / den;
    const bool hit = (approaching | (a < 0)) & (disc >= 0);
    t[k] = hit ? q : kInf;
  }
}

// Each disk's neighbourhood (bounding neighbourhoods, Donev, Torquato & Stillinger 2005): a fixed
// circle that contains the growing disk until the disk's next update event. Two disks can touch
// only if their neighbourhoods overlap, so a disk predicts against its neighbour list alone
// (about the six contacts near jamming, against ~10 disks in 9 cells of a cell grid) and there are
// no cell-crossing events; the grid only indexes the anchors, which move at updates.
struct Neighbourhood {
  Vec2 anchor;
  double radius = 0;
  int cell = 0, slot = 0;
  unsigned walls = 0;  // bit s: the neighbourhood reaches side s
};

// Everything the engine needs, already in container units.
struct Setup {
  std::vector<Vec2> x, v;
  std::vector<char> pinned;
  double diam0 = 0, rate = 0, diam_cap = 0;
  std::vector<GrowthStep> schedule;  // by decreasing gap
  std::uint64_t thermostat_every = 0;
  StopRules stop;
};

// Neighbourhood radius = disk radius + kSkin * (largest diameter). Near jamming the second shell
// of neighbours is sqrt3 D away, so any skin below 0.36 D keeps the lists at the contacts; a
// larger skin means fewer updates at low density (bench_billiards measured 0.1 .. 0.3).
constexpr double kSkin = 0.2;

// kGrowth, kThermostat, kPinned, kTrack (shaking: each disk's path extent): which effects are
// compiled in. Absent effects are constant-folded away (rate 0, no rescaling, no pinned tests,
// no extent updates on the hot path).
template <bool kGrowth, bool kThermostat, bool kPinned, bool kTrack = false>
class Engine {
 public:
  Engine(Setup s, const BilliardsOptions& o) : opt_(o), stop_(s.stop), n_(int(s.x.size())) {
    if constexpr (kGrowth) g_ = base_rate_ = s.rate;
    if constexpr (kGrowth) schedule_ = s.schedule;
    if constexpr (kTrack) {
      lo_ = hi_ = s.x;
      hits_.assign(std::size_t(n_), 0);
    }
    if constexpr (kThermostat) every_ = s.thermostat_every;
    if constexpr (kPinned) pinned_ = s.pinned;
    diam0_ = s.diam0;
    disks_.resize(std::size_t(n_));
    hood_.resize(std::size_t(n_));
    traj_.assign(std::size_t(n_), 0);
    for (int i = 0; i < n_; ++i) {
      disks_[std::size_t(i)].x0 = s.x[std::size_t(i)];  // the clock starts at 0
      disks_[std::size_t(i)].v = is_pinned(i) ? Vec2{} : s.v[std::size_t(i)];
    }
    build_neighbourhoods(std::max(s.diam_cap, s.diam0) * (1 + 1e-9));
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
        bounce(e.i, static_cast<Side>(-1 - e.j));
        ++r.collisions;
        ++since_rescale;
        record(r, e.i, e.j);
        predict(e.i);
      } else {
        relist(e.i);
        predict(e.i);
      }
      if (opt_.check_every_event)  // all pairs: independent of the neighbour lists it checks
        r.max_overlap = std::max(r.max_overlap, max_overlap_all_pairs());
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
        const bool rebuilt = sync();
        bool new_rate = false;
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
            if (stop_.pressure > 0 && 2 / gap_ > stop_.pressure) {
              stop("pressure reached", true);
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
            // Growth schedule: the rate of the last step whose gap the estimate is below. The
            // clock was just restarted (diameter = diam0 + g t from t = 0), so g may change here.
            double want = base_rate_;
            for (const auto& step : schedule_)
              if (gap_ < step.gap) want = step.rate;
            if (want != g_) {
              g_ = want;
              new_rate = true;
              if constexpr (kPinned) pin_limit_ = pinned_limit();
            }
          }
        } else {
          since_sync = 0;
        }
        if (rescale) {
          thermostat();
          since_rescale = 0;
        }
        if (block_energy_ < 0) block_energy_ = 2 * kinetic_energy();
        if (rescale || rebuilt || new_rate) rebuild_heap();  // else the shifted ones still hold
      }
    }
    sync();
    r.max_overlap = std::max(r.max_overlap, max_overlap());
    r.time = t_base_;
    r.diameter = diameter(0);
    r.relative_gap = gap_;
    r.kinetic_energy_end = kinetic_energy();
    r.growth_rate = rate();
    if constexpr (kTrack) {
      const double D = diameter(0);
      for (int i = 0; i < n_; ++i) {
        const Vec2 e = hi_[std::size_t(i)] - lo_[std::size_t(i)];
        r.excursion.push_back(D > 0 ? std::max(e.x, e.y) / D : 0.0);
      }
      r.shake_hits = hits_;
    }
    r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    for (const auto& d : disks_) {
      r.positions.push_back(d.x0);  // synced: the clock is at 0
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
  Vec2 position(const Disk& d) const { return d.x0 + d.v * now_; }
  // A new velocity from now on, the position at now kept.
  void set_velocity(Disk& d, Vec2 x, Vec2 v) {
    d.v = v;
    d.x0 = x - v * now_;
  }
  // Shaking: paths are straight between events, so their extremes are at events.
  void track(int i, Vec2 x) {
    if constexpr (kTrack) {
      auto& lo = lo_[std::size_t(i)];
      auto& hi = hi_[std::size_t(i)];
      lo = {std::min(lo.x, x.x), std::min(lo.y, x.y)};
      hi = {std::max(hi.x, x.x), std::max(hi.y, x.y)};
    } else {
      (void)i, (void)x;
    }
  }
  double kinetic_energy() const {
    double e = 0;
    for (const auto& d : disks_) e += dot(d.v, d.v) / 2;
    return e;
  }

  // --- neighbourhoods ---
  // A grid over the bounding box indexes the anchors; cell side >= the largest neighbourhood
  // diameter (the largest disk diameter `diam_max` plus twice the skin), so overlapping
  // neighbourhoods are anchored in adjacent cells.
  void build_neighbourhoods(double diam_max) {
    diam_max_ = diam_max + 1e-300;
    skin_ = kSkin * diam_max_;
    cell_size_ = (diam_max_ + 2 * skin_) * (1 + 1e-9);
    mx_ = std::max(1, int(1.0 / cell_size_));
    my_ = std::max(1, int(kH / cell_size_));
    wx_ = 1.0 / mx_;
    wy_ = kH / my_;
    cell_count_.assign(std::size_t(mx_) * std::size_t(my_), 0);
    cell_cap_ = 8;
    cell_list_.assign(cell_count_.size() * std::size_t(cell_cap_), 0);
    nbr_cap_ = 16;
    nbr_count_.assign(std::size_t(n_), 0);
    nbr_.assign(std::size_t(n_) * std::size_t(nbr_cap_), 0);
    batch_.assign(std::size_t(nbr_cap_), 0.0);
    for (int i = 0; i < n_; ++i) {
      set_neighbourhood(i);
      cell_insert(i);
    }
    for (int i = 0; i < n_; ++i)
      for_each_overlapping(i, [&](int j) {
        if (j > i) add_neighbours(i, j);
      });
  }
  // A new neighbourhood around disk i's present position.
  void set_neighbourhood(int i) {
    auto& h = hood_[std::size_t(i)];
    h.anchor = position(disks_[std::size_t(i)]);
    h.radius = diameter(now_) / 2 + skin_;
    h.walls = 0;
    for (Side s : kSides)
      if (wall_distance(h.anchor, s, 1.0) < h.radius * (1 + 1e-9)) h.walls |= 1u << unsigned(s);
  }
  // Calls f(j) for every other disk j whose neighbourhood overlaps i's (a relative slack of 1e-9
  // covers the rounding of positions against the neighbourhood boundary).
  template <class F>
  void for_each_overlapping(int i, F&& f) const {
    const auto& h = hood_[std::size_t(i)];
    const int cx = h.cell % mx_, cy = h.cell / mx_;
    const int x0 = std::max(cx - 1, 0), x1 = std::min(cx + 1, mx_ - 1);
    for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, my_ - 1); ++y)
      for (int x = x0; x <= x1; ++x) {
        const int c = y * mx_ + x;
        const int* list = cell_begin(c);
        for (int k = 0; k < cell_count_[std::size_t(c)]; ++k) {
          const int j = list[k];
          if (j == i) continue;
          const auto& hj = hood_[std::size_t(j)];
          const double reach = (h.radius + hj.radius) * (1 + 1e-9);
          const Vec2 dx = hj.anchor - h.anchor;
          if (dot(dx, dx) < reach * reach) f(j);
        }
      }
  }
  // Update event: disk i reached the edge of its neighbourhood; give it a new one.
  void relist(int i) {
    track(i, position(disks_[std::size_t(i)]));
    const int* list = neighbours(i);
    for (int k = 0; k < nbr_count_[std::size_t(i)]; ++k) drop_neighbour(list[k], i);
    nbr_count_[std::size_t(i)] = 0;
    cell_remove(i);
    set_neighbourhood(i);
    cell_insert(i);
    for_each_overlapping(i, [&](int j) { add_neighbours(i, j); });
  }
  const int* neighbours(int i) const {
    return nbr_.data() + std::size_t(i) * std::size_t(nbr_cap_);
  }
  void add_neighbours(int i, int j) {
    if (nbr_count_[std::size_t(i)] == nbr_cap_ || nbr_count_[std::size_t(j)] == nbr_cap_)
      grow_neighbour_lists();
    nbr_[std::size_t(i) * std::size_t(nbr_cap_) + std::size_t(nbr_count_[std::size_t(i)]++)] = j;
    nbr_[std::size_t(j) * std::size_t(nbr_cap_) + std::size_t(nbr_count_[std::size_t(j)]++)] = i;
  }
  void drop_neighbour(int j, int i) {  // remove i from j's list
    int* list = nbr_.data() + std::size_t(j) * std::size_t(nbr_cap_);
    int& count = nbr_count_[std::size_t(j)];
    for (int k = 0; k < count; ++k)
      if (list[k] == i) {
        list[k] = list[--count];
        return;
      }
  }
  // Lists are stored flat with one capacity for all; a full list doubles it (rare: low density).
  void grow_neighbour_lists() {
    const int cap = 2 * nbr_cap_;
    std::vector<int> list(std::size_t(n_) * std::size_t(cap));
    for (int i = 0; i < n_; ++i)
      std::copy_n(neighbours(i), nbr_count_[std::size_t(i)],
                  list.begin() + std::ptrdiff_t(std::size_t(i) * std::size_t(cap)));
    nbr_.swap(list);
    nbr_cap_ = cap;
    batch_.assign(std::size_t(nbr_cap_), 0.0);
  }
  // Anchor cells, stored flat: cell c holds cell_count_[c] disks at cell_list_[c * cell_cap_ ...].
  const int* cell_begin(int c) const {
    return cell_list_.data() + std::size_t(c) * std::size_t(cell_cap_);
  }
  void cell_insert(int i) {
    auto& h = hood_[std::size_t(i)];
    const int cx = std::clamp(int(h.anchor.x / wx_), 0, mx_ - 1);
    const int cy = std::clamp(int(h.anchor.y / wy_), 0, my_ - 1);
    const int c = cy * mx_ + cx;
    if (cell_count_[std::size_t(c)] == cell_cap_) grow_cells();
    const int k = cell_count_[std::size_t(c)]++;
    cell_list_[std::size_t(c) * std::size_t(cell_cap_) + std::size_t(k)] = i;
    h.cell = c;
    h.slot = k;
  }
  void cell_remove(int i) {
    const auto& h = hood_[std::size_t(i)];
    int* list = cell_list_.data() + std::size_t(h.cell) * std::size_t(cell_cap_);
    const int last = list[--cell_count_[std::size_t(h.cell)]];
    list[h.slot] = last;
    hood_[std::size_t(last)].slot = h.slot;
  }
  void grow_cells() {
    const int cap = 2 * cell_cap_;
    std::vector<int> list(cell_count_.size() * std::size_t(cap));
    for (std::size_t c = 0; c < cell_count_.size(); ++c)
      std::copy_n(cell_list_.begin() + std::ptrdiff_t(c * std::size_t(cell_cap_)), cell_count_[c],
                  list.begin() + std::ptrdiff_t(c * std::size_t(cap)));
    cell_list_.swap(list);
    cell_cap_ = cap;
  }

  // --- prediction ---
  // Time from now until a disk at p (relative to its anchor), velocity v, whose radius grows at
  // h, leaves its neighbourhood: |p + v t| = s - h t with s = neighbourhood radius - disk radius.
  // The positive root of (v^2 - h^2) t^2 + 2 (p.v + s h) t + (p^2 - s^2) = 0, cancellation-free;
  // never later than s / h, when the disk fills the neighbourhood.
  static double exit_time(Vec2 p, Vec2 v, double s, double h) {
    if (s <= 0) return 0;
    const double a = dot(v, v) - h * h, b = dot(p, v) + s * h;
    const double c = std::min(dot(p, p) - s * s, 0.0);
    const double disc = std::max(b * b - a * c, 0.0);
    double t = kInf;
    if (b >= 0) {
      const double q = b + std::sqrt(disc);
      t = q > 0 ? -c / q : 0;
    } else if (a > 0) {
      t = (-b + std::sqrt(disc)) / a;
    }
    return h > 0 ? std::min(t, s / h) : t;
  }

  // Is the disk still inside its neighbourhood at time t (see exit_time)?
  static bool inside_at(Vec2 p, Vec2 v, double s, double h, double t) {
    const Vec2 q = p + v * t;
    const double room = s - h * t;
    return room > 0 && dot(q, q) < room * room;
  }

  void predict(int i) {
    const auto& di = disks_[std::size_t(i)];
    const auto& hi = hood_[std::size_t(i)];
    const Vec2 xi = position(di);
    const double D = diameter(now_), g = rate();
    double best = kInf;
    int partner = kNoEvent;
    if (!is_pinned(i)) {  // pinned disks only need their updates; the others predict against them
      for (Side side : kSides) {
        if (!(hi.walls >> unsigned(side) & 1u)) continue;
        const double w = std::max(wall_distance(xi, side, 1.0) - D / 2, 0.0);
        const double denom = g / 2 - dot(di.v, wall_normal<double>(side));
        if (denom > 0 && w < best * denom) {
          best = w / denom;
          partner = -1 - int(side);
        }
      }
      const Vec2 vi = di.v;
      const double now = now_;
      const int* list = neighbours(i);
      const int count = nbr_count_[std::size_t(i)];
      double* t = batch_.data();
      pair_times((count + 3) & ~3, disks_.data(), list, xi, vi, now, D, g, t);
      int arg = -1;  // selected, not branched to (the winner is unpredictable)
      for (int k = 0; k < count; ++k) {
        const bool earlier = t[k] < best;
        best = earlier ? t[k] : best;
        arg = earlier ? k : arg;
      }
      if (arg >= 0) partner = list[arg];
    }
    // The update comes first only if the disk is out of its neighbourhood at `best`: the times it
    // is inside, |p + v t| + h t <= s, form an interval from 0 (a convex function of t), so
    // inside at `best` means inside until then. Most predictions skip the root this way.
    const Vec2 p = xi - hi.anchor;
    const double s = hi.radius - D / 2, h = g / 2;
    if (!(best < kInf) || !inside_at(p, di.v, s, h, best)) {
      const double t = exit_time(p, di.v, s, h);
      if (t <= best) best = t, partner = kUpdate;
    }
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
    const Vec2 xa = position(a), xb = position(b);
    track(i, xa);
    track(j, xb);
    Vec2 va = a.v, vb = b.v;
    const Vec2 dx = xb - xa;
    const double r2 = dot(dx, dx), q = dot(vb - va, dx);
    const double dist = std::sqrt(r2), u = q / dist, g = rate();
    const double target = std::max(2 * g - u, g * diameter(now_) / dist);
    if (target > u) {
      [[maybe_unused]] const double e0 = dot(va, va) + dot(vb, vb);
      // Velocity change of each free disk along dx: elastic part plus the growth extra
      // (zero when g = 0 and the pair approaches).
      const double k = -q / r2 + (target + u) / (2 * dist);
      if (is_pinned(i))
        vb += dx * (2 * k);
      else if (is_pinned(j))
        va -= dx * (2 * k);
      else {
        va -= dx * k;
        vb += dx * k;
      }
      if constexpr (!kGrowth) {  // remove the rounding bias of the energy (~0.4 ulp a collision)
        // v (1 + delta), added rather than multiplied: a factor next to 1 rounds with a bias.
        const double e1 = dot(va, va) + dot(vb, vb), delta = (e0 - e1) / (2 * e1);
        va += va * delta;
        vb += vb * delta;
      }
      // Virial r . dp: the momentum k dist moved across distance D (twice against a pinned disk).
      virial_ += diameter(now_) * k * dist * (is_pinned(i) || is_pinned(j) ? 2 : 1);
      set_velocity(a, xa, va);
      set_velocity(b, xb, vb);
    }
    ++traj_[std::size_t(i)];
    ++traj_[std::size_t(j)];
    if constexpr (kTrack) ++hits_[std::size_t(i)], ++hits_[std::size_t(j)];
  }
  void bounce(int i, Side side) {
    auto& d = disks_[std::size_t(i)];
    const Vec2 x = position(d);
    track(i, x);
    const Vec2 nrm = wall_normal<double>(side);
    Vec2 v = d.v;
    const double vn = dot(v, nrm), g = rate();
    const double target = std::max(g - vn, g / 2);
    if (target > vn) {
      [[maybe_unused]] const double e0 = dot(v, v);
      v += nrm * (-2 * vn / dot(nrm, nrm) + (target + vn));
      if constexpr (!kGrowth) {
        const double e1 = dot(v, v);
        v += v * ((e0 - e1) / (2 * e1));
      }
      virial_ += diameter(now_) * (target - vn);
      set_velocity(d, x, v);
    }
    ++traj_[std::size_t(i)];
    if constexpr (kTrack) ++hits_[std::size_t(i)];
  }
  void record(BilliardsResult&, int i, int j) {
    if (!opt_.trace) return;
    const auto& d = disks_[std::size_t(i)];
    opt_.trace->push_back({t_base_ + now_, i, j, position(d), d.v});
  }

  // --- bookkeeping ---
  // Bring every disk to now and restart the clock at 0 (event times stay small, so collisions
  // 1e-14 apart near jamming are still resolved). True when the neighbourhoods were rebuilt (the
  // predictions must be redone).
  bool sync() {
    heap_.shift(now_);
    for (auto& d : disks_) d.x0 += d.v * now_;  // the position at now becomes x0
    diam0_ = diameter(now_);
    t_base_ += now_;
    if constexpr (kPinned) pin_limit_ -= now_;
    now_ = 0;
    if (diam0_ <= diam_max_) return false;
    build_neighbourhoods(2 * diam0_);  // a start beyond Oler's bound
    return true;
  }
  void rebuild_heap() {
    heap_.reset(n_);
    for (int i = 0; i < n_; ++i) predict(i);
  }
  void thermostat() {
    const double e = 2 * kinetic_energy();
    if (e <= 0 || energy_target_ <= 0) return;
    const double s = std::sqrt(energy_target_ / e);
    for (auto& d : disks_) set_velocity(d, position(d), d.v * s);
    for (auto& t : traj_) ++t;
  }
  // Largest overlap (relative to the diameter) among pairs and walls, positions at now. Disks
  // that overlap have overlapping neighbourhoods, so the neighbour lists cover every pair.
  double max_overlap() const {
    const double D = diameter(now_);
    if (D <= 0) return 0;
    double worst = 0;
    for (int i = 0; i < n_; ++i) {
      const Vec2 xi = position(disks_[std::size_t(i)]);
      for (Side s : kSides) worst = std::max(worst, D / 2 - wall_distance(xi, s, 1.0));
      const int* list = neighbours(i);
      for (int k = 0; k < nbr_count_[std::size_t(i)]; ++k)
        if (const int j = list[k]; j > i)
          worst = std::max(worst, D - norm(position(disks_[std::size_t(j)]) - xi));
    }
    return worst / D;
  }
  // The same over every pair (O(n^2); the test mode of check_every_event).
  double max_overlap_all_pairs() {
    const double D = diameter(now_);
    if (D <= 0) return 0;
    double worst = 0, closest2 = kInf;
    check_x_.resize(std::size_t(n_));
    for (int i = 0; i < n_; ++i) {
      check_x_[std::size_t(i)] = position(disks_[std::size_t(i)]);
      for (Side s : kSides)
        worst = std::max(worst, D / 2 - wall_distance(check_x_[std::size_t(i)], s, 1.0));
    }
    for (std::size_t i = 0; i < check_x_.size(); ++i)
      for (std::size_t j = i + 1; j < check_x_.size(); ++j) {
        const Vec2 dx = check_x_[j] - check_x_[i];
        closest2 = std::min(closest2, dot(dx, dx));
      }
    if (closest2 < kInf) worst = std::max(worst, D - std::sqrt(closest2));
    return worst / D;
  }
  // Pinned pairs and pinned disks on walls cannot move apart: growth must stop when they touch.
  double pinned_limit() const {
    double dmax = kInf;
    for (int i = 0; i < n_; ++i) {
      if (!is_pinned(i)) continue;
      const Vec2 xi = position(disks_[std::size_t(i)]);
      for (Side s : kSides) dmax = std::min(dmax, 2 * wall_distance(xi, s, 1.0));
      for (int j = i + 1; j < n_; ++j)
        if (is_pinned(j)) dmax = std::min(dmax, norm(position(disks_[std::size_t(j)]) - xi));
    }
    if (rate() <= 0 || dmax == kInf) return kInf;
    return std::max(dmax - diam0_, 0.0) / rate();
  }

  BilliardsOptions opt_;
  StopRules stop_;
  int n_;
  std::vector<Disk> disks_;
  std::vector<Neighbourhood> hood_;
  std::vector<std::uint32_t> traj_;
  std::vector<char> pinned_;
  std::vector<int> cell_list_, cell_count_;  // anchors by cell
  int cell_cap_ = 8;
  std::vector<int> nbr_, nbr_count_;  // neighbour lists, nbr_cap_ slots per disk
  int nbr_cap_ = 16;                  // a multiple of 4 (pair_times' padding)
  std::vector<double> batch_;         // predict's relative positions, velocities and times
  EventQueue heap_;
  double diam_max_ = 0, skin_ = 0, cell_size_ = 0, wx_ = 1, wy_ = 1;
  int mx_ = 1, my_ = 1;
  std::vector<Vec2> check_x_;        // max_overlap_all_pairs' positions
  std::vector<Vec2> lo_, hi_;        // path extents (kTrack)
  std::vector<std::uint64_t> hits_;  // collisions per disk (kTrack)
  std::vector<GrowthStep> schedule_;
  double base_rate_ = 0;
  double g_ = 0, diam0_ = 0, now_ = 0, t_base_ = 0, pin_limit_ = kInf;
  std::uint64_t every_ = 0, block_ = 0;
  double virial_ = 0, block_time_ = 0, gap_ = 1, energy_target_ = 0, block_energy_ = 0;
};

template <bool G, bool T, bool P, bool S = false>
BilliardsResult run_engine(Setup s, const BilliardsOptions& o) {
  return Engine<G, T, P, S>(std::move(s), o).run();
}
// The engine compiled for exactly the effects a run needs (the shaking engine never grows).
BilliardsResult run_engine_for(bool G, bool T, bool P, bool shaking, Setup s,
                               const BilliardsOptions& o) {
  auto pins = [&]<bool g, bool t, bool sh>() {
    return P ? run_engine<g, t, true, sh>(std::move(s), o)
             : run_engine<g, t, false, sh>(std::move(s), o);
  };
  if (shaking) return pins.template operator()<false, false, true>();
  if (G)
    return T ? pins.template operator()<true, true, false>()
             : pins.template operator()<true, false, false>();
  return T ? pins.template operator()<false, true, false>()
           : pins.template operator()<false, false, false>();
}

// Upper bound of the container diameter from Oler's bound (d <= 1/t(n)); the cell size.
double diameter_cap(int n) {
  if (n == 1) return 1 / std::sqrt(3.0);  // the inscribed disk
  const double t = (-3 + std::sqrt(8.0 * n + 1)) / 2;
  const double d = std::min(1.0, 1 / t);
  return d / (1 + std::sqrt(3.0) * d);
}

// Shaking at fixed size: an elastic run from the state in r (engine numbering) for per_disk * n
// collisions with fresh random unit velocities, recording each disk's path extent in
// r.excursion. The state in r is left as it was (shaking is a diagnostic).
void shake(BilliardsResult& r, const ShakeEffect& fx, const std::vector<char>& pinned,
           double diam_cap, std::mt19937_64& rng, const BilliardsOptions& options) {
  Setup s;
  const std::size_t n = r.positions.size();
  s.x = r.positions;
  s.pinned = pinned;
  s.diam0 = double(r.diameter);
  s.diam_cap = std::max(diam_cap, s.diam0);
  std::uniform_real_distribution<double> u01(0, 1);
  for (std::size_t i = 0; i < n; ++i) {
    const double phi = 2 * M_PI * u01(rng);
    s.v.push_back({std::cos(phi), std::sin(phi)});
  }
  s.thermostat_every = std::numeric_limits<std::uint64_t>::max();
  s.stop.max_collisions = fx.per_disk * n;
  s.stop.max_seconds = r.seconds > 0 ? std::max(60.0, 10 * r.seconds) : 600;
  BilliardsOptions o = options;
  o.trace = nullptr;  // the trace is the main phase's
  o.all_policies = false;
  const bool any_pinned = std::find(pinned.begin(), pinned.end(), 1) != pinned.end();
  const BilliardsResult shaken = run_engine_for(false, false, any_pinned, true, std::move(s), o);
  r.excursion = shaken.excursion;
  r.shake_hits = shaken.shake_hits;
  r.shake_collisions = shaken.collisions;
  r.shake_seconds = shaken.seconds;
  r.max_overlap = std::max(r.max_overlap, shaken.max_overlap);
}

// order[k] = the scene index of the disk the engine calls k: sorted by the Z-order (Morton) key
// of the cell of side `cell` holding its start position (ties keep the scene order).
std::vector<int> spatial_order(const std::vector<Vec2>& x, double cell) {
  auto spread = [](std::uint32_t v) {  // bits of v to the even bit positions
    std::uint64_t w = v;
    w = (w | (w << 16)) & 0x0000FFFF0000FFFFull;
    w = (w | (w << 8)) & 0x00FF00FF00FF00FFull;
    w = (w | (w << 4)) & 0x0F0F0F0F0F0F0F0Full;
    w = (w | (w << 2)) & 0x3333333333333333ull;
    w = (w | (w << 1)) & 0x5555555555555555ull;
    return w;
  };
  const double inv = 1 / std::max(cell, 1e-6);
  std::vector<std::uint64_t> key(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const auto cx = std::uint32_t(std::clamp(x[i].x * inv, 0.0, 65535.0));
    const auto cy = std::uint32_t(std::clamp(x[i].y * inv, 0.0, 65535.0));
    key[i] = spread(cx) | (spread(cy) << 1);
  }
  std::vector<int> order(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) order[i] = int(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return key[std::size_t(a)] < key[std::size_t(b)]; });
  return order;
}
template <class T>
std::vector<T> permuted(const std::vector<T>& v, const std::vector<int>& order) {
  if (v.empty()) return v;
  std::vector<T> out(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) out[k] = v[std::size_t(order[k])];
  return out;
}
template <class T>
std::vector<T> unpermuted(const std::vector<T>& v, const std::vector<int>& order) {
  std::vector<T> out(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) out[std::size_t(order[k])] = v[k];
  return out;
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
  if (G) s.schedule = scene.growth->schedule;
  if (T) s.thermostat_every = scene.thermostat->every ? scene.thermostat->every : 10 * n;
  if (!T) s.thermostat_every = std::numeric_limits<std::uint64_t>::max();

  // The engine numbers disks along a Z-order curve of their start cells, so neighbours sit close
  // in memory; everything it returns is mapped back to the scene's numbering.
  const std::vector<int> order = spatial_order(s.x, s.diam_cap);
  s.x = permuted(s.x, order);
  s.v = permuted(s.v, order);
  s.pinned = permuted(s.pinned, order);
  const std::size_t traced = options.trace ? options.trace->size() : 0;
  const std::vector<char> pinned = s.pinned;
  const double diam_cap = s.diam_cap;

  BilliardsResult r;
  const bool main_phase = G || !scene.shake;  // without growth, a shaking scene only shakes
  if (!main_phase) {
    r.positions = s.x;
    r.velocities = s.v;
    r.diameter = s.diam0;
    r.stop_reason = "shake only";
  }
  if (main_phase) {
    const bool all = options.all_policies;
    r = run_engine_for(G || all, T || all, P || all, false, std::move(s), options);
  }
  if (scene.shake) shake(r, *scene.shake, pinned, diam_cap, rng, options);
  r.positions = unpermuted(r.positions, order);
  r.velocities = unpermuted(r.velocities, order);
  if (scene.shake) {
    r.excursion = unpermuted(r.excursion, order);
    r.shake_hits = unpermuted(r.shake_hits, order);
    // Rattlers collide far less often than the median disk: a jammed disk bounces across the
    // remaining gap, a rattler across its cage.
    std::vector<std::uint64_t> sorted = r.shake_hits;
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2),
                     sorted.end());
    const double median = double(sorted[sorted.size() / 2]);
    for (int i = 0; i < n; ++i)
      if (double(r.shake_hits[std::size_t(i)]) * scene.shake->rattler_factor < median &&
          !(std::find(scene.pinned.begin(), scene.pinned.end(), i) != scene.pinned.end()))
        r.shake_rattlers.push_back(i);
  }
  if (options.trace)
    for (std::size_t k = traced; k < options.trace->size(); ++k) {
      auto& e = (*options.trace)[k];
      e.i = order[std::size_t(e.i)];
      if (e.partner >= 0) e.partner = order[std::size_t(e.partner)];
    }
  // Map the centres' triangle (inset by diam/2) onto the unit triangle.
  const long double diam = r.diameter, rad = diam / 2, side = 1 - kSqrt3 * diam;
  r.packing.d = d_from_diameter(diam);
  for (const auto& x : r.positions)
    r.packing.points.push_back({(x.x - kSqrt3 * rad) / side, (x.y - rad) / side});
  return r;
}

}  // namespace tripack
