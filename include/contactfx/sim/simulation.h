// contactfx_sim: a scene, its effects and its driver, stepped together.
//
// What the CLI, the tests, the benchmarks and the testbed all do: load a RUBE scene, give its fixtures
// the materials named by their custom property `material`, attach an Effects object, and step world and
// effects at a fixed rate, with the tutorial car driven by a script or by the keyboard.
#pragma once

#include "contactfx/effects.h"
#include "contactfx/presets.h"
#include "contactfx/scene/rube.h"
#include "contactfx/sim/car.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace cfx
{

/// Gives every fixture of `scene` the material its custom property `material` names. Throws
/// InputError naming `file` and the property's JSON path (e.g.
/// `body[1].fixture[0].customProperties[0].string`) for a name the config does not know.
void AssignSceneMaterials(const Scene& scene, Effects& effects, std::string_view file);

struct SimulationDef
{
    std::filesystem::path scene; ///< RUBE JSON file
    EffectsConfig config = DefaultPreset();
    std::uint64_t seed = 1;
    float hz = 60.0f;                    ///< steps per second, in [1, 10000]
    std::span<const DriveSegment> drive; ///< scripted input for the scene's car; empty: no driver
};

class Simulation
{
public:
    /// Loads and prepares everything; throws InputError on bad input.
    explicit Simulation(const SimulationDef& def);
    ~Simulation();

    /// One world step and one effects step of 1/hz seconds. The script (if any) sets the car's input.
    void Step();

    /// Overrides the script from now on (the testbed's keyboard).
    void SetInput(const DriveInput& input);

    float Dt() const { return m_dt; }
    float Time() const { return static_cast<float>(m_steps) * m_dt; }
    std::uint64_t Steps() const { return m_steps; }
    Scene& GetScene() { return m_scene; }
    const Scene& GetScene() const { return m_scene; }
    Effects& GetEffects() { return *m_effects; }
    const Effects& GetEffects() const { return *m_effects; }
    const std::optional<Car>& GetCar() const { return m_car; }

private:
    Scene m_scene;
    std::unique_ptr<Effects> m_effects; // before the scene's world goes: declared after m_scene
    std::optional<Car> m_car;
    std::span<const DriveSegment> m_drive;
    std::optional<DriveInput> m_manual;
    float m_dt;
    std::uint64_t m_steps = 0;
};

/// The stats file of the CLI: {"steps", "hz", "seconds", "spawned": {TYPE: n}, "rules": {"A+B":
/// {"contacts_max", "spawned"}}, "live_max", "spawned_inside_solid"}; rule names sorted, every type and
/// rule present.
std::string StatsJson(const Effects& effects, float hz);

} // namespace cfx
