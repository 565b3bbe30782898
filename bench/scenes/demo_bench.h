// contactfx benchmarks: what the whole effects layer costs in the tutorial scene.
//
// The tutorial scene driven by the demo's script, timed twice with the same drive: once as Box2D alone
// (world.Step, no effects attached: no contact listener, no emission, no particles), once with the
// effects layer (world.Step with the tracker listening, then Effects::Step: pruning, emission, spawn
// placement, particles). The difference is what contactfx adds to a step.
#pragma once

#include "contactfx/config.h"

#include <cstdint>
#include <filesystem>

namespace cfx::bench
{

struct DemoBenchResult
{
    std::uint32_t steps = 0;
    double worldAloneMsMin = 0.0, worldAloneMsMedian = 0.0;   ///< world.Step, no effects
    double withEffectsMsMin = 0.0, withEffectsMsMedian = 0.0; ///< world.Step + Effects::Step
    double effectsStepMsMin = 0.0, effectsStepMsMedian = 0.0; ///< Effects::Step alone, in that run
    std::uint32_t liveMax = 0;                                ///< most live particles
    std::uint64_t spawned = 0;                                ///< particles emitted in all
};

/// Runs `steps` steps of 1/hz s of `scene` (a RUBE file with a car) under the demo's drive.
DemoBenchResult MeasureDemo(const std::filesystem::path& scene, const EffectsConfig& config, float hz,
                            std::uint32_t steps);

} // namespace cfx::bench
