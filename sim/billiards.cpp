// run_billiards: a scene's start state in container units (random or given points and
// velocities), the engine's Z-order numbering of the disks, the dispatcher that picks the engine
// instantiation for the run's effects, and the mapping of the results back to the scene (disk
// numbering, Packing convention). The only translation unit that includes sim/engine.hpp: the
// engine is compiled here, with -fno-math-errno -fno-trapping-math (CMakeLists.txt).
#include "sim/billiards.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/effects.hpp"
#include "sim/engine.hpp"
#include "sim/setup.hpp"

namespace tripack {
namespace sim_detail {

template <bool G, bool T, bool P, bool S = false>
BilliardsResult run_engine(Setup s, const BilliardsOptions& o) {
  return Engine<G, T, P, S>(std::move(s), o).run();
}
// The engine compiled for exactly the effects a run needs (the shaking engine never grows);
// declared in sim/setup.hpp.
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
template <class T>
std::vector<T> unpermuted(const std::vector<T>& v, const std::vector<int>& order) {
  std::vector<T> out(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) out[std::size_t(order[k])] = v[k];
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
    r.shake_rattlers = shake_rattlers(r.shake_hits, scene.shake->rattler_factor, scene.pinned);
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
