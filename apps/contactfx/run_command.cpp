#include "run_command.h"

#include "cli_common.h"
#include "contactfx/scene/text_file.h"
#include "contactfx/sim/simulation.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

namespace cfx::cli
{

namespace
{

void PrintSummary(const Simulation& simulation, const RunOptions& options, const std::string& what)
{
    const Effects& effects = simulation.GetEffects();
    const EffectsConfig& config = effects.Config();
    const EffectsStats& stats = effects.Stats();
    std::printf("%s: %s effects, %.0f Hz, %.2f s (%llu steps), seed %llu\n", what.c_str(),
                config.name.empty() ? "custom" : config.name.c_str(), options.hz,
                static_cast<double>(simulation.Time()), static_cast<unsigned long long>(stats.steps),
                static_cast<unsigned long long>(options.seed));
    std::printf("  spawned:");
    for (std::size_t i = 0; i < config.particleTypes.size(); ++i)
    {
        std::printf(" %s %llu%s", config.particleTypes[i].name.c_str(),
                    static_cast<unsigned long long>(stats.spawnedByType[i]),
                    i + 1 < config.particleTypes.size() ? "," : "");
    }
    std::printf("\n");
    for (std::size_t i = 0; i < config.rules.size(); ++i)
    {
        const RuleDef& rule = config.rules[i];
        std::printf("  %-18s -> %-8s at most %u contacts, %llu particles\n",
                    (rule.materialA + "+" + rule.materialB).c_str(), rule.particleType.c_str(),
                    stats.rules[i].contactsMax, static_cast<unsigned long long>(stats.rules[i].spawned));
    }
    std::printf("  live particles at most %u (cap %u), recycled %llu, started inside solid %llu\n",
                stats.liveMax, config.budget.capacity, static_cast<unsigned long long>(stats.recycled),
                static_cast<unsigned long long>(stats.spawnedInsideSolid));
}

int Simulate(const RunOptions& options, std::span<const DriveSegment> drive, const std::string& what)
{
    CheckRunOptions(options);
    SimulationDef def;
    def.scene = options.scene;
    def.config = SelectConfig(options);
    def.seed = options.seed;
    def.hz = static_cast<float>(options.hz);
    def.drive = drive;
    Simulation simulation(def);
    const auto steps = static_cast<std::uint64_t>(std::llround(options.seconds * options.hz));
    for (std::uint64_t i = 0; i < steps; ++i)
    {
        simulation.Step();
    }
    if (!options.stats.empty())
    {
        WriteTextFileAtomically(options.stats, StatsJson(simulation.GetEffects(), def.hz));
    }
    PrintSummary(simulation, options, what);
    return kExitOk;
}

} // namespace

void RegisterRunCommands(CLI::App& app, int& result)
{
    auto demoOptions = std::make_shared<RunOptions>();
    CLI::App* demo =
        app.add_subcommand("demo", "The tutorial scene with a scripted drive and contactfx's default model");
    AddRunOptions(*demo, *demoOptions, true);
    demo->callback(
        [demoOptions, &result]
        {
            result = Guarded(
                [&]
                {
                    demoOptions->scene = (ScenesDir() / "physics_driven_particles.json").string();
                    return Simulate(*demoOptions, TutorialDrive(), "contactfx demo");
                });
        });

    auto runOptions = std::make_shared<RunOptions>();
    CLI::App* run =
        app.add_subcommand("run", "Any RUBE scene: bodies move by their initial velocities and joint motors");
    run->add_option("scene", runOptions->scene, "RUBE JSON scene")->required();
    AddRunOptions(*run, *runOptions, false);
    run->callback(
        [runOptions, &result] {
            result = Guarded([&] { return Simulate(*runOptions, {}, "contactfx run " + runOptions->scene); });
        });
}

} // namespace cfx::cli
