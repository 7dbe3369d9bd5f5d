// The billiards engine's event queue: each disk's earliest predicted event, ordered by time.
//
// On its own (not inside sim/engine.hpp) so tests can check it directly; header-inline because
// every event passes through it (set / top / erase are on the engine's hot path).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace tripack::sim_detail {

// A time that never comes.
inline constexpr double kInf = std::numeric_limits<double>::infinity();
// Partner codes (Event::j): >= 0 a disk, -1 - side a wall, then a neighbourhood update, then none.
inline constexpr int kUpdate = -4;
inline constexpr int kNoEvent = -5;

struct Event {
  double t;
  int i, j;
  std::uint32_t traj;  // traj[j] when predicted: j's trajectory unchanged since
};

// Indexed 4-ary min-heap with one slot per disk (its earliest predicted event), updated in place:
// no dead entries to pop, and the heap stays n long. Disks are 0 .. n-1 (reset(n)); set replaces
// disk e.i's event, erase removes it. Equal times come out in no particular order.
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

}  // namespace tripack::sim_detail
