#include "contactfx/sim/simulation.h"

#include <box2d/b2_body.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>
#include <nlohmann/json.hpp>

namespace cfx
{

void AssignSceneMaterials(const Scene& scene, Effects& effects, std::string_view file)
{
    std::vector<Diagnostic> problems;
    std::vector<int> fixturesSeen(scene.bodies.size(), 0);
    for (const SceneFixture& fixture : scene.fixtures)
    {
        const int indexInBody = fixturesSeen[static_cast<std::size_t>(fixture.bodyIndex)]++;
        for (std::size_t k = 0; k < fixture.properties.items.size(); ++k)
        {
            const CustomProperty& property = fixture.properties.items[k];
            if (property.name != "material")
            {
                continue;
            }
            const std::string path = "body[" + std::to_string(fixture.bodyIndex) + "].fixture[" +
                                     std::to_string(indexInBody) + "].customProperties[" + std::to_string(k) +
                                     "]";
            const std::string* name = std::get_if<std::string>(&property.value);
            if (name == nullptr)
            {
                problems.push_back({std::string(file), path, "expected the material as a string property"});
                continue;
            }
            const MaterialId material = effects.FindMaterial(*name);
            if (!material.IsValid())
            {
                std::string known;
                for (const std::string& each : effects.Config().materials)
                {
                    known += (known.empty() ? "" : ", ") + each;
                }
                problems.push_back(
                    {std::string(file), path + ".string",
                     "unknown material \"" + *name + "\" (the effects config has: " + known + ")"});
                continue;
            }
            effects.SetMaterial(fixture.fixture, material);
        }
    }
    if (!problems.empty())
    {
        throw InputError(std::move(problems));
    }
}

namespace
{

float CheckedHz(float hz)
{
    if (!(hz >= 1.0f && hz <= 10000.0f))
    {
        throw InputError("<api>", "hz", "expected a step rate in [1, 10000], found " + std::to_string(hz));
    }
    return hz;
}

} // namespace

Simulation::Simulation(const SimulationDef& def)
    : m_scene(LoadRubeFile(def.scene)), m_drive(def.drive), m_dt(1.0f / CheckedHz(def.hz))
{
    EffectsDef effectsDef;
    effectsDef.config = def.config;
    effectsDef.seed = def.seed;
    m_effects = std::make_unique<Effects>(*m_scene.world, effectsDef);
    AssignSceneMaterials(m_scene, *m_effects, def.scene.string());
    m_car = Car::Find(m_scene);
}

Simulation::~Simulation() = default;

void Simulation::SetInput(const DriveInput& input)
{
    m_manual = input;
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
    m_scene.world->Step(m_dt, m_scene.settings.velocityIterations, m_scene.settings.positionIterations);
    m_effects->Step(m_dt);
    ++m_steps;
}

std::string StatsJson(const Effects& effects, float hz)
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
        std::string a = config.rules[i].materialA;
        std::string b = config.rules[i].materialB;
        names.emplace_back(a < b ? a + "+" + b : b + "+" + a, i);
    }
    std::sort(names.begin(), names.end());
    Json rules = Json::object();
    for (const auto& [name, index] : names)
    {
        rules[name] =
            Json{{"contacts_max", stats.rules[index].contactsMax}, {"spawned", stats.rules[index].spawned}};
    }
    root["rules"] = rules;
    root["live_max"] = stats.liveMax;
    root["spawned_inside_solid"] = stats.spawnedInsideSolid;
    return root.dump(2) + "\n";
}

} // namespace cfx
