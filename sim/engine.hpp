// The Lubachevsky-Stillinger event loop: Engine<Effects...> predicts, orders and processes the
// collisions and neighbourhood updates of one run.
//
// A template on the effects' policy types (sim/effect.hpp) so that the effects a run does not use
// are compiled out: the hooks of absent effects do not exist, and the empty hooks of present ones
// inline to nothing. Private to sim/: only sim/billiards.cpp (the dispatcher) includes it, so it
// is instantiated in one translation unit, compiled with -fno-math-errno -fno-trapping-math
// (CMakeLists.txt). The event queue (sim/event_queue.hpp), the neighbour lists and pair times
// (sim/neighbourhood.hpp) and the effects (sim/effects/*.hpp) are in their own files.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "sim/billiards.hpp"
#include "sim/effect.hpp"
#include "sim/event_queue.hpp"
#include "sim/neighbourhood.hpp"
#include "sim/setup.hpp"

namespace tripack::sim_detail {

template <class... Effects>
class Engine {
  static constexpr std::size_t grower_index() {
    constexpr bool grows[] = {Effects::kGrows..., false};
    std::size_t i = 0;
    while (i < sizeof...(Effects) && !grows[i]) ++i;
    return i;
  }
  static constexpr std::size_t kGrower = grower_index();

 public:
  // Whether an effect grows the disks; without one the rate is 0 at compile time.
  static constexpr bool kGrows = kGrower < sizeof...(Effects);
  static_assert((0 + ... + int(Effects::kGrows)) <= 1, "at most one effect sets the growth rate");
  static constexpr bool kHasHorizon = (false || ... || Effects::kHasHorizon);

  Engine(Setup s, const BilliardsOptions& o, Effects... effects)
      : opt_(o), stop_(s.stop), n_(int(s.x.size())), fx_(std::move(effects)...) {
    diam0_ = s.diam0;
    disks_.resize(std::size_t(n_));
    traj_.assign(std::size_t(n_), 0);
    for (int i = 0; i < n_; ++i) {
      disks_[std::size_t(i)].x0 = s.x[std::size_t(i)];  // the clock starts at 0
      disks_[std::size_t(i)].v = is_pinned(i) ? Vec2{} : s.v[std::size_t(i)];
    }
    nb_.build(disks_, now_, diameter(now_), std::max(s.diam_cap, s.diam0) * (1 + 1e-9));
    block_events_ = std::max<std::uint64_t>(20 * std::uint64_t(n_), 2000);
  }

