// contactfx benchmarks: the particle benchmark scene under Google Benchmark, 1k to 100k particles, for
// the pool (colliding step and plain integration) and for a body per particle.
//
//   build/bin/contactfx_bench --benchmark_filter=Pool
//
// Each iteration is one step of the scene (world.Step, particle step, respawn); the counter
// ns_per_particle divides by the particle count so sizes compare directly.
//
// StaticSweep and StaticScan time the static cache alone (src/particles/world_geometry.h): one disc sweep
// of the kind a colliding step makes against the benchmark scene's chain, and one scan of the world for
// changes, per iteration.
//
// Debris/200 and Debris/1000 run the debris scene (bench/scenes/debris_bench.h) after the same 150 warm-up
// steps as `contactfx bench debris` (the pool is full by then): each iteration is one whole step (world.Step,
// Effects::Step and the dropper, which costs a few microseconds every third step), with counters world_ms and
// effects_ms (each part's time per step) and effects_over_world (the ratio of their sums).
#include "particles/world_geometry.h"
#include "scenes/debris_bench.h"
#include "scenes/particle_bench.h"

#include <benchmark/benchmark.h>
#include <chrono>
#include <cmath>
#include <vector>

namespace
{

using cfx::ParticleBackend;
using cfx::bench::ParticleBenchScene;

constexpr int kWarmup = 30;

void Run(benchmark::State& state, ParticleBackend backend, bool plain, unsigned threads)
{
    const auto count = static_cast<std::uint32_t>(state.range(0));
    ParticleBenchScene scene;
    cfx::ParticleSystemOptions options;
    options.threads = threads;
    scene.Populate(count, backend, options);
    for (int i = 0; i < kWarmup; ++i)
    {
        plain ? scene.StepPlain() : scene.Step();
    }
    for (auto _ : state)
    {
        plain ? scene.StepPlain() : scene.Step();
    }
    state.counters["ns_per_particle"] =
        benchmark::Counter(static_cast<double>(count),
                           benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    state.counters["threads"] = scene.Particles().ThreadsUsed();
}

void Pool(benchmark::State& state)
{
    Run(state, ParticleBackend::pool, false, 0);
}
void PoolOneThread(benchmark::State& state)
{
    Run(state, ParticleBackend::pool, false, 1);
}
void PoolPlain(benchmark::State& state)
{
    Run(state, ParticleBackend::pool, true, 0);
}
void Bodies(benchmark::State& state)
{
    Run(state, ParticleBackend::body, false, 1);
}

// The next step's motions of the particles near the ground (below 1.5 m, not at rest) over 20 steps of
// the 10,000-particle benchmark at steady state: the sweeps a colliding step makes, each measuring the
// clearance as a particle's first sweep does.
void StaticSweep(benchmark::State& state)
{
    using namespace cfx::particles;
    constexpr float kDt = 1.0f / cfx::bench::kBenchHz;
    constexpr float kDamping = 1.0f / (1.0f + kDt * 0.2f); // the benchmark type's drag
    ParticleBenchScene scene;
    scene.Populate(10000, ParticleBackend::pool);
    WorldGeometry geometry;
    geometry.Scan(scene.World(), nullptr, kDt);
    const ParticleSide side{0.05f, 0.5f, 0.5f, 0.5f, 0x0002, 0x0001};
    std::vector<SweepInput> motions;
    for (int step = 0; step < 260; ++step)
    {
        scene.Step();
        const cfx::ParticleView view = scene.Particles().View();
        for (std::uint32_t i = 0; step >= 240 && i < view.count; ++i)
        {
            const std::uint32_t slot = view.Slot(i);
            const b2Vec2 p(view.positionX[slot], view.positionY[slot]);
            const b2Vec2 v(view.velocityX[slot], view.velocityY[slot]);
            if (p.y < 1.5f && (v.x != 0.0f || v.y != 0.0f))
            {
                const b2Vec2 d = (kDt * kDamping) * (v + kDt * scene.World().GetGravity());
                motions.push_back({p, d, side.radius});
            }
        }
    }
    std::size_t next = 0;
    for (auto _ : state)
    {
        const SweepInput& motion = motions[next];
        next = next + 1 == motions.size() ? 0 : next + 1;
        SweepResult result;
        float clearance = 0.0f;
        benchmark::DoNotOptimize(geometry.SweepStatic(motion, side, result, &clearance));
        benchmark::DoNotOptimize(clearance);
    }
    state.counters["motions"] = static_cast<double>(motions.size());
}

// The walk of the world every colliding step makes to notice changed static geometry (nothing changes
// here, so nothing is rebuilt): the benchmark scene's 256-segment chain.
void StaticScan(benchmark::State& state)
{
    ParticleBenchScene scene;
    cfx::particles::WorldGeometry geometry;
    for (auto _ : state)
    {
        geometry.Scan(scene.World(), nullptr, 1.0f / cfx::bench::kBenchHz);
    }
    state.counters["builds"] = static_cast<double>(geometry.StaticBuilds());
}

void Debris(benchmark::State& state)
{
    cfx::bench::DebrisBenchScene scene(static_cast<std::uint32_t>(state.range(0)));
    for (std::uint32_t i = 0; i < cfx::bench::kDebrisWarmup; ++i)
    {
        scene.Step();
    }
    double worldSeconds = 0.0, effectsSeconds = 0.0;
    for (auto _ : state)
    {
        const cfx::bench::DebrisBenchScene::StepSeconds seconds = scene.TimedStep();
        worldSeconds += seconds.world;
        effectsSeconds += seconds.effects;
    }
    state.counters["world_ms"] = benchmark::Counter(1.0e3 * worldSeconds, benchmark::Counter::kAvgIterations);
    state.counters["effects_ms"] =
        benchmark::Counter(1.0e3 * effectsSeconds, benchmark::Counter::kAvgIterations);
    state.counters["effects_over_world"] = worldSeconds > 0.0 ? effectsSeconds / worldSeconds : 0.0;
    state.counters["live"] = scene.Fx().Stats().live;
}

} // namespace

BENCHMARK(StaticScan);
BENCHMARK(StaticSweep);
BENCHMARK(Pool)->Arg(1000)->Arg(10000)->Arg(50000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(PoolOneThread)->Arg(1000)->Arg(10000)->Arg(50000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(PoolPlain)->Arg(1000)->Arg(10000)->Arg(50000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(Bodies)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(50000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(20);
BENCHMARK(Debris)->Arg(200)->Arg(1000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
