#include "cli_common.h"

#include "contactfx/error.h"
#include "contactfx/presets.h"
#include "contactfx/scene/effects_json.h"
#include "usage.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <vector>

namespace cfx::cli
{

bool FlushStandardOutput()
{
    static bool reported = false;
    errno = 0;
    std::cout.flush(); // its buffer is stdout's: the first write that fails may be this one
    const bool flushed = std::fflush(stdout) == 0;
    const int error = errno;
    if (flushed && !std::ferror(stdout) && std::cout.good())
    {
        return true;
    }
    if (!reported)
    {
        reported = true;
        // The reason is known when this flush failed; an earlier failed write left only the error flag.
        std::cerr << "contactfx: error: standard output: write failed"
                  << (error != 0 ? std::string(": ") + std::strerror(error) : std::string()) << '\n';
    }
    return false;
}

void AddRunOptions(CLI::App& command, RunOptions& options, bool demo)
{
    command
        .add_option("--seconds", options.seconds,
                    "Simulated time in seconds, (0, 86400]; at least one step: 0.5 / --hz or more")
        ->check(DecimalNumber())
        ->capture_default_str();
    command.add_option("--hz", options.hz, "Steps per second, [1, 10000]")
        ->check(DecimalNumber())
        ->capture_default_str();
    command.add_option("--seed", options.seed, "Seed of every random choice, 0 .. 2^64-1")
        ->transform(CLI::Validator(
            [](std::string& text)
            {
                // Digits only (no sign, no spaces) and at most 2^64-1, where CLI11 alone would saturate;
                // rewritten in plain decimal, where CLI11 alone would read "010" as octal 8.
                std::uint64_t value = 0;
                const char* end = text.data() + text.size();
                const auto [stop, error] = std::from_chars(text.data(), end, value);
                if (error != std::errc() || stop != end)
                {
                    return "expected a whole number from 0 to 2^64-1, found " + text;
                }
                text = std::to_string(value);
                return std::string();
            },
            "UINT64"))
        ->capture_default_str();
    command.add_option("--stats", options.stats, "Write statistics as JSON to this file")
        ->check(NamesAFile());
    command.add_flag(
        "--check-particles", options.checkParticles,
        "Check every particle after every step against the world (slow): the stats count "
        "particle_steps_inside, crossings and passed_through_moving, and spawned_inside_solid audits "
        "every start");
    command
        .add_option("--threads", options.threads,
                    "Threads for the particle step, 1 .. 8, split at any particle count (for testing: the "
                    "results are the same bits with any number); default: the machine's, split when it pays")
        ->transform(WholeNumberIn(1, 8));
    AddEffectsOptions(command, options,
                      demo ? "Effects config JSON (overrides --preset); the tutorial scene's fixtures name "
                             "steel, rubber, concrete and dirt"
                           : "Effects config JSON (overrides --preset)");
}

void AddEffectsOptions(CLI::App& command, RunOptions& options, const std::string& effectsHelp)
{
    command
        .add_option("--preset", options.preset,
                    "Built-in effects: default or tutorial. Without --preset and --effects: a registered "
                    "scene's own effects, else default")
        ->check(CLI::IsMember({"default", "tutorial"}));
    command.add_option("--effects", options.effects, effectsHelp)->check(NamesAFile());
}

bool EffectsChosen(const RunOptions& options)
{
    return !options.effects.empty() || !options.preset.empty();
}

void CheckRunOptions(const RunOptions& options)
{
    if (!std::isfinite(options.seconds) || options.seconds <= 0.0 || options.seconds > 86400.0)
    {
        throw InputError(kCommandLine, "--seconds",
                         "expected a number in (0, 86400], found " + NumberText(options.seconds));
    }
    if (!std::isfinite(options.hz) || options.hz < 1.0 || options.hz > 10000.0)
    {
        throw InputError(kCommandLine, "--hz",
                         "expected a number in [1, 10000], found " + NumberText(options.hz));
    }
    // The run makes round(seconds * hz) steps: less than half a step would be none at all.
    if (std::llround(options.seconds * options.hz) < 1)
    {
        // The least --seconds that makes a step, as the check computes it: 0.5 / hz itself can round
        // to just under half a step (--hz 103).
        double least = 0.5 / options.hz;
        while (std::llround(least * options.hz) < 1)
        {
            least = std::nextafter(least, 1.0);
        }
        throw InputError(kCommandLine, "--seconds",
                         NumberText(options.seconds) + " s at --hz " + NumberText(options.hz) +
                             " is less than half a step (" + NumberText(0.5 / options.hz) +
                             " s), so nothing would be simulated: give --seconds " + NumberText(least) +
                             " or more, or a higher --hz");
    }
}

void PrintSceneWarnings(const Scene& scene, const RunOptions& options)
{
    std::vector<Diagnostic> warnings = scene.warnings;
    const float sceneHz = scene.settings.stepsPerSecond;
    // For a scene file the user named; a registered scene's rate is the harness's to choose.
    if (!options.scene.empty() && sceneHz != static_cast<float>(options.hz)) // the run steps at a float rate
    {
        const std::string rate = NumberText(sceneHz); // as the file has it: "59.99", not 59.9900016784668
        Diagnostic warning{options.scene, "stepsPerSecond",
                           "the scene steps at " + rate + " Hz; this run steps at --hz " +
                               NumberText(options.hz) + " (give --hz " + rate +
                               " to step as the scene says)"};
        warning.warning = true;
        warnings.push_back(std::move(warning));
    }
    for (const Diagnostic& warning : warnings)
    {
        std::cerr << "contactfx: " << warning.ToString() << '\n'; // "...: warning: ..."
    }
}

EffectsConfig SelectConfig(const RunOptions& options)
{
    if (!options.effects.empty())
    {
        return LoadEffectsFile(options.effects);
    }
    return options.preset == "tutorial" ? TutorialPreset() : DefaultPreset();
}

int Guarded(const CLI::App& command, const std::function<int()>& body)
{
    try
    {
        return body();
    }
    catch (const InputError& error)
    {
        bool commandLineOnly = !error.Diagnostics().empty();
        for (const Diagnostic& problem : error.Diagnostics())
        {
            std::cerr << "contactfx: error: " << problem.ToString() << '\n';
            commandLineOnly = commandLineOnly && problem.file == kCommandLine;
        }
        if (commandLineOnly)
        {
            std::cerr << "See '" << CommandPath(command) << " --help'.\n";
        }
    }
    catch (const std::exception& error)
    {
        std::cerr << "contactfx: error: " << error.what() << '\n';
    }
    return kExitError;
}

} // namespace cfx::cli
