// Effect `shake`: shaking at fixed size after the growth phase (or instead of it, without
// growth): an elastic run of per_disk * n collisions from fresh random unit velocities that
// counts each disk's collisions and measures its path extent. A rattler collides far less often
// than the median disk (a jammed disk bounces across the remaining gap, a rattler across its
// cage). The result keeps the state before shaking.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "sim/effect.hpp"
#include "sim/effects.hpp"
#include "sim/effects/growth.hpp"
#include "sim/effects/pinned.hpp"
#include "sim/scene_yaml.hpp"
#include "sim/setup.hpp"

namespace tripack::sim_detail {

// The shaking run's engine hooks: each disk's collisions and the box its path spans.
class ShakeTrack : public EffectHooks {
 public:
  explicit ShakeTrack(const std::vector<Vec2>& start)
      : lo_(start), hi_(start), hits_(start.size(), 0) {}

  void on_disk_at(int i, Vec2 x) {
    auto& lo = lo_[std::size_t(i)];
    auto& hi = hi_[std::size_t(i)];
    lo = {std::min(lo.x, x.x), std::min(lo.y, x.y)};
    hi = {std::max(hi.x, x.x), std::max(hi.y, x.y)};
  }
  void on_collision(int i, int j) {
    ++hits_[std::size_t(i)];
    if (j >= 0) ++hits_[std::size_t(j)];
  }
  template <class E>
  void at_end(const E& engine, BilliardsResult& r) const {
    const double D = engine.diameter(0);
    for (std::size_t i = 0; i < lo_.size(); ++i) {
      const Vec2 e = hi_[i] - lo_[i];
      r.excursion.push_back(D > 0 ? std::max(e.x, e.y) / D : 0.0);
    }
    r.shake_hits = hits_;
  }

 private:
  std::vector<Vec2> lo_, hi_;
  std::vector<std::uint64_t> hits_;
};

class Shake : public EffectHooks {
 public:
  static constexpr const char* kKey = "shake";

  static void parse(const YAML::Node& node, Scene& s) {
    s.shake = ShakeEffect{};
    if (!has_options(node, {"per_disk", "rattler_factor"}, "effects.shake")) return;
    if (node["per_disk"]) s.shake->per_disk = count(node["per_disk"], "shake.per_disk");
    if (node["rattler_factor"])
      s.shake->rattler_factor = scalar<double>(node["rattler_factor"], "shake.rattler_factor");
  }
  static void validate(const Scene& s) {
    if (s.shake && s.shake->per_disk == 0) scene_error("shake.per_disk must be at least 1");
    if (s.shake && !(s.shake->rattler_factor > 1 && std::isfinite(s.shake->rattler_factor)))
      scene_error("shake.rattler_factor must be finite and > 1");
  }
  static bool active(const Scene& s) { return s.shake.has_value(); }
  static std::string describe(const Scene& s) {
    return fmt::format("shake {} collisions per disk (rattlers: {:g}x fewer than the median disk)",
                       s.shake->per_disk, s.shake->rattler_factor);
  }

  // Without growth a shaking scene only shakes.
  static bool replaces_main_phase(const Scene& s) { return !Growth::active(s); }

  // Shakes the end state in r (engine numbering) and adds the shake's outputs, in scene
  // numbering, to r.
  template <template <class...> class Engine>
  static void after_run(BilliardsResult& r, const RunStart& start) {
    const ShakeEffect& fx = *start.scene.shake;
    Setup s;
    const std::size_t n = r.positions.size();
    s.x = r.positions;
    s.diam0 = double(r.diameter);
    s.diam_cap = std::max(start.diam_cap, s.diam0);
    s.v = random_unit_velocities(n, start.rng);
    s.stop.max_collisions = fx.per_disk * n;
    s.stop.max_seconds = r.seconds > 0 ? std::max(60.0, 10 * r.seconds) : 600;
    BilliardsOptions o = start.options;
    o.trace = nullptr;  // the trace is the main phase's
    o.all_policies = false;
    ShakeTrack track(s.x);
    const BilliardsResult shaken =
        Pinned::active(start.scene)
            ? Engine<Pinned, ShakeTrack>(std::move(s), o, Pinned::for_run(start), std::move(track))
                  .run()
            : Engine<ShakeTrack>(std::move(s), o, std::move(track)).run();
    r.excursion = start.to_scene_numbering(shaken.excursion);
    r.shake_hits = start.to_scene_numbering(shaken.shake_hits);
    r.shake_collisions = shaken.collisions;
    r.shake_seconds = shaken.seconds;
    r.max_overlap = std::max(r.max_overlap, shaken.max_overlap);
    r.shake_rattlers = shake_rattlers(r.shake_hits, fx.rattler_factor, start.scene.pinned);
  }
};

}  // namespace tripack::sim_detail
