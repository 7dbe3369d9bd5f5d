// The effects a scene may name, in the order they are parsed, validated, described and handed
// to the engine (sim/effect.hpp says what an effect is). A new effect is added here.
#pragma once

#include "sim/effect.hpp"
#include "sim/effects/growth.hpp"
#include "sim/effects/pinned.hpp"
#include "sim/effects/shake.hpp"
#include "sim/effects/thermostat.hpp"

namespace tripack::sim_detail {

using SceneEffects = EffectList<Growth, Thermostat, Shake, Pinned>;

}  // namespace tripack::sim_detail
