// What a simulating command (demo, run, render) simulates: a registered scene, with its scripted drive,
// per-step action and effects file, or a RUBE scene file as it is. One code path for all three.
#pragma once

#include "cli_common.h"
#include "harness/scenes.h"
#include "harness/simulation.h"
#include "outputs.h"

#include <CLI/CLI.hpp>
#include <string>

namespace cfx::cli
{

/// A simulation ready to be created, and how to step it.
struct Scenario
{
    SimulationDef def;                 ///< scene file, effects, seed, rate, drive
    const SceneEntry* entry = nullptr; ///< the registered scene; null for a scene file

    /// One step: the registered scene's per-step action (if any), then simulation.Step().
    void Step(Simulation& simulation) const;
};

/// Adds the scene a command simulates: the positional SCENE.json (`fileHelp`) or --scene NAME.
void AddSceneOptions(CLI::App& command, RunOptions& options, const std::string& fileHelp);

/// The scenario `options` select, with their --seed and --hz:
/// - --scene NAME: the registered scene's file (under BundledScenesDir()), drive, per-step action and
///   effects file, unless --preset or --effects replace the effects (its effects file is read even then);
/// - a scene file: that file without drive or action, effects from SelectConfig().
/// Throws InputError ("<command line>", "scene" or "--scene") when both or neither are given, or NAME
/// is not registered (listing the registered names and suggesting the nearest); and what reading the
/// effects file throws. Loads no scene: Simulation(def) does.
Scenario SelectScenario(const RunOptions& options);

/// Registers the files `scenario` reads (scene file, effects file; for a registered scene its bundled
/// files) as inputs of `outputs`, which may then not overwrite them.
void AddScenarioInputs(OutputFiles& outputs, const RunOptions& options, const Scenario& scenario);

} // namespace cfx::cli
