// Effect `thermostat`: the kinetic energy rescaled to its start value every `every` collisions
// (0: 10 n). Growth pumps energy into every collision; without rescaling a compression never
// reaches its stop gap (sim/effects/growth.hpp).
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "sim/effect.hpp"
#include "sim/scene_yaml.hpp"
#include "sim/setup.hpp"

namespace tripack::sim_detail {

class Thermostat : public EffectHooks {
 public:
  static constexpr const char* kKey = "thermostat";

  static void parse(const YAML::Node& node, Scene& s) {
    s.thermostat = ThermostatEffect{};
    if (!has_options(node, {"every"}, "effects.thermostat")) return;
    if (node["every"]) s.thermostat->every = count(node["every"], "thermostat.every");
  }
  static void validate(const Scene&) {}
  static bool active(const Scene& s) { return s.thermostat.has_value(); }
  static std::string describe(const Scene& s) {
    return s.thermostat->every ? fmt::format("thermostat every {} collisions", s.thermostat->every)
                               : fmt::format("thermostat every 10 n = {} collisions", 10 * s.n);
  }

  static Thermostat for_run(const RunStart& start) {
    const Scene& s = start.scene;
    if (!active(s)) return Thermostat(std::numeric_limits<std::uint64_t>::max());
    return Thermostat(s.thermostat->every ? s.thermostat->every : 10 * s.n);
  }

  template <class E>
  void on_start(E& engine) {
    target_ = 2 * engine.kinetic_energy();
  }
  void on_collision(int, int) { ++since_; }
  bool sync_due() const { return since_ >= every_; }
  template <class E>
  bool at_sync(E& engine) {
    if (since_ < every_) return false;
    const double e = 2 * engine.kinetic_energy();
    if (e > 0 && target_ > 0) engine.scale_velocities(std::sqrt(target_ / e));
    since_ = 0;
    return true;
  }

 private:
  explicit Thermostat(std::uint64_t every) : every_(every) {}

  std::uint64_t every_, since_ = 0;  // collisions between rescalings, and since the last
  double target_ = 0;                // 2 x the start kinetic energy
};

}  // namespace tripack::sim_detail
