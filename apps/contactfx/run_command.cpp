#include "run_command.h"

#include "cli_common.h"
#include "contactfx/error.h"
#include "outputs.h"
#include "plot_option.h"
#include "scenario.h"
#include "sound_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <vector>

namespace cfx::cli
{

namespace
{

// "contactfx demo: default effects, 60 Hz, 20.00 s (1200 steps), seed 1": the summary's first line and the
// plot's title.
std::string Headline(const Simulation& simulation, const RunOptions& options, const std::string& what)
{
    const EffectsConfig& config = simulation.GetEffects().Config();
    char time[64];
    std::snprintf(time, sizeof time, "%.2f s (%llu steps)", static_cast<double>(simulation.Time()),
                  static_cast<unsigned long long>(simulation.GetEffects().Stats().steps));
    const std::string effects = (config.name.empty() ? "custom" : config.name) + " effects" +
                                (options.effects.empty() ? "" : " (" + options.effects + ")");
    return what + ": " + effects + ", " + NumberText(options.hz) + " Hz, " + time + ", seed " +
           std::to_string(options.seed);
}

void PrintSummary(const Simulation& simulation, const RunOptions& options, const std::string& what)
{
    const Effects& effects = simulation.GetEffects();
    const EffectsConfig& config = effects.Config();
    const EffectsStats& stats = effects.Stats();
    std::printf("%s\n", Headline(simulation, options, what).c_str());
    std::printf("  spawned:");
    for (std::size_t i = 0; i < config.particleTypes.size(); ++i)
    {
        std::printf(" %s %llu%s", config.particleTypes[i].name.c_str(),
                    static_cast<unsigned long long>(stats.spawnedByType[i]),
                    i + 1 < config.particleTypes.size() ? "," : "");
    }
    std::printf("\n");
    // What each rule emits, in one column as wide as the widest (up to 40 characters).
    std::vector<std::string> types;
    int typesWidth = 8;
    for (const RuleDef& rule : config.rules)
    {
        types.push_back(rule.burstParticleType.empty() || rule.burstParticleType == rule.particleType
                            ? rule.particleType
                            : rule.particleType + ", bursts " + rule.burstParticleType);
        typesWidth = std::max(typesWidth, static_cast<int>(std::min<std::size_t>(types.back().size(), 40)));
    }
    for (std::size_t i = 0; i < config.rules.size(); ++i)
    {
        const RuleDef& rule = config.rules[i];
        const RuleStats& counts = stats.rules[i];
        std::printf("  %-18s -> %-*s at most %u contacts, %llu particles", PairName(rule).c_str(), typesWidth,
                    types[i].c_str(), counts.contactsMax, static_cast<unsigned long long>(counts.spawned));
        if (counts.spawnRejected > 0) // no free start near the contact: a pile, a crevice, a thin pane
        {
            std::printf(", %llu not started (no free place)",
                        static_cast<unsigned long long>(counts.spawnRejected));
        }
        std::printf("\n");
    }
    std::printf("  live particles at most %u (cap %u), recycled %llu, started inside solid %llu\n",
                stats.liveMax, config.budget.capacity, static_cast<unsigned long long>(stats.recycled),
                static_cast<unsigned long long>(stats.spawnedInsideSolid));
}

// `error` with " (after T s simulated)" added to its messages: where a stream of output failed.
InputError AfterTime(const InputError& error, double seconds)
{
    std::vector<Diagnostic> problems = error.Diagnostics();
    char when[64];
    std::snprintf(when, sizeof when, " (after %.2f s simulated)", seconds);
    for (Diagnostic& problem : problems)
    {
        problem.message += when;
    }
    return InputError(std::move(problems));
}

// Runs what `options` select for --seconds; `what` heads the summary and the plot. Every output is
// checked before the simulation starts and written together at the end, or none is (outputs.h); the
// events stream to their temporary file as they come, so memory stays flat for any duration.
int Simulate(const RunOptions& options, const std::string& what, const std::string& plotFile)
{
    CheckRunOptions(options);
    if (!options.audio.empty())
    {
        CheckAudioSeconds(options.seconds, "--audio");
    }
    const Scenario scenario = SelectScenario(options);
    OutputFiles outputs;
    AddScenarioInputs(outputs, options, scenario);
    std::optional<OutputFiles::Handle> stats;
    std::optional<OutputFiles::Handle> events;
    std::optional<OutputFiles::Handle> plotOutput;
    if (!options.stats.empty())
    {
        stats = outputs.Add("--stats", options.stats);
    }
    if (!options.events.empty())
    {
        events = outputs.Add("--events", options.events);
    }
    if (!plotFile.empty())
    {
        plotOutput = outputs.Add("--plot", plotFile, ".png");
    }
    SoundOutput sound(outputs, options.audio, options.voices);
    outputs.Prepare();

    Simulation simulation(scenario.def);
    PrintSceneWarnings(simulation.GetScene(), options);
    sound.Start(simulation.GetEffects().Config(), options.seed);
    PlotWriter plot(plotFile, simulation.GetEffects());
    const auto steps = static_cast<std::uint64_t>(std::llround(options.seconds * options.hz));
    for (std::uint64_t i = 0; i < steps; ++i)
    {
        scenario.Step(simulation);
        plot.AfterStep(simulation.GetEffects(), simulation.Dt());
        outputs.CheckInterrupted();
        try
        {
            if (events)
            {
                for (const EffectEvent& event : simulation.GetEffects().Events())
                {
                    outputs.Append(*events,
                                   EventJsonLine(event, simulation.GetEffects().Config(), options.hz));
                }
            }
            sound.AfterStep(simulation.GetEffects(), simulation.Dt());
        }
        catch (const InputError& error)
        {
            throw AfterTime(error, static_cast<double>(simulation.Time()));
        }
    }
    try
    {
        if (events)
        {
            // The scrapes still open end with the run: every scrape_began has its scrape_ended.
            for (const EffectEvent& event : simulation.EndScrapes())
            {
                outputs.Append(*events, EventJsonLine(event, simulation.GetEffects().Config(), options.hz));
            }
        }
        sound.Finish(static_cast<double>(simulation.Time()));
    }
    catch (const InputError& error)
    {
        throw AfterTime(error, static_cast<double>(simulation.Time()));
    }
    const StateHash runHash = simulation.RunHash();
    if (stats)
    {
        outputs.Write(*stats, StatsJson(simulation.GetEffects(), scenario.def.hz, &runHash));
    }
    if (plotOutput)
    {
        outputs.Write(*plotOutput, plot.Png(simulation.GetEffects(), Headline(simulation, options, what)));
    }
    // The summary is part of the result: it is printed and flushed before the outputs are committed, so
    // that a failed write of standard output (`> /dev/full`) leaves no output file either. It tells what
    // was simulated, nothing a failing Commit() would make untrue; that failure is an error of its own.
    PrintSummary(simulation, options, what);
    std::fputs(sound.Summary().c_str(), stdout);
    if (!FlushStandardOutput())
    {
        return kExitError;
    }
    outputs.Commit();
    return kExitOk;
}

void AddSoundOptions(CLI::App& command, RunOptions& options)
{
    command
        .add_option("--audio", options.audio,
                    "Write the sound of the run to this WAV file (48 kHz, 16-bit mono, synthesized from the "
                    "voices; docs/sound.md)")
        ->check(NamesAFile());
    command
        .add_option("--voices", options.voices,
                    "Write the voices started and stopped as JSON Lines to this file (docs/sound.md)")
        ->check(NamesAFile());
}

} // namespace

void RegisterRunCommands(CLI::App& app, int& result)
{
    auto demoOptions = std::make_shared<RunOptions>();
    auto demoPlot = std::make_shared<std::string>();
    CLI::App* demo =
        app.add_subcommand("demo", "The tutorial scene with a scripted drive and contactfx's default model");
    AddRunOptions(*demo, *demoOptions, true);
    demo->add_option("--events", demoOptions->events,
                     "Write scrape and impact events as JSON Lines to this file")
        ->check(NamesAFile());
    AddSoundOptions(*demo, *demoOptions);
    AddPlotOption(*demo, *demoPlot);
    demo->callback(
        [demo, demoOptions, demoPlot, &result]
        {
            result = Guarded(*demo,
                             [&]
                             {
                                 demoOptions->sceneName = "tutorial";
                                 return Simulate(*demoOptions, "contactfx demo", *demoPlot);
                             });
        });

    auto runOptions = std::make_shared<RunOptions>();
    auto runPlot = std::make_shared<std::string>();
    CLI::App* run = app.add_subcommand(
        "run", "A registered scene (--scene NAME) with its scripted drive, or any RUBE scene file as it is");
    AddSceneOptions(*run, *runOptions,
                    "RUBE JSON scene: bodies move by their initial velocities and joint motors");
    AddRunOptions(*run, *runOptions, false);
    run->add_option("--events", runOptions->events,
                    "Write scrape and impact events as JSON Lines to this file")
        ->check(NamesAFile());
    AddSoundOptions(*run, *runOptions);
    AddPlotOption(*run, *runPlot);
    run->callback(
        [run, runOptions, runPlot, &result]
        {
            result = Guarded(*run,
                             [&]
                             {
                                 const std::string what = runOptions->sceneName.empty()
                                                              ? runOptions->scene
                                                              : "--scene " + runOptions->sceneName;
                                 return Simulate(*runOptions, "contactfx run " + what, *runPlot);
                             });
        });
}

} // namespace cfx::cli