  BilliardsResult run() {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    BilliardsResult r;
    each_effect([&](auto& fx) { fx.on_start(*this); });
    r.kinetic_energy_start = kinetic_energy();
    block_stats_.energy_start = 2 * r.kinetic_energy_start;
    rebuild_heap();
    std::uint64_t since_block = 0;  // events
    double next_progress = opt_.progress_seconds;
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
      if constexpr (kHasHorizon) {
        if (const auto [until, why] = horizon(); e.t > until) {
          now_ = std::max(now_, until);
          stop(why.why, why.jammed);
          break;
        }
      }
      now_ = e.t;
      if (e.j >= 0 && e.traj != traj_[std::size_t(e.j)]) {  // partner changed course: re-plan
        predict(e.i);
        continue;
      }
      ++r.events;
      ++since_block;
      if (e.j >= 0) {
        collide(e.i, e.j);
        ++r.collisions;
        each_effect([&](auto& fx) { fx.on_collision(e.i, e.j); });
        record(r, e.i, e.j);
        predict(e.i);
        predict(e.j);
      } else if (e.j >= -3) {
        bounce(e.i, static_cast<Side>(-1 - e.j));
        ++r.collisions;
        each_effect([&](auto& fx) { fx.on_collision(e.i, e.j); });
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
        throw_if_abandoned(opt_.cancel);
        const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        if (elapsed > stop_.max_seconds) {
          stop("max seconds", false);
          break;
        }
        if (opt_.progress && elapsed >= next_progress) {
          next_progress = elapsed + opt_.progress_seconds;
          Progress p;
          p.stage = "billiards";
          p.events = r.events;
          p.elapsed = elapsed;
          p.d = d_from_diameter(diameter(now_));
          p.relative_gap = gap_;
          opt_.progress(p);
        }
      }
      const bool requested = (false || ... || std::get<Effects>(fx_).sync_due());
      if (since_block >= block_events_ || requested) {
        block_stats_.time += now_;
        bool replan = sync();
        if (since_block >= block_events_) {
          if (const std::optional<Stop> verdict = block_end()) {
            stop(verdict->why, verdict->jammed);
            break;
          }
          block_stats_ = {0, 0, -1};
          since_block = 0;
        } else if constexpr (!kGrows) {
          since_block = 0;  // nothing reads the block statistics: a block is the time since a sync
        }
        each_effect([&](auto& fx) { replan = fx.at_sync(*this) || replan; });
        replan = std::exchange(rate_changed_, false) || replan;
        if (block_stats_.energy_start < 0) block_stats_.energy_start = 2 * kinetic_energy();
        if (replan) rebuild_heap();  // else the shifted predictions still hold
      }
    }
    sync();
    r.max_overlap = std::max(r.max_overlap, max_overlap());
    r.time = t_base_;
    r.diameter = diameter(0);
    r.relative_gap = gap_;
    r.kinetic_energy_end = kinetic_energy();
    r.growth_rate = rate();
    each_effect([&](const auto& fx) { fx.at_end(*this, r); });
    r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    for (const auto& d : disks_) {
      r.positions.push_back(d.x0);  // synced: the clock is at 0
      r.velocities.push_back(d.v);
    }
    return r;
  }

  // --- what the effects' hooks may use ---
  int size() const { return n_; }
  // Diameter at engine time t (the clock restarts at every sync).
  double diameter(double t) const {
    if constexpr (kGrows)
      return diam0_ + rate() * t;
    else
      return (void)t, diam0_;
  }
  double rate() const {
    if constexpr (kGrows)
      return std::get<kGrower>(fx_).rate();
    else
      return 0;
  }
  // The growing effect changed rate(), at a block end or sync (the clock was just restarted, so
  // diameter(t) = diameter(0) + rate() t holds from there): the effects are told and the
  // predictions redone.
  void rate_changed() {
    rate_changed_ = true;
    each_effect([&](auto& fx) { fx.on_rate_change(*this); });
  }
  Vec2 position(int i) const { return position(disks_[std::size_t(i)]); }
  double kinetic_energy() const {
    double e = 0;
    for (const auto& d : disks_) e += dot(d.v, d.v) / 2;
    return e;
  }
  // Multiplies every velocity by s (at a sync: then the predictions must be redone).
  void scale_velocities(double s) {
    for (auto& d : disks_) set_velocity(d, position(d), d.v * s);
    for (auto& t : traj_) ++t;
  }
  const StopRules& stop_rules() const { return stop_; }
  const BlockStatistics& block() const { return block_stats_; }
  // The estimated relative gap to jamming 1 - D / D_jam (1 until an effect estimates it).
  double relative_gap() const { return gap_; }
  void set_relative_gap(double gap) { gap_ = gap; }

