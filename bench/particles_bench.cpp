// contactfx benchmarks: the particle benchmark scene under Google Benchmark, 1k to 100k particles, for
// the pool (colliding step and plain integration) and for a body per particle.
//
//   build/bin/contactfx_bench --benchmark_filter=Pool
//
// Each iteration is one step of the scene (world.Step, particle step, respawn); the counter
// ns_per_particle divides by the particle count so sizes compare directly.
#include "scenes/particle_bench.h"

#include <benchmark/benchmark.h>

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

} // namespace

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

BENCHMARK_MAIN();
