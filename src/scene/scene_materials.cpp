// Scene fixtures -> materials: the fixture's `material` property first, then its body's, then the config's
// assignment rules.
//
// Every bad property of the scene is collected before anything is thrown, so a user fixes the file in one
// pass, and no fixture is touched unless the whole scene resolves.
#include "contactfx/scene/scene_materials.h"

#include "contactfx/effects.h"
#include "quoted_text.h"
#include "scene/json_reader.h"
#include "scene/known_keys.h"

#include <box2d/b2_body.h>
#include <box2d/b2_fixture.h>
#include <optional>
#include <string>
#include <variant>

namespace cfx
{

namespace
{

/// A property that is not a string, as the file has it: "int property 4", "vec2 property".
std::string DescribeNonString(const CustomProperty& property)
{
    struct Describe
    {
        std::string operator()(int value) const { return "int property " + std::to_string(value); }
        std::string operator()(float value) const
        {
            return "float property " + scene_detail::FormatFloat(value);
        }
        std::string operator()(const std::string&) const { return "string property"; }
        std::string operator()(bool value) const
        {
            return value ? "bool property true" : "bool property false";
        }
        std::string operator()(const b2Vec2&) const { return "vec2 property"; }
        std::string operator()(const Rgba8&) const { return "color property"; }
    };
    return std::visit(Describe{}, property.value);
}

// Whether `name` looks like a misspelt `material`: one edit from it, a case slip included ("Material",
// "materal", "materials"). Only looked at on an object without a `material` property, and only for string
// properties: "materialId" or "subMaterial" are properties of their own.
bool MisspeltMaterial(std::string_view name)
{
    return detail::TypoDistance(name, "material") == 1;
}

// The material an object's (body's or fixture's) custom properties name: nullopt when it has no `material`
// property, an invalid id when it names a bad one (the problem is added to `problems`). `at`: the object's
// JSON path ("body[1].fixture[0]").
std::optional<MaterialId> MaterialProperty(const CustomProperties& properties, const std::string& at,
                                           const EffectsConfig& config, std::string_view file,
                                           detail::SuggestionBudget& budget,
                                           std::vector<Diagnostic>& problems)
{
    std::optional<MaterialId> found;
    std::size_t first = 0; // the property `found` came from
    for (std::size_t k = 0; k < properties.items.size(); ++k)
    {
        const CustomProperty& property = properties.items[k];
        const std::string path = at + ".customProperties[" + std::to_string(k) + "]";
        if (property.name != "material")
        {
            // A typo of it gives the object no material, silently (a trial lost 80 % of its dust).
            if (properties.Find("material") == nullptr && MisspeltMaterial(property.name) &&
                std::holds_alternative<std::string>(property.value))
            {
                problems.push_back({std::string(file), path + ".name",
                                    "a custom property named " + detail::QuotedText(property.name) +
                                        ", did you mean `material`? (it gives no material)"});
            }
            continue;
        }
        if (found)
        {
            problems.push_back({std::string(file), path + ".name",
                                "a second `material` property (the first is customProperties[" +
                                    std::to_string(first) + "])"});
            continue;
        }
        found = MaterialId{};
        first = k;
        const std::string* name = std::get_if<std::string>(&property.value);
        if (name == nullptr)
        {
            problems.push_back(
                {std::string(file), path,
                 "expected the material as a string property, found " + DescribeNonString(property)});
            continue;
        }
        const MaterialId material = config.FindMaterial(*name);
        if (!material.IsValid())
        {
            problems.push_back(
                {std::string(file), path + ".string",
                 "unknown material " + detail::QuotedText(*name) +
                     detail::DidYouMean(*name, config.materials, budget) + " (the effects config" +
                     (config.name.empty() ? std::string() : " " + detail::QuotedText(config.name)) +
                     " has: " + detail::NameList(config.materials, "no materials") + ")"});
            continue;
        }
        found = material;
    }
    return found;
}

} // namespace

std::vector<MaterialId> ResolveSceneMaterials(const Scene& scene, const EffectsConfig& config,
                                              std::string_view file)
{
    std::vector<Diagnostic> problems;
    detail::SuggestionBudget budget;
    std::vector<std::optional<MaterialId>> bodyMaterials(scene.bodies.size());
    for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    {
        bodyMaterials[b] = MaterialProperty(scene.bodies[b].properties, "body[" + std::to_string(b) + "]",
                                            config, file, budget, problems);
    }
    std::vector<MaterialId> materials(scene.fixtures.size());
    std::vector<int> fixturesSeen(scene.bodies.size(), 0);
    for (std::size_t f = 0; f < scene.fixtures.size(); ++f)
    {
        const SceneFixture& fixture = scene.fixtures[f];
        const std::size_t body = static_cast<std::size_t>(fixture.bodyIndex);
        const std::string at =
            "body[" + std::to_string(body) + "].fixture[" + std::to_string(fixturesSeen[body]++) + "]";
        const std::optional<MaterialId> own =
            MaterialProperty(fixture.properties, at, config, file, budget, problems);
        if (own || bodyMaterials[body])
        {
            materials[f] = own ? *own : *bodyMaterials[body];
        }
        else if (fixture.fixture != nullptr)
        {
            const FixtureFacts facts = FactsOf(*fixture.fixture, scene.bodies[body].name, fixture.name);
            if (std::optional<std::size_t> rule = FirstMatch(config.assignments, facts))
            {
                materials[f] = config.FindMaterial(config.assignments[*rule].material);
            }
        }
    }
    if (!problems.empty())
    {
        throw InputError(std::move(problems));
    }
    return materials;
}

void AssignSceneMaterials(const Scene& scene, Effects& effects, std::string_view file)
{
    const std::vector<MaterialId> materials = ResolveSceneMaterials(scene, effects.Config(), file);
    for (std::size_t f = 0; f < scene.fixtures.size(); ++f)
    {
        if (materials[f].IsValid())
        {
            effects.SetMaterial(scene.fixtures[f].fixture, materials[f]);
            if (scene.fixtures[f].backSide != nullptr)
            {
                effects.SetMaterial(scene.fixtures[f].backSide, materials[f]);
            }
        }
    }
}

} // namespace cfx
