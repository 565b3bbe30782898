// contactfx_harness (the demo harness, not installed): a scene, its effects and its driver, stepped together.
//
// What the CLI, the tests, the benchmarks and the testbed all do: load a RUBE scene, give its fixtures
// their materials (their custom property `material`, else the config's assignments), attach an Effects
// object, and step world and effects at a fixed rate, with the tutorial car driven by a script or by the
// keyboard.
#pragma once

#include "contactfx/effects.h"
#include "contactfx/presets.h"
#include "contactfx/scene/rube.h"
#include "contactfx/scene/scene_materials.h"
#include "harness/car.h"
#include "harness/state_hash.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace cfx
{

struct SimulationDef
{
    std::filesystem::path scene; ///< RUBE JSON file
    EffectsConfig config = DefaultPreset();
    std::uint64_t seed = 1;
    /// Steps per second, in [1, 10000]; 0: the scene's own `stepsPerSecond`, brought into [1, 10000].
    float hz = 60.0f;
    std::span<const DriveSegment> drive; ///< scripted input for the scene's car; empty: no driver
    ParticleSystemOptions particles;     ///< threads, and the particle check (checkParticles)
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

    /// Replaces the effects by ones made from `config` (same seed), keeping the world as it is: bodies,
    /// joints and touching contacts stay (the new effects pick the contacts up at the next step);
    /// particles and counters start afresh. Throws InputError, leaving everything as it was, when
    /// `config` is invalid or lacks a material that the scene's fixtures name. `config` may be
    /// GetEffects().Config(). The testbed's live edits.
    void ReplaceEffects(const EffectsConfig& config);

    /// Wall-clock cost of the last Step(), for statistics panels; never affects the simulation.
    struct StepTimes
    {
        double worldMs = 0.0;   ///< b2World::Step
        double effectsMs = 0.0; ///< Effects::Step
    };
    const StepTimes& LastStepTimes() const { return m_times; }

    float Dt() const { return m_dt; }
    float Time() const { return static_cast<float>(m_steps) * m_dt; }
    std::uint64_t Steps() const { return m_steps; }
    Scene& GetScene() { return m_scene; }
    const Scene& GetScene() const { return m_scene; }
    Effects& GetEffects() { return *m_effects; }
    const Effects& GetEffects() const { return *m_effects; }
    const std::optional<Car>& GetCar() const { return m_car; }
    /// The run's hash (state_hash.h): every event reported since the start (or the last ReplaceEffects),
    /// then the live particles now. The events of EndScrapes() are not in it.
    StateHash RunHash() const;

    /// Ends the scrapes still going as the run stops (Effects::EndScrapes): their scrapeEnded events,
    /// reason ScrapeEnd::stopped, in id order, at the last step (so their time is Time()). Valid until the
    /// next Step(); empty before the first.
    std::span<const EffectEvent> EndScrapes();

private:
    Scene m_scene;
    std::unique_ptr<Effects> m_effects; // before the scene's world goes: declared after m_scene
    std::optional<Car> m_car;
    std::span<const DriveSegment> m_drive;
    std::optional<DriveInput> m_manual;
    std::string m_sceneFile; // for diagnostics
    std::uint64_t m_seed;
    ParticleSystemOptions m_particleOptions;
    float m_dt;
    std::uint64_t m_steps = 0;
    StepTimes m_times;
    StateHash m_events; // every event so far
};

/// The stats file of the CLI: {"steps", "hz", "seconds", "spawned": {TYPE: n}, "rules": {"A+B":
/// {"contacts_max", "spawned", "spawn_rejected", "impacts", "intensity_max", "approach_max" (m/s, the fastest
/// new touch, impact or not)}}, "live_max", "spawned_inside_solid", "crushed",
/// "particle_steps_inside", "crossings", "passed_through_moving", "spawn_rejected", "spawn_over_capacity",
/// "non_finite", "skipped_bodies", "dropped_hit_groups", "non_finite_samples", "stale_materials",
/// "static_geometry_builds", "state_hash"}; rule names sorted, every type and rule present; "state_hash"
/// (Simulation::RunHash, 16 hexadecimal digits) only when given.
std::string StatsJson(const Effects& effects, float hz, const StateHash* runHash = nullptr);

/// One line of the CLI's events file (JSON Lines, newline included): {"type" (scrape_began,
/// scrape_changed, scrape_ended, impact), "step", "time" (s simulated when reported), "id", "pair"
/// ("A+B", names sorted), "point": [x, y], "normal": [x, y], then "intensity", "tangential_speed",
/// "normal_impulse" for scrapes, "reason" for ended scrapes ("contact_ended", "asleep",
/// "below_threshold", "destroyed", "material_changed", or "run_ended" for those of Simulation::EndScrapes),
/// "approach_speed", "normal_impulse" for impacts}; particle hits: {"type": "particle_hits", "step", "time",
/// "particle_type" (its name), "count", "point": [x, y] (their mean touch point), "mean_speed" (m/s)}.
std::string EventJsonLine(const EffectEvent& event, const EffectsConfig& config, double hz);

} // namespace cfx
