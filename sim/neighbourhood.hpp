// Who the billiards engine predicts against: bounding neighbourhoods (Donev, Torquato &
// Stillinger 2005), their neighbour lists, and the pair collision times over a list.
//
// Each disk owns a fixed circle (its neighbourhood) that contains the growing disk until the
// disk's next update event. Two disks can touch only if their neighbourhoods overlap, so a disk
// predicts against its neighbour list alone (about the six contacts near jamming, against ~10
// disks in 9 cells of a cell grid) and there are no cell-crossing events; a grid only indexes the
// anchors, which move at updates. Split from sim/engine.hpp because this bookkeeping does not
// depend on the engine's effects. The list operations of an update event are inline here; the
// rare ones (building, growing the storage) and the vectorised pair_times (a target_clones
// function: it must live in a .cpp) are in sim/neighbourhood.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "core/geometry.hpp"
#include "sim/event_queue.hpp"  // kInf

namespace tripack::sim_detail {

inline constexpr double kH = 0.8660254037844386;  // sqrt3 / 2: height of the unit triangle

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
void pair_times(int m, const Disk* __restrict disks, const int* __restrict list, Vec2 xi, Vec2 vi,
                double now, double D, double g, double* __restrict t);

// Time from now until a disk at p (relative to its anchor), velocity v, whose radius grows at
// h, leaves its neighbourhood: |p + v t| = s - h t with s = neighbourhood radius - disk radius.
// The positive root of (v^2 - h^2) t^2 + 2 (p.v + s h) t + (p^2 - s^2) = 0, cancellation-free;
// never later than s / h, when the disk fills the neighbourhood.
inline double exit_time(Vec2 p, Vec2 v, double s, double h) {
  if (s <= 0) return 0;
  const double a = dot(v, v) - h * h, b = dot(p, v) + s * h;
  const double c = std::min(dot(p, p) - s * s, 0.0);
  const double disc = std::max(b * b - a * c, 0.0);
  double t = kInf;
  if (b >= 0) {
    // q = 0 with the disk inside (c < 0): the root is at infinity (a disk at rest in a
    // neighbourhood that does not shrink, e.g. a pinned disk without growth, never leaves it).
    // Reading it as 0 gave that disk an update event at the same time forever.
    const double q = b + std::sqrt(disc);
    t = q > 0 ? -c / q : (c < 0 ? kInf : 0);
  } else if (a > 0) {
    t = (-b + std::sqrt(disc)) / a;
  }
  return h > 0 ? std::min(t, s / h) : t;
}

// Is the disk still inside its neighbourhood at time t (see exit_time)?
inline bool inside_at(Vec2 p, Vec2 v, double s, double h, double t) {
  const Vec2 q = p + v * t;
  const double room = s - h * t;
  return room > 0 && dot(q, q) < room * room;
}

// A disk's neighbourhood: a fixed circle around `anchor`.
struct Neighbourhood {
  Vec2 anchor;
  double radius = 0;
  int cell = 0, slot = 0;
  unsigned walls = 0;  // bit s: the neighbourhood reaches side s
};

// Neighbourhood radius = disk radius + kSkin * (largest diameter). Near jamming the second shell
// of neighbours is sqrt3 D away, so any skin below 0.36 D keeps the lists at the contacts; a
// larger skin means fewer updates at low density (bench_billiards measured 0.1 .. 0.3).
inline constexpr double kSkin = 0.2;

// All disks' neighbourhoods, the grid of their anchors, and the neighbour lists (j is in i's list
// iff their neighbourhoods overlap, and then i is in j's).
class Neighbourhoods {
 public:
  // New neighbourhoods around the disks' positions at `now`, for diameters D now and up to
  // diam_max (the skin and the grid's cell size follow from diam_max).
  void build(const std::vector<Disk>& disks, double now, double D, double diam_max);
  // Update event: disk i (now at x, diameter D) reached the edge of its neighbourhood; give it a
  // new one.
  void relist(int i, Vec2 x, double D) {
    const int* list = neighbours(i);
    for (int k = 0; k < nbr_count_[std::size_t(i)]; ++k) drop_neighbour(list[k], i);
    nbr_count_[std::size_t(i)] = 0;
    cell_remove(i);
    set_neighbourhood(i, x, D);
    cell_insert(i);
    for_each_overlapping(i, [&](int j) { add_neighbours(i, j); });
  }

  const Neighbourhood& hood(int i) const { return hood_[std::size_t(i)]; }
  const int* neighbours(int i) const {
    return nbr_.data() + std::size_t(i) * std::size_t(nbr_cap_);
  }
  int count(int i) const { return nbr_count_[std::size_t(i)]; }
  // Room for one time per list entry, rounded up to a multiple of 4 (pair_times' output).
  double* times() { return batch_.data(); }
  // The largest diameter the neighbourhoods were built for.
  double diam_max() const { return diam_max_; }

 private:
  // A new neighbourhood around x for a disk of diameter D.
  void set_neighbourhood(int i, Vec2 x, double D) {
    auto& h = hood_[std::size_t(i)];
    h.anchor = x;
    h.radius = D / 2 + skin_;
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
  void grow_neighbour_lists();
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
  void grow_cells();

  int n_ = 0;
  std::vector<Neighbourhood> hood_;
  std::vector<int> cell_list_, cell_count_;  // anchors by cell
  int cell_cap_ = 8;
  std::vector<int> nbr_, nbr_count_;  // neighbour lists, nbr_cap_ slots per disk
  int nbr_cap_ = 16;                  // a multiple of 4 (pair_times' padding)
  std::vector<double> batch_;         // pair_times' output, nbr_cap_ long
  double diam_max_ = 0, skin_ = 0, wx_ = 1, wy_ = 1;
  int mx_ = 1, my_ = 1;
};

}  // namespace tripack::sim_detail