 private:
  template <class F>
  void each_effect(F&& f) {
    std::apply([&](auto&... fx) { (f(fx), ...); }, fx_);
  }
  template <class F>
  void each_effect(F&& f) const {
    std::apply([&](const auto&... fx) { (f(fx), ...); }, fx_);
  }
  bool is_pinned(int i) const {
    return std::apply([&](const auto&... fx) { return (false || ... || fx.is_pinned(i)); }, fx_);
  }
  // The earliest of the effects' horizons and its stop reason.
  std::pair<double, Stop> horizon() const {
    std::pair<double, Stop> earliest{kInf, {}};
    each_effect([&](const auto& fx) {
      if constexpr (std::decay_t<decltype(fx)>::kHasHorizon)
        if (fx.horizon() < earliest.first) earliest = {fx.horizon(), fx.kHorizonStop};
    });
    return earliest;
  }
  // The first effect's verdict at a block end; later effects are not asked once one stops.
  std::optional<Stop> block_end() {
    std::optional<Stop> verdict;
    std::apply([&](auto&... fx) { (void)(false || ... || (verdict = fx.at_block_end(*this))); },
               fx_);
    return verdict;
  }
  Vec2 position(const Disk& d) const { return d.x0 + d.v * now_; }
  // A new velocity from now on, the position at now kept.
  void set_velocity(Disk& d, Vec2 x, Vec2 v) {
    d.v = v;
    d.x0 = x - v * now_;
  }

  // --- neighbourhoods ---
  // Update event: disk i reached the edge of its neighbourhood; give it a new one.
  void relist(int i) {
    const Vec2 x = position(disks_[std::size_t(i)]);
    each_effect([&](auto& fx) { fx.on_disk_at(i, x); });
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
    each_effect([&](auto& fx) {
      fx.on_disk_at(i, xa);
      fx.on_disk_at(j, xb);
    });
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
      if constexpr (!kGrows) {  // remove the rounding bias of the energy (~0.4 ulp a collision)
        // v (1 + delta), added rather than multiplied: a factor next to 1 rounds with a bias.
        const double e1 = dot(va, va) + dot(vb, vb), delta = (e0 - e1) / (2 * e1);
        va += va * delta;
        vb += vb * delta;
      }
      // Virial r . dp: the momentum k dist moved across distance D (twice against a pinned disk).
      block_stats_.virial += diameter(now_) * k * dist * (is_pinned(i) || is_pinned(j) ? 2 : 1);
      set_velocity(a, xa, va);
      set_velocity(b, xb, vb);
    }
    ++traj_[std::size_t(i)];
    ++traj_[std::size_t(j)];
  }
  void bounce(int i, Side side) {
    auto& d = disks_[std::size_t(i)];
    const Vec2 x = position(d);
    each_effect([&](auto& fx) { fx.on_disk_at(i, x); });
    const Vec2 nrm = wall_normal<double>(side);
    Vec2 v = d.v;
    const double vn = dot(v, nrm), g = rate();
    const double target = std::max(g - vn, g / 2);
    if (target > vn) {
      [[maybe_unused]] const double e0 = dot(v, v);
      v += nrm * (-2 * vn / dot(nrm, nrm) + (target + vn));
      if constexpr (!kGrows) {
        const double e1 = dot(v, v);
        v += v * ((e0 - e1) / (2 * e1));
      }
      block_stats_.virial += diameter(now_) * (target - vn);
      set_velocity(d, x, v);
    }
    ++traj_[std::size_t(i)];
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
    each_effect([&](auto& fx) { fx.on_clock_restart(now_); });
    now_ = 0;
    if (diam0_ <= nb_.diam_max()) return false;
    nb_.build(disks_, now_, diameter(now_), 2 * diam0_);  // a start beyond Oler's bound
    return true;
  }
  void rebuild_heap() {
    heap_.reset(n_);
    for (int i = 0; i < n_; ++i) predict(i);
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
  BilliardsOptions opt_;
  StopRules stop_;
  int n_;
  std::tuple<Effects...> fx_;
  std::vector<Disk> disks_;
  Neighbourhoods nb_;
  std::vector<std::uint32_t> traj_;
  EventQueue heap_;
  std::vector<Vec2> check_x_;  // max_overlap_all_pairs' positions
  double diam0_ = 0, now_ = 0, t_base_ = 0;
  std::uint64_t block_events_ = 0;  // events per block
  BlockStatistics block_stats_;
  double gap_ = 1;
  bool rate_changed_ = false;
};

}  // namespace tripack::sim_detail
