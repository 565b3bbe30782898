// The contactfx command line: what every command shares.
#pragma once

#include "contactfx/config.h"
#include "contactfx/scene/rube.h"
#include "harness/command_line.h" // kCommandLine, CheckExtension
#include "harness/parse_errors.h" // NamesAFile: on every option and argument that names a file

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

namespace cfx::cli
{

/// Exit codes: 0 success, 1 any error (bad input, bad options, failed output).
inline constexpr int kExitOk = 0;
inline constexpr int kExitError = 1;

/// Options of commands that simulate.
struct RunOptions
{
    std::string scene;     ///< RUBE JSON file; empty: sceneName
    std::string sceneName; ///< --scene NAME, a registered scene (harness/scenes.h); empty: scene
    std::string preset;    ///< --preset default|tutorial; empty: the scene's effects, else default
    std::string effects;   ///< effects config file; empty: the preset
    double seconds = 20.0; ///< simulated time, (0, 86400]
    double hz = 60.0;      ///< step rate, [1, 10000]
    std::uint64_t seed = 1;
    std::string stats;           ///< stats file; empty: none
    std::string events;          ///< events file (JSON Lines); empty: none
    std::string audio;           ///< --audio: WAV of the built-in synthesizer; empty: none
    std::string voices;          ///< --voices: voices file (JSON Lines); empty: none
    bool checkParticles = false; ///< ParticleSystemOptions::checkParticles
    unsigned threads = 0;        ///< --threads: 0 (default) the machine's; N forces N threads per step
};

/// Flushes standard output and tells whether everything a command printed on it so far was written. On a
/// failed write (a full disk, `> /dev/full`), now or earlier, it reports "contactfx: error: standard
/// output: write failed[: reason]" on stderr, once per process, and returns false. A command calls it after
/// printing its summary and before committing its output files (outputs.h), so that a lost result leaves
/// no output either; main() calls it last.
bool FlushStandardOutput();

/// Adds --seconds, --hz, --seed, --stats, --preset and --effects to `command`; `demo` (a command on the
/// bundled tutorial scene) only changes the help of --effects.
void AddRunOptions(CLI::App& command, RunOptions& options, bool demo);

/// Adds --preset and --effects (the effects config every command that touches effects takes).
void AddEffectsOptions(CLI::App& command, RunOptions& options,
                       const std::string& effectsHelp = "Effects config JSON (overrides --preset)");

/// True when --preset or --effects was given: they replace a registered scene's effects.
bool EffectsChosen(const RunOptions& options);

/// Prints the warnings of a loaded scene (unknown keys, dropped polygon vertices) to stderr, one line each
/// ("contactfx: FILE: PATH: warning: ..."): a run goes on, but the author sees what was ignored. Also one
/// when the step rate (`stepsPerSecond`) of a scene file the user named is not the --hz the run steps at
/// (default 60; 60 is also what a file without `stepsPerSecond` is read as).
void PrintSceneWarnings(const Scene& scene, const RunOptions& options);

/// Checks ranges CLI11 cannot (NaN, infinities), and that --seconds at --hz makes at least one step
/// (round(seconds * hz) >= 1); throws InputError naming the flag.
void CheckRunOptions(const RunOptions& options);

/// The effects configuration the options select: --effects FILE, else --preset NAME, else the default
/// preset.
EffectsConfig SelectConfig(const RunOptions& options);

/// Runs `command`'s `body`, turning exceptions into one error line per problem on stderr and exit code 1.
/// When every problem is the command line's (a flag's value out of its range: `--hz 0`), a last line
/// points at the command's help, as after an error CLI11 finds while parsing.
int Guarded(const CLI::App& command, const std::function<int()>& body);

} // namespace cfx::cli
