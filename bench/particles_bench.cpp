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
//
// ChainGround/N/0 and ChainGround/N/1: 20 steel boxes dragged at 6 m/s along a static ground of N vertices
// 0.2 m apart, as one chain (0) or as N - 1 edge fixtures (1); each iteration is one Effects::Step (the world
// step is not timed). The same ground either way: the time should not grow with N for a chain.
//
// FarFixture/D: particles raining on a finely split chain, with one static box far away (see below).
//
// TileBuild/N and TileScan/N/W: the static cache of a tile map of N boxes: one build, and one step's scan
// with nothing changed, watched or not (see below).
#include "particles/world_geometry.h"
#include "scenes/debris_bench.h"
#include "scenes/particle_bench.h"
#include "scenes/split_mix.h"

#include <benchmark/benchmark.h>
#include <box2d/box2d.h>
#include <chrono>
#include <cmath>
#include <contactfx/effects.h>
#include <contactfx/particle_system.h>
#include <contactfx/presets.h>
#include <contactfx/rules.h>
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

// A tile map of N static 0.5 m boxes on one body, rows of 1,000 at round coordinates.
void AddTiles(b2World& world, int tiles)
{
    b2BodyDef def;
    b2Body* ground = world.CreateBody(&def);
    for (int i = 0; i < tiles; ++i)
    {
        b2PolygonShape tile;
        tile.SetAsBox(0.25f, 0.25f,
                      b2Vec2(-250.0f + 0.5f * static_cast<float>(i % 1000),
                             -0.25f - 0.5f * static_cast<float>(i / 1000)),
                      0.0f);
        ground->CreateFixture(&tile, 0.0f);
    }
}

// TileBuild/N: one build of the static cache of N tiles (what a level load, or any change of a watched
// static fixture, costs). TileScan/N/W: a step's scan of the same level with nothing changed, watched (W = 1:
// every fixture hashed) or not (W = 0, ParticleSystemOptions::watchStaticGeometry false).
void TileBuild(benchmark::State& state)
{
    b2World world(b2Vec2(0.0f, -10.0f));
    AddTiles(world, static_cast<int>(state.range(0)));
    cfx::particles::WorldGeometry geometry;
    for (auto _ : state)
    {
        geometry.Invalidate();
        benchmark::DoNotOptimize(geometry.UpdateStatic(world, cfx::particles::StaticWatch::onRequest));
    }
    state.counters["primitives"] = static_cast<double>(geometry.StaticPrimitives());
    state.counters["bytes"] = static_cast<double>(geometry.Bytes());
}

