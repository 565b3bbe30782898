// contactfx_harness (the demo harness, not installed): the named scenes, written once.
//
// Every front end that shows or measures a scenario (the testbed's scene list, the CLI, the tests, the
// benchmarks) takes it from this one registry instead of repeating its file, drive and camera. A scene
// is a RUBE file in scenes/ whose fixtures name their material in the custom property `material`, an
// optional effects config (else the default preset), an optional scripted drive of its car, an
// optional per-step action, where to look, and the particle types it is built to show (checked by
// tests/sim/scenes_test.cpp).
#pragma once

#include "harness/car.h"
#include "harness/simulation.h"

#include <box2d/b2_math.h>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace cfx
{

/// Where a viewer looks.
struct SceneView
{
    b2Vec2 center{0.0f, 0.0f}; ///< m, world point at the middle of the picture
    float height = 20.0f;      ///< m of world from the bottom of the picture to its top, > 0
    bool wholeWorld = false;   ///< show every body of the world instead (as `contactfx render` does)
};

/// One registered scene. Plain data with static storage: entries live as long as the program.
struct SceneEntry
{
    std::string_view name{};        ///< what `--scene` takes, e.g. "tutorial"
    std::string_view title{};       ///< one line for lists and help
    std::string_view file{};        ///< RUBE JSON, relative to the scenes folder
    std::string_view effectsFile{}; ///< effects config relative to the scenes folder; empty: DefaultPreset()
    std::span<const DriveSegment> drive{}; ///< scripted input of the scene's car; empty: none
    /// Called before every step with the running simulation (e.g. puts rocks that came to rest back
    /// at the top); may be null. Must be a pure function of the simulation's state (determinism).
    void (*beforeStep)(Simulation& simulation) = nullptr;
    SceneView view;
    bool followCar = false;                    ///< the view follows the body named "car"
    std::span<const std::string_view> makes{}; ///< particle types the scene promises to emit
};

/// Every registered scene, "tutorial" first, in a fixed order.
std::span<const SceneEntry> Scenes();

/// The scene with this name, or nullptr.
const SceneEntry* FindScene(std::string_view name);

/// "tutorial, grinder, ..." for help texts and error messages.
std::string SceneNames();

/// Throws InputError (file "<command line>", path "scene") when `file`, given as a scene file, names no
/// file but is a registered scene's name (`contactfx run grinder`, where --scene grinder was meant).
void CheckNotASceneName(const std::string& file);

/// The folder of the bundled scenes: $CONTACTFX_SCENES when set and not empty, else
/// <folder of the running program>/../share/contactfx/scenes (where both the build tree and an installed
/// prefix keep them). Never depends on the source tree.
std::filesystem::path BundledScenesDir();

/// How to build the simulation of `entry`: its file and drive under `scenesDir`, its effects config
/// (read from its effects file, which throws InputError naming the file when bad, or the default
/// preset), seed 1, 60 Hz. Callers may change the config, seed and rate before creating it.
SimulationDef SceneSimulationDef(const SceneEntry& entry, const std::filesystem::path& scenesDir);

/// One step of a registered scene: its per-step action (if any), then simulation.Step().
void StepScene(const SceneEntry& entry, Simulation& simulation);

} // namespace cfx
