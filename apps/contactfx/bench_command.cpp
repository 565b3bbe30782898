// contactfx bench: the benchmark scenes of bench/scenes, timed from the command line.
//
//   contactfx bench particles --count N [--steps S] [--warmup W] [--mode pool|bodies] [--threads T] [--json]
//   contactfx bench demo [--steps S] [--json]
//   contactfx bench debris [--boxes N] [--steps S] [--json]
//
// `particles` runs the particle benchmark scene (a body per particle, or the pool) and prints the
// minimum and median milliseconds per step and the heap bytes per live particle; for the pool also the
// particle update alone and the plain integration of the same arrays. Without --mode both modes run and
// their ratio is printed. `demo` times the tutorial scene with its scripted drive with and without the
// effects layer. `debris` runs the debris scene (steel boxes sliding down concrete ramps into a pile, the
// particle budget full) and compares Effects::Step with world.Step step by step. Timing depends on the
// machine: nothing here is checked against a figure.
#include "bench_command.h"

#include "cli_common.h"
#include "contactfx/error.h"
#include "harness/scenes.h"
#include "scenes/debris_bench.h"
#include "scenes/demo_bench.h"
#include "scenes/particle_bench.h"

#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace cfx::cli
{

namespace
{

using Json = nlohmann::ordered_json;

struct ParticleBenchOptions
{
    std::uint32_t count = 0;
    std::uint32_t steps = 120;
    std::uint32_t warmup = 10;
    std::string mode; ///< empty: both
    unsigned threads = 0;
    bool json = false;
};

struct DemoBenchOptions
{
    std::uint32_t steps = 1200;
    bool json = false;
};

struct DebrisBenchOptions
{
    std::uint32_t boxes = 200;
    std::uint32_t steps = 600;
    bool json = false;
};

Json ToJson(const bench::ParticleBenchResult& result)
{
    Json out{{"mode", result.mode},
             {"count", result.count},
             {"steps", result.steps},
             {"ms_per_step_min", result.msMin},
             {"ms_per_step_median", result.msMedian},
             {"bytes_per_particle", result.bytesPerParticle},
             {"update_ms_min", result.updateMsMin},
             {"update_ms_median", result.updateMsMedian}};
    if (result.mode == "pool")
    {
        out["plain_ms_min"] = result.plainMsMin;
        out["plain_ms_median"] = result.plainMsMedian;
        out["plain_threads"] = result.plainThreads;
    }
    out["threads"] = result.threads;
    return out;
}

void PrintText(const bench::ParticleBenchResult& result)
{
    std::printf("  %-6s step: min %.3f ms, median %.3f ms (%.1f ns per particle); particle update median "
                "%.3f ms; %.1f bytes per particle; %u thread(s)\n",
                result.mode.c_str(), result.msMin, result.msMedian, 1.0e6 * result.msMedian / result.count,
                result.updateMsMedian, result.bytesPerParticle, result.threads);
    if (result.mode == "pool")
    {
        std::printf(
            "  %-6s plain integration of the same arrays (no collision): min %.3f ms, median %.3f ms, %u "
            "thread(s); colliding update / plain = %.2fx\n",
            "", result.plainMsMin, result.plainMsMedian, result.plainThreads,
            result.plainMsMedian > 0.0 ? result.updateMsMedian / result.plainMsMedian : 0.0);
    }
}

int RunParticles(const ParticleBenchOptions& options)
{
    ParticleSystemOptions system;
    system.threads = options.threads;
    std::optional<bench::ParticleBenchResult> pool, bodies;
    if (options.mode != "bodies")
    {
        pool = bench::MeasureParticles(options.count, ParticleBackend::pool, options.steps, options.warmup,
                                       system);
    }
    if (options.mode != "pool")
    {
        bodies = bench::MeasureParticles(options.count, ParticleBackend::body, options.steps, options.warmup,
                                         system);
    }
    const double ratio = pool && bodies && pool->msMedian > 0.0 ? bodies->msMedian / pool->msMedian : 0.0;
    if (options.json)
    {
        if (!options.mode.empty())
        {
            std::printf("%s\n", ToJson(pool ? *pool : *bodies).dump().c_str());
        }
        else
        {
            Json both{{"count", options.count},
                      {"steps", options.steps},
                      {"pool", ToJson(*pool)},
                      {"bodies", ToJson(*bodies)},
                      {"bodies_over_pool", ratio}};
            std::printf("%s\n", both.dump().c_str());
        }
        return kExitOk;
    }
    std::printf("contactfx bench particles: %u particles, %u steps at %.0f Hz after %u warm-up steps\n",
                options.count, options.steps, static_cast<double>(bench::kBenchHz), options.warmup);
    if (pool)
    {
        PrintText(*pool);
    }
    if (bodies)
    {
        PrintText(*bodies);
    }
    if (pool && bodies)
    {
        std::printf("  pool is %.1fx faster than a body per particle (median step)\n", ratio);
    }
    return kExitOk;
}

int RunDemo(const DemoBenchOptions& options)
{
    // The demo's scene and effects, from the registry (harness/scenes.h); MeasureDemo drives its car.
    const SimulationDef tutorial = SceneSimulationDef(*FindScene("tutorial"), BundledScenesDir());
    const bench::DemoBenchResult result =
        bench::MeasureDemo(tutorial.scene, tutorial.config, tutorial.hz, options.steps);
    if (options.json)
    {
        const Json out{{"steps", result.steps},
                       {"world_alone_ms_min", result.worldAloneMsMin},
                       {"world_alone_ms_median", result.worldAloneMsMedian},
                       {"with_effects_ms_min", result.withEffectsMsMin},
                       {"with_effects_ms_median", result.withEffectsMsMedian},
                       {"effects_step_ms_min", result.effectsStepMsMin},
                       {"effects_step_ms_median", result.effectsStepMsMedian},
                       {"live_max", result.liveMax},
                       {"spawned", result.spawned}};
        std::printf("%s\n", out.dump().c_str());
        return kExitOk;
    }
    std::printf("contactfx bench demo: tutorial scene, scripted drive, %s effects, %u steps at %.0f Hz\n",
                tutorial.config.name.empty() ? "custom" : tutorial.config.name.c_str(), result.steps,
                static_cast<double>(tutorial.hz));
    std::printf("  world.Step alone:           min %.4f ms, median %.4f ms\n", result.worldAloneMsMin,
                result.worldAloneMsMedian);
    std::printf("  world.Step + effects:       min %.4f ms, median %.4f ms\n", result.withEffectsMsMin,
                result.withEffectsMsMedian);
    std::printf("  Effects::Step in that run:  min %.4f ms, median %.4f ms\n", result.effectsStepMsMin,
                result.effectsStepMsMedian);
    std::printf("  effects add %.0f %% to the median step; %llu particles emitted, at most %u live\n",
                result.worldAloneMsMedian > 0.0
                    ? 100.0 * (result.withEffectsMsMedian / result.worldAloneMsMedian - 1.0)
                    : 0.0,
                static_cast<unsigned long long>(result.spawned), result.liveMax);
    return kExitOk;
}

int RunDebris(const DebrisBenchOptions& options)
{
    const bench::DebrisBenchResult result = bench::MeasureDebris(options.boxes, options.steps);
    if (options.json)
    {
        const Json out{{"boxes", result.boxes},
                       {"steps", result.steps},
                       {"world_ms_median", result.worldMsMedian},
                       {"effects_ms_median", result.effectsMsMedian},
                       {"effects_ms_p99", result.effectsMsP99},
                       {"effects_ms_max", result.effectsMsMax},
                       {"effects_over_world", result.effectsOverWorld},
                       {"live_max", result.liveMax},
                       {"ns_per_particle", result.nsPerParticle}};
        std::printf("%s\n", out.dump().c_str());
        return kExitOk;
    }
    std::printf("contactfx bench debris: %u steel boxes on concrete ramps and in a bin, default effects "
                "(budget %u), %u steps at %.0f Hz after %u untimed steps\n",
                result.boxes, result.capacity, result.steps, static_cast<double>(bench::kDebrisHz),
                result.warmup);
    std::printf("  world.Step:     median %.4f ms\n", result.worldMsMedian);
    std::printf("  Effects::Step:  median %.4f ms, p99 %.4f ms, max %.4f ms\n", result.effectsMsMedian,
                result.effectsMsP99, result.effectsMsMax);
    std::printf("  effects / world over the run: %.3f; %.1f ns per particle moved and step\n",
                result.effectsOverWorld, result.nsPerParticle);
    std::printf(
        "  particles: at most %u live at once (%u after a step) of %u; the pool was full when emitting in "
        "%u of %u steps; %llu sparks\n",
        result.liveMax, result.liveAfterMax, result.capacity, result.stepsFull, result.steps,
        static_cast<unsigned long long>(result.sparks));
    std::printf("  %llu boxes dropped onto the ramps; %u of %u boxes touch another box at the end\n",
                static_cast<unsigned long long>(result.dropped), result.touchingAtEnd, result.boxes);
    return kExitOk;
}

} // namespace

void RegisterBenchCommand(CLI::App& app, int& result)
{
    CLI::App* bench = app.add_subcommand("bench", "Time the particle system and the effects layer");
    bench->require_subcommand(1);

    auto particleOptions = std::make_shared<ParticleBenchOptions>();
    CLI::App* particles = bench->add_subcommand(
        "particles", "The particle benchmark scene: a chain of 256 segments and N respawning particles");
    particles->add_option("--count", particleOptions->count, "Particles, 1 .. 4,000,000")
        ->required()
        ->transform(WholeNumberIn(1, 4000000));
    particles->add_option("--steps", particleOptions->steps, "Timed steps, 1 .. 100,000")
        ->transform(WholeNumberIn(1, 100000))
        ->capture_default_str();
    particles->add_option("--warmup", particleOptions->warmup, "Untimed steps first, 0 .. 100,000")
        ->transform(WholeNumberIn(0, 100000))
        ->capture_default_str();
    particles->add_option("--mode", particleOptions->mode, "pool or bodies; both when omitted")
        ->check(CLI::IsMember({"pool", "bodies"}));
    particles->add_option("--threads", particleOptions->threads, "Threads for the pool, 0 (all) .. 8")
        ->transform(WholeNumberIn(0, 8))
        ->capture_default_str();
    particles->add_flag("--json", particleOptions->json, "One JSON object instead of text");
    particles->callback([particles, particleOptions, &result]
                        { result = Guarded(*particles, [&] { return RunParticles(*particleOptions); }); });

    auto demoOptions = std::make_shared<DemoBenchOptions>();
    CLI::App* demo =
        bench->add_subcommand("demo", "The tutorial scene: world.Step alone against world.Step plus effects");
    demo->add_option("--steps", demoOptions->steps, "Steps at 60 Hz, 1 .. 1,000,000")
        ->transform(WholeNumberIn(1, 1000000))
        ->capture_default_str();
    demo->add_flag("--json", demoOptions->json, "One JSON object instead of text");
    demo->callback([demo, demoOptions, &result]
                   { result = Guarded(*demo, [&] { return RunDemo(*demoOptions); }); });

    auto debrisOptions = std::make_shared<DebrisBenchOptions>();
    CLI::App* debris = bench->add_subcommand(
        "debris",
        "Steel boxes sliding down concrete ramps into a pile, particle budget full: Effects::Step against "
        "world.Step");
    debris->add_option("--boxes", debrisOptions->boxes, "Dynamic boxes, 1 .. 10,000")
        ->transform(WholeNumberIn(1, 10000))
        ->capture_default_str();
    debris
        ->add_option("--steps", debrisOptions->steps,
                     "Timed steps at 60 Hz (after 150 untimed ones), 1 .. 100,000")
        ->transform(WholeNumberIn(1, 100000))
        ->capture_default_str();
    debris->add_flag("--json", debrisOptions->json, "One JSON object instead of text");
    debris->callback([debris, debrisOptions, &result]
                     { result = Guarded(*debris, [&] { return RunDebris(*debrisOptions); }); });
}

} // namespace cfx::cli
