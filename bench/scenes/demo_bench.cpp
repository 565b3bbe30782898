// contactfx benchmarks: the tutorial scene with and without effects (see demo_bench.h).
#include "scenes/demo_bench.h"

#include "contactfx/effects.h"
#include "contactfx/scene/rube.h"
#include "harness/car.h"
#include "harness/simulation.h"
#include "scenes/timing.h"

#include <algorithm>
#include <box2d/b2_world.h>
#include <chrono>
#include <memory>
#include <numeric>
#include <vector>

namespace cfx::bench
{

namespace
{

using Clock = std::chrono::steady_clock;

} // namespace

DemoBenchResult MeasureDemo(const std::filesystem::path& scenePath, const EffectsConfig& config, float hz,
                            std::uint32_t steps)
{
    DemoBenchResult result;
    result.steps = steps;
    const float dt = 1.0f / hz;
    for (int withEffects = 0; withEffects < 2; ++withEffects)
    {
        Scene scene = LoadRubeFile(scenePath);
        std::unique_ptr<Effects> effects;
        if (withEffects == 1)
        {
            EffectsDef def;
            def.config = config;
            effects = std::make_unique<Effects>(*scene.world, def);
            AssignSceneMaterials(scene, *effects, scenePath.string());
        }
        const std::optional<Car> car = Car::Find(scene);
        std::vector<double> total, effectsOnly;
        for (std::uint32_t i = 0; i < steps; ++i)
        {
            if (car)
            {
                car->Apply(InputAt(TutorialDrive(), static_cast<float>(i) * dt));
            }
            const Clock::time_point start = Clock::now();
            scene.world->Step(dt, scene.settings.velocityIterations, scene.settings.positionIterations);
            const Clock::time_point worldDone = Clock::now();
            if (effects)
            {
                effects->Step(dt);
            }
            const Clock::time_point end = Clock::now();
            total.push_back(Milliseconds(end - start));
            effectsOnly.push_back(Milliseconds(end - worldDone));
        }
        if (withEffects == 0)
        {
            Summarize(total, result.worldAloneMsMin, result.worldAloneMsMedian);
        }
        else
        {
            Summarize(total, result.withEffectsMsMin, result.withEffectsMsMedian);
            Summarize(effectsOnly, result.effectsStepMsMin, result.effectsStepMsMedian);
            result.liveMax = effects->Stats().liveMax;
            result.spawned = std::accumulate(effects->Stats().spawnedByType.begin(),
                                             effects->Stats().spawnedByType.end(), std::uint64_t{0});
            effects.reset(); // before the scene's world
        }
    }
    return result;
}

} // namespace cfx::bench
