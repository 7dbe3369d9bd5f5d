// The effects' helpers outside the engine (see sim/effects.hpp).
#include "sim/effects.hpp"

#include <algorithm>
#include <cmath>

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

std::vector<Vec2> random_unit_velocities(std::size_t n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u01(0, 1);
  std::vector<Vec2> v;
  v.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double phi = 2 * M_PI * u01(rng);
    v.push_back({std::cos(phi), std::sin(phi)});
  }
  return v;
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
