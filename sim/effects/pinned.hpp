// Effect `pinned`: these disks never move (infinite mass). Growth must stop once two pinned
// disks, or a pinned disk and a wall, touch: nothing can move them apart.
#pragma once

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <string>
#include <vector>

#include "sim/effect.hpp"
#include "sim/event_queue.hpp"  // kInf
#include "sim/scene_yaml.hpp"
#include "sim/setup.hpp"

namespace tripack::sim_detail {

class Pinned : public EffectHooks {
 public:
  static constexpr const char* kKey = "pinned";
  static constexpr bool kHasHorizon = true;
  static constexpr Stop kHorizonStop{"pinned disks touch", true};

  static void parse(const YAML::Node& node, Scene& s) {
    if (!node.IsSequence()) scene_error("effects.pinned must be a list of disk indices");
    for (const auto& i : node) s.pinned.push_back(scalar<int>(i, "a pinned index"));
  }
  static void validate(const Scene& s) {
    for (int i : s.pinned)
      if (i < 0 || i >= s.n) scene_error("pinned index " + std::to_string(i) + " out of range");
  }
  static bool active(const Scene& s) { return !s.pinned.empty(); }
  static std::string describe(const Scene& s) {
    return fmt::format("pinned disks {}", fmt::join(s.pinned, " "));
  }

  static Pinned for_run(const RunStart& start) {
    std::vector<char> by_scene_index(start.order.size(), 0);
    for (int i : start.scene.pinned) by_scene_index[std::size_t(i)] = 1;
    Pinned p;
    for (int i : start.order) p.pinned_.push_back(by_scene_index[std::size_t(i)]);
    return p;
  }

  bool is_pinned(int i) const { return pinned_[std::size_t(i)] != 0; }
  double horizon() const { return limit_; }
  template <class E>
  void on_start(E& engine) {
    limit_ = touching_time(engine);
  }
  template <class E>
  void on_rate_change(E& engine) {
    limit_ = touching_time(engine);
  }
  void on_clock_restart(double elapsed) { limit_ -= elapsed; }

 private:
  // When (engine clock, at time 0) growth makes two pinned disks or a pinned disk and a wall
  // touch; infinite without growth.
  template <class E>
  double touching_time(const E& engine) const {
    double dmax = kInf;
    for (int i = 0; i < engine.size(); ++i) {
      if (!is_pinned(i)) continue;
      const Vec2 xi = engine.position(i);
      for (Side s : kSides) dmax = std::min(dmax, 2 * wall_distance(xi, s, 1.0));
      for (int j = i + 1; j < engine.size(); ++j)
        if (is_pinned(j)) dmax = std::min(dmax, norm(engine.position(j) - xi));
    }
    if (engine.rate() <= 0 || dmax == kInf) return kInf;
    return std::max(dmax - engine.diameter(0), 0.0) / engine.rate();
  }

  std::vector<char> pinned_;  // per disk, engine numbering
  double limit_ = kInf;       // touching_time, on the engine clock
};

}  // namespace tripack::sim_detail
