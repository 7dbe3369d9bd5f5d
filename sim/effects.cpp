// Effects outside the event loop (see sim/effects.hpp).
#include "sim/effects.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/setup.hpp"

namespace tripack::sim_detail {

double diameter_cap(int n) {
  if (n == 1) return 1 / std::sqrt(3.0);  // the inscribed disk
  const double t = (-3 + std::sqrt(8.0 * n + 1)) / 2;
  const double d = std::min(1.0, 1 / t);
  return d / (1 + std::sqrt(3.0) * d);
}

double scheduled_rate(double base_rate, const std::vector<GrowthStep>& schedule, double gap) {
  double want = base_rate;
  for (const auto& step : schedule)
    if (gap < step.gap) want = step.rate;
  return want;
}

void shake(BilliardsResult& r, const ShakeEffect& fx, const std::vector<char>& pinned,
           double diam_cap, std::mt19937_64& rng, const BilliardsOptions& options) {
  Setup s;
  const std::size_t n = r.positions.size();
  s.x = r.positions;
  s.pinned = pinned;
  s.diam0 = double(r.diameter);
  s.diam_cap = std::max(diam_cap, s.diam0);
  std::uniform_real_distribution<double> u01(0, 1);
  for (std::size_t i = 0; i < n; ++i) {
    const double phi = 2 * M_PI * u01(rng);
    s.v.push_back({std::cos(phi), std::sin(phi)});
  }
  s.thermostat_every = std::numeric_limits<std::uint64_t>::max();
  s.stop.max_collisions = fx.per_disk * n;
  s.stop.max_seconds = r.seconds > 0 ? std::max(60.0, 10 * r.seconds) : 600;
  BilliardsOptions o = options;
  o.trace = nullptr;  // the trace is the main phase's
  o.all_policies = false;
  const bool any_pinned = std::find(pinned.begin(), pinned.end(), 1) != pinned.end();
  const BilliardsResult shaken = run_engine_for(false, false, any_pinned, true, std::move(s), o);
  r.excursion = shaken.excursion;
  r.shake_hits = shaken.shake_hits;
  r.shake_collisions = shaken.collisions;
  r.shake_seconds = shaken.seconds;
  r.max_overlap = std::max(r.max_overlap, shaken.max_overlap);
}

// Rattlers collide far less often than the median disk: a jammed disk bounces across the
// remaining gap, a rattler across its cage.
std::vector<int> shake_rattlers(const std::vector<std::uint64_t>& hits, double rattler_factor,
                                const std::vector<int>& pinned) {
  std::vector<std::uint64_t> sorted = hits;
  std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2),
                   sorted.end());
  const double median = double(sorted[sorted.size() / 2]);
  std::vector<int> rattlers;
  for (int i = 0; i < int(hits.size()); ++i)
    if (double(hits[std::size_t(i)]) * rattler_factor < median &&
        !(std::find(pinned.begin(), pinned.end(), i) != pinned.end()))
      rattlers.push_back(i);
  return rattlers;
}

}  // namespace tripack::sim_detail
