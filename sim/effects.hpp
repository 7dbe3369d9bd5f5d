// The billiards effects that act outside the engine's event loop: the container's diameter
// bound, the growth schedule's rate choice (at block ends), and shaking at fixed size with its
// rattler test. Kept out of sim/engine.hpp: none of it is on the hot path.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "sim/billiards.hpp"
#include "sim/scene.hpp"

namespace tripack::sim_detail {

// Upper bound of the container diameter from Oler's bound (d <= 1/t(n)); the cell size.
double diameter_cap(int n);

// Growth schedule: the rate of the last step whose gap the estimate `gap` is below (base_rate
// when none).
double scheduled_rate(double base_rate, const std::vector<GrowthStep>& schedule, double gap);

// Shaking at fixed size: an elastic run from the state in r (engine numbering) for per_disk * n
// collisions with fresh random unit velocities, recording each disk's path extent in
// r.excursion. The state in r is left as it was (shaking is a diagnostic).
void shake(BilliardsResult& r, const ShakeEffect& fx, const std::vector<char>& pinned,
           double diam_cap, std::mt19937_64& rng, const BilliardsOptions& options);

// The rattlers of a shake: the disks (not pinned) that collided more than rattler_factor times
// less often than the median disk.
std::vector<int> shake_rattlers(const std::vector<std::uint64_t>& hits, double rattler_factor,
                                const std::vector<int>& pinned);

}  // namespace tripack::sim_detail