void TileScan(benchmark::State& state)
{
    b2World world(b2Vec2(0.0f, -10.0f));
    AddTiles(world, static_cast<int>(state.range(0)));
    const auto watch =
        state.range(1) != 0 ? cfx::particles::StaticWatch::everyStep : cfx::particles::StaticWatch::onRequest;
    cfx::particles::WorldGeometry geometry;
    for (auto _ : state)
    {
        geometry.Scan(world, nullptr, 1.0f / cfx::bench::kBenchHz, watch);
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

void ChainGround(benchmark::State& state)
{
    const auto vertices = static_cast<int>(state.range(0));
    const bool asEdges = state.range(1) != 0;
    b2World world(b2Vec2(0.0f, -10.0f));
    std::vector<b2Vec2> points(static_cast<std::size_t>(vertices));
    for (int i = 0; i < vertices; ++i)
    {
        // Right to left, so that the chain's front (its right side) faces up.
        points[static_cast<std::size_t>(vertices - 1 - i)].Set(
            -0.1f * static_cast<float>(vertices - 1) + 0.2f * static_cast<float>(i), 0.0f);
    }
    b2BodyDef groundDef;
    b2Body* ground = world.CreateBody(&groundDef);
    b2ChainShape chain;
    chain.CreateChain(points.data(), vertices, points.front() + b2Vec2(0.2f, 0.0f),
                      points.back() - b2Vec2(0.2f, 0.0f));
    if (asEdges)
    {
        for (int child = 0; child < chain.GetChildCount(); ++child)
        {
            b2EdgeShape edge;
            chain.GetChildEdge(&edge, child);
            ground->CreateFixture(&edge, 0.0f);
        }
    }
    else
    {
        ground->CreateFixture(&chain, 0.0f);
    }
    std::vector<b2Body*> boxes;
    for (int i = 0; i < 20; ++i)
    {
        b2BodyDef boxDef;
        boxDef.type = b2_dynamicBody;
        boxDef.position.Set(-50.0f + 5.0f * static_cast<float>(i), 0.2f);
        b2Body* box = world.CreateBody(&boxDef);
        b2PolygonShape shape;
        shape.SetAsBox(0.3f, 0.2f);
        box->CreateFixture(&shape, 8.0f)->SetFriction(0.4f);
        boxes.push_back(box);
    }
    cfx::Effects fx(world, cfx::EffectsDef{cfx::DefaultPreset()});
    fx.SetMaterial(ground, fx.FindMaterial("concrete"));
    for (b2Body* box : boxes)
    {
        fx.SetMaterial(box, fx.FindMaterial("steel"));
    }
    const auto step = [&]
    {
        for (b2Body* box : boxes)
        {
            box->SetLinearVelocity(b2Vec2(6.0f, box->GetLinearVelocity().y));
        }
        world.Step(1.0f / 60.0f, 8, 3);
    };
    for (int i = 0; i < 60; ++i)
    {
        step();
        fx.Step(1.0f / 60.0f);
    }
    for (auto _ : state)
    {
        state.PauseTiming();
        step();
        state.ResumeTiming();
        fx.Step(1.0f / 60.0f);
    }
    state.counters["live"] = fx.Stats().live;
}

// FarFixture/D: 5,000 pool particles (1 cm, bouncing) raining on a static chain of 2,000 segments of 5 cm
// (100 m), 100 new ones a step, with one more static box at (D, D) m (0: none); each iteration is one
// particle step (with the 100 spawns) on one thread. The time should grow little with D.
void FarFixture(benchmark::State& state)
{
    const auto farAway = static_cast<float>(state.range(0));
    b2World world(b2Vec2(0.0f, -10.0f));
    b2BodyDef groundDef;
    b2Body* ground = world.CreateBody(&groundDef);
    std::vector<b2Vec2> points;
    for (int i = 0; i <= 2000; ++i)
    {
        points.emplace_back(50.0f - 0.05f * static_cast<float>(i), 0.0f); // right to left: front up
    }
    b2ChainShape chain;
    chain.CreateChain(points.data(), static_cast<int>(points.size()), points.front(), points.back());
    ground->CreateFixture(&chain, 0.0f);
    if (farAway > 0.0f)
    {
        b2PolygonShape box;
        box.SetAsBox(1.0f, 1.0f, b2Vec2(farAway, farAway), 0.0f);
        ground->CreateFixture(&box, 0.0f);
    }
    cfx::ParticleTypeDef type;
    type.name = "ball";
    type.radius = 0.01f;
    type.restitution = 0.3f;
    type.friction = 0.5f;
    type.lifetime = 3600.0f;
    constexpr std::uint32_t kCount = 5000;
    const cfx::ParticleTypeDef types[] = {type};
    cfx::ParticleBudget budget;
    budget.capacity = kCount;
    cfx::ParticleSystemOptions options;
    options.threads = 1;
    cfx::ParticleSystem particles(world, types, budget, options);
    cfx::bench::SplitMix64 random(11);
    // A rain: 100 new particles a step over the chain, the oldest recycled.
    const auto step = [&]
    {
        for (int i = 0; i < 100; ++i)
        {
            cfx::ParticleSpawn spawn;
            spawn.position = b2Vec2(random.Uniform(-49.0f, 49.0f), random.Uniform(0.5f, 3.0f));
            spawn.velocity = b2Vec2(random.Uniform(-1.0f, 1.0f), random.Uniform(-2.0f, 0.0f));
            spawn.type = cfx::ParticleTypeId{0};
            particles.Spawn(spawn);
        }
        particles.Step(1.0f / 60.0f, world.GetGravity());
    };
    for (int i = 0; i < 120; ++i)
    {
        step();
    }
    for (auto _ : state)
    {
        step();
    }
    state.counters["live"] = particles.Count();
}

} // namespace

BENCHMARK(StaticScan);
BENCHMARK(TileBuild)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(TileScan)
    ->Args({10000, 1})
    ->Args({10000, 0})
    ->Args({100000, 1})
    ->Args({100000, 0})
    ->Unit(benchmark::kMicrosecond);
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
BENCHMARK(ChainGround)
    ->ArgsProduct({{1000, 20000}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(300); // 5 s: the boxes stay on the shortest ground

BENCHMARK(FarFixture)->Arg(0)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

// RuleTable::Find for 20,000 rules of one material against 20,000 others among 65,534 (the hashed table):
// every pair shares its larger id, which once put them all in one cluster. Arg 1: that material is
// the larger id of each pair; 0: the smaller.
void RuleLookup(benchmark::State& state)
{
    constexpr int kRules = 20000;
    constexpr std::uint16_t kShared = 65533;
    cfx::RuleTable table(65534);
    for (int i = 0; i < kRules; ++i)
    {
        const cfx::MaterialId other{static_cast<std::uint16_t>(state.range(0) != 0 ? i : 40000 + i)};
        const cfx::MaterialId shared{static_cast<std::uint16_t>(state.range(0) != 0 ? kShared : 0)};
        table.Set(other, shared, cfx::RuleId{static_cast<std::uint16_t>(i)});
    }
    int i = 0;
    for (auto _ : state)
    {
        const cfx::MaterialId other{static_cast<std::uint16_t>(state.range(0) != 0 ? i : 40000 + i)};
        benchmark::DoNotOptimize(table.Find(
            cfx::MaterialId{static_cast<std::uint16_t>(state.range(0) != 0 ? kShared : 0)}, other));
        i = i + 1 == kRules ? 0 : i + 1;
    }
}
BENCHMARK(RuleLookup)->Arg(0)->Arg(1);

BENCHMARK_MAIN();
