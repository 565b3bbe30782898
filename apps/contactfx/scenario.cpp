#include "scenario.h"

#include "contactfx/error.h"
#include "suggest.h"

#include <vector>

namespace cfx::cli
{

namespace
{

const SceneEntry& FindRegisteredScene(const std::string& name)
{
    if (const SceneEntry* entry = FindScene(name))
    {
        return *entry;
    }
    std::vector<std::string> names;
    for (const SceneEntry& entry : Scenes())
    {
        names.emplace_back(entry.name);
    }
    const std::string suggestion = DidYouMean(name, names);
    throw InputError(kCommandLine, "--scene",
                     "unknown scene \"" + name + "\"" + (suggestion.empty() ? "" : "; " + suggestion) +
                         " (scenes: " + SceneNames() + ")");
}

} // namespace

void Scenario::Step(Simulation& simulation) const
{
    if (entry != nullptr)
    {
        StepScene(*entry, simulation);
    }
    else
    {
        simulation.Step();
    }
}

void AddSceneOptions(CLI::App& command, RunOptions& options, const std::string& fileHelp)
{
    command.add_option("scene", options.scene, fileHelp)->check(NamesAFile());
    command.add_option("--scene", options.sceneName,
                       "A registered scene with its scripted drive and effects: " + SceneNames());
}

Scenario SelectScenario(const RunOptions& options)
{
    const bool file = !options.scene.empty();
    const bool named = !options.sceneName.empty();
    if (file == named)
    {
        throw InputError(kCommandLine, "scene",
                         file ? "give either a scene file or --scene NAME, not both"
                              : "give a scene file or --scene NAME (" + SceneNames() + ")");
    }
    Scenario scenario;
    if (named)
    {
        scenario.entry = &FindRegisteredScene(options.sceneName);
        scenario.def = SceneSimulationDef(*scenario.entry, BundledScenesDir());
        if (EffectsChosen(options))
        {
            scenario.def.config = SelectConfig(options);
        }
    }
    else
    {
        CheckNotASceneName(options.scene);
        scenario.def.scene = options.scene;
        scenario.def.config = SelectConfig(options);
    }
    scenario.def.seed = options.seed;
    scenario.def.hz = static_cast<float>(options.hz);
    scenario.def.particles.checkParticles = options.checkParticles;
    if (options.threads > 0)
    {
        scenario.def.particles.threads = options.threads; // forced: split whatever the particle count
        scenario.def.particles.minParticlesPerThread = 1;
    }
    return scenario;
}

void AddScenarioInputs(OutputFiles& outputs, const RunOptions& options, const Scenario& scenario)
{
    outputs.AddInput(options.scene);
    outputs.AddInput(options.effects);
    outputs.AddInput(scenario.def.scene);
    if (scenario.entry != nullptr && !scenario.entry->effectsFile.empty())
    {
        outputs.AddInput(BundledScenesDir() / scenario.entry->effectsFile);
    }
}

} // namespace cfx::cli
