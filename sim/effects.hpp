// The effects' helpers that are not engine hooks: the container's diameter bound, the growth
// schedule's rate choice, fresh random velocities and the shake's rattler test. The effects
// themselves are policy types (sim/effect.hpp, sim/effects/*.hpp, listed in sim/effect_list.hpp).
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

// n velocities of unit speed in uniformly random directions.
std::vector<Vec2> random_unit_velocities(std::size_t n, std::mt19937_64& rng);

// The rattlers of a shake: the disks (not pinned) that collided more than rattler_factor times
// less often than the median disk.
std::vector<int> shake_rattlers(const std::vector<std::uint64_t>& hits, double rattler_factor,
                                const std::vector<int>& pinned);

}  // namespace tripack::sim_detail
