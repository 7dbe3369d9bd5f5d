// The Lubachevsky-Stillinger event loop: Engine<kGrowth, kThermostat, kPinned, kTrack> predicts,
// orders and processes the collisions and neighbourhood updates of one run.
//
// A template so that the effects a scene does not use are compiled out. Private to sim/: only
// sim/billiards.cpp (the dispatcher, run_engine_for) includes it, so it is instantiated in one
// translation unit, compiled with -fno-math-errno -fno-trapping-math (CMakeLists.txt). The event
// queue (sim/event_queue.hpp), the neighbour lists and pair times (sim/neighbourhood.hpp) and the
// effects outside the loop (sim/effects.hpp) are in their own files.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "sim/billiards.hpp"
#include "sim/effects.hpp"
#include "sim/event_queue.hpp"
#include "sim/neighbourhood.hpp"
#include "sim/setup.hpp"

namespace tripack::sim_detail {

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
    traj_.assign(std::size_t(n_), 0);
    for (int i = 0; i < n_; ++i) {
      disks_[std::size_t(i)].x0 = s.x[std::size_t(i)];  // the clock starts at 0
      disks_[std::size_t(i)].v = is_pinned(i) ? Vec2{} : s.v[std::size_t(i)];
    }
    nb_.build(disks_, now_, diameter(now_), std::max(s.diam_cap, s.diam0) * (1 + 1e-9));
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
            const double want = scheduled_rate(base_rate_, schedule_, gap_);
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
  // Update event: disk i reached the edge of its neighbourhood; give it a new one.
  void relist(int i) {
    const Vec2 x = position(disks_[std::size_t(i)]);
    track(i, x);
    nb_.relist(i, x, diameter(now_));
  }

  // --- prediction ---
  void predict(int i) {
    const auto& di = disks_[std::size_t(i)];
    const auto& hi = nb_.hood(i);
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
      const int* list = nb_.neighbours(i);
      const int count = nb_.count(i);
      double* t = nb_.times();
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
    if (diam0_ <= nb_.diam_max()) return false;
    nb_.build(disks_, now_, diameter(now_), 2 * diam0_);  // a start beyond Oler's bound
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
      const int* list = nb_.neighbours(i);
      for (int k = 0; k < nb_.count(i); ++k)
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
  Neighbourhoods nb_;
  std::vector<std::uint32_t> traj_;
  std::vector<char> pinned_;
  EventQueue heap_;
  std::vector<Vec2> check_x_;        // max_overlap_all_pairs' positions
  std::vector<Vec2> lo_, hi_;        // path extents (kTrack)
  std::vector<std::uint64_t> hits_;  // collisions per disk (kTrack)
  std::vector<GrowthStep> schedule_;
  double base_rate_ = 0;
  double g_ = 0, diam0_ = 0, now_ = 0, t_base_ = 0, pin_limit_ = kInf;
  std::uint64_t every_ = 0, block_ = 0;
  double virial_ = 0, block_time_ = 0, gap_ = 1, energy_target_ = 0, block_energy_ = 0;
};

}  // namespace tripack::sim_detail
