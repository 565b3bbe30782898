#include "harness/simulation.h"

#include <algorithm>
#include <box2d/b2_body.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>
#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace cfx
{

namespace
{

constexpr float kLowestHz = 1.0f;
constexpr float kHighestHz = 10000.0f;

float CheckedHz(float hz)
{
    if (!(hz >= kLowestHz && hz <= kHighestHz))
    {
        throw InputError("<api>", "hz", "expected a step rate in [1, 10000], found " + std::to_string(hz));
    }
    return hz;
}

} // namespace

Simulation::Simulation(const SimulationDef& def)
    : m_scene(LoadRubeFile(def.scene)), m_drive(def.drive), m_sceneFile(def.scene.string()), m_seed(def.seed),
      m_particleOptions(def.particles),
      m_dt(1.0f / CheckedHz(def.hz == 0.0f
                                ? std::clamp(m_scene.settings.stepsPerSecond, kLowestHz, kHighestHz)
                                : def.hz))
{
    EffectsDef effectsDef;
    effectsDef.config = def.config;
    effectsDef.seed = def.seed;
    effectsDef.particles = def.particles;
    m_effects = std::make_unique<Effects>(*m_scene.world, effectsDef);
    AssignSceneMaterials(m_scene, *m_effects, def.scene.string());
    m_car = Car::Find(m_scene);
}

Simulation::~Simulation() = default;

void Simulation::SetInput(const DriveInput& input)
{
    m_manual = input;
}

void Simulation::ReplaceEffects(const EffectsConfig& config)
{
    std::vector<Diagnostic> problems = Validate(config);
    if (!problems.empty())
    {
        throw InputError(std::move(problems));
    }
    ResolveSceneMaterials(m_scene, config, m_sceneFile); // throws before anything changes
    EffectsDef effectsDef;
    effectsDef.config = config; // copied before the old effects go: `config` may be theirs
    effectsDef.seed = m_seed;
    effectsDef.particles = m_particleOptions;
    // Fixtures made after the scene was loaded (a ball the testbed launched) keep their material by name;
    // the scene's own get theirs from its file and the new configuration's assignment rules, as on a
    // restart.
    std::unordered_set<const b2Fixture*> fromFile;
    for (const SceneFixture& fixture : m_scene.fixtures)
    {
        fromFile.insert(fixture.fixture);
        fromFile.insert(fixture.backSide);
    }
    std::vector<std::pair<b2Fixture*, std::string>> given;
    const EffectsConfig& old = m_effects->Config();
    for (b2Body* body = m_scene.world->GetBodyList(); body != nullptr; body = body->GetNext())
    {
        for (b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext())
        {
            const MaterialId material = m_effects->Material(fixture);
            if (material.IsValid() && !fromFile.contains(fixture))
            {
                given.emplace_back(fixture, old.materials[material.index]);
            }
        }
    }
    // The old effects put the world's listeners back before the new ones install theirs.
    m_effects.reset();
    m_effects = std::make_unique<Effects>(*m_scene.world, effectsDef);
    AssignSceneMaterials(m_scene, *m_effects, m_sceneFile);
    for (const auto& [fixture, name] : given)
    {
        const MaterialId material = m_effects->FindMaterial(name);
        if (material.IsValid())
        {
            m_effects->SetMaterial(fixture, material);
        }
    }
}

std::span<const EffectEvent> Simulation::EndScrapes()
{
    m_effects->EndScrapes();
    return m_effects->Events();
}

void Simulation::Step()
{
    if (m_car)
    {
        if (m_manual)
        {
            m_car->Apply(*m_manual);
        }
        else if (!m_drive.empty())
        {
            m_car->Apply(InputAt(m_drive, Time()));
        }
    }
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    m_scene.world->Step(m_dt, m_scene.settings.velocityIterations, m_scene.settings.positionIterations);
    const Clock::time_point stepped = Clock::now();
    m_effects->Step(m_dt);
    m_events.Add(m_effects->Events());
    m_times.worldMs = std::chrono::duration<double, std::milli>(stepped - start).count();
    m_times.effectsMs = std::chrono::duration<double, std::milli>(Clock::now() - stepped).count();
    ++m_steps;
}

std::string EventJsonLine(const EffectEvent& event, const EffectsConfig& config, double hz)
{
    using Json = nlohmann::ordered_json;
    static constexpr const char* kTypes[] = {"scrape_began", "scrape_changed", "scrape_ended", "impact",
                                             "particle_hits"};
    // ScrapeEnd::stopped: the run stopped (Simulation::EndScrapes).
    static constexpr const char* kReasons[] = {
        "none", "contact_ended", "asleep", "below_threshold", "destroyed", "run_ended", "material_changed"};
    static_assert(std::size(kReasons) == static_cast<std::size_t>(ScrapeEnd::materialChanged) + 1);
    Json line;
    line["type"] = kTypes[static_cast<int>(event.type)];
    line["step"] = event.step;
    line["time"] = static_cast<double>(event.step + 1) / hz;
    if (event.type == EffectEventType::particleHits)
    {
        line["particle_type"] = config.particleTypes[event.particleType.index].name;
        line["count"] = event.count;
        line["point"] = Json::array({event.point.x, event.point.y});
        line["mean_speed"] = event.approachSpeed;
        return line.dump() + "\n";
    }
    line["id"] = event.id;
    line["pair"] = PairName(config.rules[event.rule.index]);
    line["point"] = Json::array({event.point.x, event.point.y});
    line["normal"] = Json::array({event.normal.x + 0.0f, event.normal.y + 0.0f}); // + 0: no "-0.0"
    if (event.type == EffectEventType::impact)
    {
        line["approach_speed"] = event.approachSpeed;
        line["normal_impulse"] = event.normalImpulse;
    }
    else if (event.type == EffectEventType::scrapeEnded)
    {
        line["reason"] = kReasons[static_cast<int>(event.end)];
    }
    else
    {
        line["intensity"] = event.intensity;
        line["tangential_speed"] = event.tangentialSpeed;
        line["normal_impulse"] = event.normalImpulse;
    }
    return line.dump() + "\n";
}

StateHash Simulation::RunHash() const
{
    StateHash hash = m_events;
    hash.Add(m_effects->Particles());
    return hash;
}

std::string StatsJson(const Effects& effects, float hz, const StateHash* runHash)
{
    using Json = nlohmann::ordered_json;
    const EffectsConfig& config = effects.Config();
    const EffectsStats& stats = effects.Stats();
    Json root;
    root["steps"] = stats.steps;
    root["hz"] = hz;
    root["seconds"] = static_cast<double>(stats.steps) / static_cast<double>(hz);
    Json spawned = Json::object();
    for (std::size_t i = 0; i < config.particleTypes.size(); ++i)
    {
        spawned[config.particleTypes[i].name] = stats.spawnedByType[i];
    }
    root["spawned"] = spawned;
    std::vector<std::pair<std::string, std::size_t>> names;
    for (std::size_t i = 0; i < config.rules.size(); ++i)
    {
        names.emplace_back(PairName(config.rules[i]), i);
    }
    std::sort(names.begin(), names.end());
    Json rules = Json::object();
    for (const auto& [name, index] : names)
    {
        const RuleStats& rule = stats.rules[index];
        rules[name] = Json{{"contacts_max", rule.contactsMax},     {"spawned", rule.spawned},
                           {"spawn_rejected", rule.spawnRejected}, {"impacts", rule.impacts},
                           {"intensity_max", rule.intensityMax},   {"approach_max", rule.approachMax}};
    }
    root["rules"] = rules;
    root["live_max"] = stats.liveMax;
    root["recycled"] = stats.recycled;
    root["spawned_inside_solid"] = stats.spawnedInsideSolid;
    root["crushed"] = stats.crushed;
    root["particle_steps_inside"] = stats.particleStepsInside;
    root["crossings"] = stats.crossings;
    root["passed_through_moving"] = stats.passedThroughMoving;
    root["spawn_rejected"] = stats.spawnRejected;
    root["spawn_over_capacity"] = stats.spawnOverCapacity;
    root["non_finite"] = stats.nonFinite;
    root["skipped_bodies"] = stats.skippedBodies;
    root["dropped_hit_groups"] = stats.droppedHitGroups;
    root["non_finite_samples"] = stats.nonFiniteSamples;
    root["stale_materials"] = stats.staleMaterials;
    root["static_geometry_builds"] = stats.staticGeometryBuilds;
    if (runHash != nullptr)
    {
        root["state_hash"] = runHash->Hex();
    }
    return root.dump(2) + "\n";
}

} // namespace cfx
