// run_billiards: a scene's start state in container units (random or given points and
// velocities), the engine's Z-order numbering of the disks, the dispatcher that compiles the
// engine for the run's effects, the effects' own phases (shaking), and the mapping of the results
// back to the scene (disk numbering, Packing convention). The only translation unit that includes
// sim/engine.hpp: the engine is compiled here, with -fno-math-errno -fno-trapping-math
// (CMakeLists.txt).
#include "sim/billiards.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "sim/effect_list.hpp"
#include "sim/effects.hpp"
#include "sim/engine.hpp"
#include "sim/setup.hpp"

namespace tripack {
namespace sim_detail {

// An effect with per-run engine state takes part in the main phase; one with a phase of its own
// runs it after that.
template <class P>
concept InMainPhase = requires(const RunStart& start) {
  P::for_run(start);
};
template <class P>
concept WithOwnPhase = requires(BilliardsResult& r, const RunStart& start) {
  P::template after_run<Engine>(r, start);
};
template <class P>
concept ReplacingMainPhase = requires(const Scene& s) {
  P::replaces_main_phase(s);
};

// The main phase: walks the effect list and runs the engine compiled for the effects the scene
// uses (every effect with options.all_policies), so 2^k instantiations for k main-phase effects.
template <class... Chosen>
BilliardsResult run_main_phase(EffectList<>, const RunStart& start, Setup s, Chosen&&... chosen) {
  return Engine<std::decay_t<Chosen>...>(std::move(s), start.options,
                                         std::forward<Chosen>(chosen)...)
      .run();
}
template <class First, class... Rest, class... Chosen>
BilliardsResult run_main_phase(EffectList<First, Rest...>, const RunStart& start, Setup s,
                               Chosen&&... chosen) {
  if constexpr (InMainPhase<First>) {
    if (First::active(start.scene) || start.options.all_policies)
      return run_main_phase(EffectList<Rest...>{}, start, std::move(s),
                            std::forward<Chosen>(chosen)..., First::for_run(start));
  }
  return run_main_phase(EffectList<Rest...>{}, start, std::move(s),
                        std::forward<Chosen>(chosen)...);
}

template <class... Policies>
void run_own_phases(EffectList<Policies...>, BilliardsResult& r, const RunStart& start) {
  const auto run = [&]<class P>() {
    if constexpr (WithOwnPhase<P>)
      if (P::active(start.scene)) P::template after_run<Engine>(r, start);
  };
  (run.template operator()<Policies>(), ...);
}

// The key of the effect that runs instead of the main phase, or nullptr.
template <class... Policies>
const char* replacing_effect(EffectList<Policies...>, const Scene& scene) {
  const char* key = nullptr;
  const auto find = [&]<class P>() {
    if constexpr (ReplacingMainPhase<P>)
      if (P::active(scene) && P::replaces_main_phase(scene)) key = P::kKey;
  };
  (find.template operator()<Policies>(), ...);
  return key;
}

}  // namespace sim_detail

namespace {

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

}  // namespace

BilliardsResult run_billiards(const Scene& scene, std::mt19937_64& rng,
                              const BilliardsOptions& options) {
  using namespace sim_detail;
  validate_scene(scene);
  const int n = scene.n;
  Setup s;
  s.stop = scene.stop;
  s.diam_cap = diameter_cap(n);
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
  s.v = scene.velocities.empty() ? random_unit_velocities(std::size_t(n), rng) : scene.velocities;

  // The engine numbers disks along a Z-order curve of their start cells, so neighbours sit close
  // in memory; everything it returns is mapped back to the scene's numbering.
  const RunStart start{scene, spatial_order(s.x, s.diam_cap), s.diam_cap, rng, options};
  s.x = permuted(s.x, start.order);
  s.v = permuted(s.v, start.order);
  const std::size_t traced = options.trace ? options.trace->size() : 0;

  BilliardsResult r;
  if (const char* instead = replacing_effect(SceneEffects{}, scene)) {
    r.positions = s.x;
    r.velocities = s.v;
    r.diameter = s.diam0;
    r.stop_reason = std::string(instead) + " only";
  } else {
    r = run_main_phase(SceneEffects{}, start, std::move(s));
  }
  run_own_phases(SceneEffects{}, r, start);
  r.positions = start.to_scene_numbering(r.positions);
  r.velocities = start.to_scene_numbering(r.velocities);
  if (options.trace)
    for (std::size_t k = traced; k < options.trace->size(); ++k) {
      auto& e = (*options.trace)[k];
      e.i = start.order[std::size_t(e.i)];
      if (e.partner >= 0) e.partner = start.order[std::size_t(e.partner)];
    }
  // Map the centres' triangle (inset by diam/2) onto the unit triangle.
  const long double diam = r.diameter, rad = diam / 2, side = 1 - kSqrt3 * diam;
  r.packing.d = d_from_diameter(diam);
  for (const auto& x : r.positions)
    r.packing.points.push_back({(x.x - kSqrt3 * rad) / side, (x.y - rad) / side});
  return r;
}

}  // namespace tripack
