// Effect `growth`: the Lubachevsky-Stillinger compression (docs/billiards.md). Every diameter
// grows at `rate`; at each block end (every 20 n events, where the clock restarts) the collision
// virial of the block gives the reduced pressure p and the estimated relative gap to jamming
// 2 / p, which ends the run (stop.relative_gap, stop.pressure, or growth below the precision of
// double) and picks the schedule's rate.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "sim/effect.hpp"
#include "sim/effects.hpp"
#include "sim/scene_yaml.hpp"
#include "sim/setup.hpp"

namespace tripack::sim_detail {

class Growth : public EffectHooks {
 public:
  static constexpr const char* kKey = "growth";
  static constexpr bool kGrows = true;

  static void parse(const YAML::Node& node, Scene& s) {
    s.growth = GrowthEffect{};
    if (!has_options(node, {"rate", "schedule"}, "effects.growth")) return;
    if (node["rate"]) s.growth->rate = scalar<double>(node["rate"], "growth.rate");
    const auto schedule = node["schedule"];
    if (!schedule) return;
    if (!schedule.IsSequence())
      scene_error("growth.schedule must be a list of {pressure|gap, rate}");
    for (const auto& step : schedule) {
      check_keys(step, {"pressure", "gap", "rate"}, "a growth.schedule step");
      if (!step["rate"] || (!step["pressure"] == !step["gap"]))
        scene_error("a growth.schedule step needs rate and one of pressure or gap");
      GrowthStep st;
      st.rate = scalar<double>(step["rate"], "growth.schedule rate");
      if (step["gap"]) {
        st.gap = scalar<double>(step["gap"], "growth.schedule gap");
      } else {
        const double p = scalar<double>(step["pressure"], "growth.schedule pressure");
        if (!(p > 2 && std::isfinite(p))) scene_error("growth.schedule pressure must be > 2");
        st.gap = 2 / p;  // free-volume estimate: 1 - D/D_jam = 2 / p
      }
      s.growth->schedule.push_back(st);
    }
    std::stable_sort(s.growth->schedule.begin(), s.growth->schedule.end(),
                     [](const GrowthStep& a, const GrowthStep& b) { return a.gap > b.gap; });
  }

  static void validate(const Scene& s) {
    if (!s.growth) return;
    if (!(s.growth->rate >= 0 && std::isfinite(s.growth->rate)))
      scene_error("growth rate must be finite and >= 0");
    for (const auto& st : s.growth->schedule) {
      if (!(st.gap > 0 && st.gap < 1)) scene_error("growth.schedule gap must be in (0, 1)");
      if (!(st.rate > 0 && std::isfinite(st.rate)))
        scene_error("growth.schedule rate must be finite and > 0");
    }
  }

  // Growth without velocity rescaling pumps kinetic energy into every collision: measured at
  // n = 10, 22, 40 and 60, such runs never reach their stop gap (15 M events in 2 s, stuck near
  // jamming) and end only at max_seconds. A YAML scene must name the thermostat with growth.
  static void after_parse(const Scene& s) {
    if (s.growth && !s.thermostat && s.stop.max_collisions == 0)
      scene_error(
          "growth needs a thermostat (add `thermostat: {}`): without rescaling the kinetic energy "
          "grows at every collision and the run never reaches its stop gap");
  }

  static bool active(const Scene& s) { return s.growth && s.growth->rate > 0; }

  static std::string describe(const Scene& s) {
    std::string line = fmt::format("growth at rate {:g}", s.growth->rate);
    for (const auto& st : s.growth->schedule)
      line += fmt::format(", {:g} below an estimated gap of {:g}", st.rate, st.gap);
    return line;
  }

  static Growth for_run(const RunStart& start) {
    return active(start.scene) ? Growth(start.scene.growth->rate, start.scene.growth->schedule)
                               : Growth(0, {});
  }

  double rate() const { return rate_; }

  template <class E>
  void on_start(E& engine) {
    block_diameter_ = engine.diameter(0);
  }

  template <class E>
  std::optional<Stop> at_block_end(E& engine) {
    const double d = engine.diameter(0);
    const BlockStatistics& block = engine.block();
    const double e2 = (block.energy_start + 2 * engine.kinetic_energy()) / 2;  // mean sum v^2
    // Free-volume estimate (2D): reduced pressure p = sum(D J) / (2 N kT dt) with kT = <v^2>/2,
    // and 1 - D/D_jam = 2/p = 2 sum(v^2) dt / sum(D J).
    if (block.virial > 0 && rate_ > 0) engine.set_relative_gap(2 * e2 * block.time / block.virial);
    const double gap = engine.relative_gap();
    const StopRules& stop = engine.stop_rules();
    if (gap < stop.relative_gap) return Stop{"relative gap reached", true};
    if (stop.pressure > 0 && 2 / gap > stop.pressure) return Stop{"pressure reached", true};
    // Growth below rounding for several blocks: the precision limit of double.
    const bool stalled =
        rate_ > 0 && d - block_diameter_ <= 8 * std::numeric_limits<double>::epsilon() * d;
    stalls_ = stalled ? stalls_ + 1 : 0;
    if (stalls_ >= 3) return Stop{"growth stalled at the precision limit", true};
    block_diameter_ = d;
    // The schedule: the rate of the last step whose gap the estimate is below. The clock was
    // just restarted (diameter = diam0 + rate t from t = 0), so the rate may change here.
    const double want = scheduled_rate(base_rate_, schedule_, gap);
    if (want != rate_) {
      rate_ = want;
      engine.rate_changed();
    }
    return std::nullopt;
  }

 private:
  Growth(double rate, std::vector<GrowthStep> schedule)
      : base_rate_(rate), rate_(rate), schedule_(std::move(schedule)) {}

  double base_rate_, rate_;
  std::vector<GrowthStep> schedule_;  // by decreasing gap
  double block_diameter_ = 0;         // at the last block end
  std::uint64_t stalls_ = 0;          // blocks in a row without growth
};

}  // namespace tripack::sim_detail
