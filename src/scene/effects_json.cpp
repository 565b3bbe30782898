// Effects config JSON <-> EffectsConfig.
//
// One table per struct lists each JSON field with its member, so reading, writing and the unknown-field
// check cannot drift apart. Value ranges are checked once, by cfx::Validate, whose paths are the JSON
// paths because field names are member names.
#include "contactfx/scene/effects_json.h"

#include "contactfx/scene/text_file.h"
#include "scene/json_reader.h"
#include "scene/json_text.h"
#include "scene/json_writer.h"

#include <array>
#include <fstream>
#include <sstream>
#include <variant>

namespace cfx
{

namespace
{

using scene_detail::DiagnosticList;
using scene_detail::Json;
using scene_detail::ObjectReader;

// A named enum value.
template <typename E> struct EnumName
{
    E value;
    const char* name;
};

constexpr std::array kSpeedModes{EnumName<SpeedMode>{SpeedMode::full, "full"},
                                 EnumName<SpeedMode>{SpeedMode::tangential, "tangential"}};
constexpr std::array kFrictionMixes{
    EnumName<FrictionMix>{FrictionMix::product, "product"}, EnumName<FrictionMix>{FrictionMix::sqrt, "sqrt"},
    EnumName<FrictionMix>{FrictionMix::min, "min"}, EnumName<FrictionMix>{FrictionMix::max, "max"},
    EnumName<FrictionMix>{FrictionMix::mean, "mean"}};
constexpr std::array kManifoldPoints{EnumName<ManifoldPoints>{ManifoldPoints::first, "first"},
                                     EnumName<ManifoldPoints>{ManifoldPoints::all, "all"}};
constexpr std::array kEmissionModes{EnumName<EmissionMode>{EmissionMode::rate, "rate"},
                                    EnumName<EmissionMode>{EmissionMode::perStep, "perStep"}};
constexpr std::array kPlacements{EnumName<SpawnPlacement>{SpawnPlacement::surface, "surface"},
                                 EnumName<SpawnPlacement>{SpawnPlacement::tutorialDrop, "tutorialDrop"}};
constexpr std::array kBackends{EnumName<ParticleBackend>{ParticleBackend::pool, "pool"},
                               EnumName<ParticleBackend>{ParticleBackend::body, "body"}};
constexpr std::array kRecyclePolicies{EnumName<RecyclePolicy>{RecyclePolicy::oldest, "oldest"},
                                      EnumName<RecyclePolicy>{RecyclePolicy::lowestLife, "lowestLife"}};

constexpr std::array kBodyTypeFilters{EnumName<BodyTypeFilter>{BodyTypeFilter::any, "any"},
                                      EnumName<BodyTypeFilter>{BodyTypeFilter::staticBody, "static"},
                                      EnumName<BodyTypeFilter>{BodyTypeFilter::kinematicBody, "kinematic"},
                                      EnumName<BodyTypeFilter>{BodyTypeFilter::dynamicBody, "dynamic"}};

// One JSON field of struct S: a member of one of the supported kinds, or a nested enum.
template <typename S> struct Field
{
    const char* key;
    std::variant<float S::*, bool S::*, std::string S::*, std::uint16_t S::*, Color S::*,
                 std::optional<float> S::*>
        member;
};

const std::array kParticleFields{
    Field<ParticleTypeDef>{"name", &ParticleTypeDef::name},
    Field<ParticleTypeDef>{"lifeBase", &ParticleTypeDef::lifeBase},
    Field<ParticleTypeDef>{"lifeFromIntensity", &ParticleTypeDef::lifeFromIntensity},
    Field<ParticleTypeDef>{"lifetime", &ParticleTypeDef::lifetime},
    Field<ParticleTypeDef>{"inheritA", &ParticleTypeDef::inheritA},
    Field<ParticleTypeDef>{"inheritB", &ParticleTypeDef::inheritB},
    Field<ParticleTypeDef>{"slipFactor", &ParticleTypeDef::slipFactor},
    Field<ParticleTypeDef>{"normalSpeed", &ParticleTypeDef::normalSpeed},
    Field<ParticleTypeDef>{"spread", &ParticleTypeDef::spread},
    Field<ParticleTypeDef>{"gravityScale", &ParticleTypeDef::gravityScale},
    Field<ParticleTypeDef>{"drag", &ParticleTypeDef::drag},
    Field<ParticleTypeDef>{"collide", &ParticleTypeDef::collide},
    Field<ParticleTypeDef>{"radius", &ParticleTypeDef::radius},
    Field<ParticleTypeDef>{"restitution", &ParticleTypeDef::restitution},
    Field<ParticleTypeDef>{"friction", &ParticleTypeDef::friction},
    Field<ParticleTypeDef>{"categoryBits", &ParticleTypeDef::categoryBits},
    Field<ParticleTypeDef>{"maskBits", &ParticleTypeDef::maskBits},
    Field<ParticleTypeDef>{"density", &ParticleTypeDef::density},
    Field<ParticleTypeDef>{"colorStart", &ParticleTypeDef::colorStart},
    Field<ParticleTypeDef>{"colorEnd", &ParticleTypeDef::colorEnd},
    Field<ParticleTypeDef>{"sizeStart", &ParticleTypeDef::sizeStart},
    Field<ParticleTypeDef>{"sizeEnd", &ParticleTypeDef::sizeEnd},
    Field<ParticleTypeDef>{"streak", &ParticleTypeDef::streak},
};

const std::array kRuleFields{
    Field<RuleDef>{"materialA", &RuleDef::materialA},
    Field<RuleDef>{"materialB", &RuleDef::materialB},
    Field<RuleDef>{"particleType", &RuleDef::particleType},
    Field<RuleDef>{"threshold", &RuleDef::threshold},
    Field<RuleDef>{"ratePerIntensity", &RuleDef::ratePerIntensity},
    Field<RuleDef>{"maxRate", &RuleDef::maxRate},
    Field<RuleDef>{"scrapeEndDelay", &RuleDef::scrapeEndDelay},
    Field<RuleDef>{"impactThreshold", &RuleDef::impactThreshold},
    Field<RuleDef>{"burstPerSpeed", &RuleDef::burstPerSpeed},
    Field<RuleDef>{"burstMax", &RuleDef::burstMax},
};

// Optional bounds are written only when set.
const std::array kAssignmentFields{
    Field<MaterialAssignment>{"material", &MaterialAssignment::material},
    Field<MaterialAssignment>{"bodyName", &MaterialAssignment::bodyName},
    Field<MaterialAssignment>{"fixtureName", &MaterialAssignment::fixtureName},
    Field<MaterialAssignment>{"frictionAbove", &MaterialAssignment::frictionAbove},
    Field<MaterialAssignment>{"frictionBelow", &MaterialAssignment::frictionBelow},
    Field<MaterialAssignment>{"massAbove", &MaterialAssignment::massAbove},
    Field<MaterialAssignment>{"massBelow", &MaterialAssignment::massBelow},
};

const std::array kIntensityFields{
    Field<IntensityModel>{"impulseWeight", &IntensityModel::impulseWeight},
};

template <typename E, std::size_t N> const char* NameOf(const std::array<EnumName<E>, N>& names, E value)
{
    for (const EnumName<E>& entry : names)
    {
        if (entry.value == value)
        {
            return entry.name;
        }
    }
    return "?";
}

template <typename E, std::size_t N>
void ReadEnum(const ObjectReader& reader, const char* key, const std::array<EnumName<E>, N>& names, E& out)
{
    if (!reader.Has(key))
    {
        return;
    }
    std::string text = reader.String(key);
    for (const EnumName<E>& entry : names)
    {
        if (text == entry.name)
        {
            out = entry.value;
            return;
        }
    }
    std::string expected;
    for (const EnumName<E>& entry : names)
    {
        expected += (expected.empty() ? "\"" : ", \"") + std::string(entry.name) + "\"";
    }
    reader.Diagnostics().Add(reader.FieldPath(key), "expected one of " + expected + ", found " +
                                                        scene_detail::Describe(*reader.Find(key)));
}

std::optional<Color> ReadColor(const Json& value, const std::string& path, DiagnosticList& diagnostics)
{
    std::optional<std::vector<float>> channels =
        scene_detail::ReadFloatArray(value, path, diagnostics, scene_detail::kAnyFinite);
    if (!channels)
    {
        return std::nullopt;
    }
    if (channels->size() != 3 && channels->size() != 4)
    {
        diagnostics.Add(path, "expected [r, g, b] or [r, g, b, a], found " +
                                  std::to_string(channels->size()) + " numbers");
        return std::nullopt;
    }
    Color color{(*channels)[0], (*channels)[1], (*channels)[2],
                channels->size() == 4 ? (*channels)[3] : 1.0f};
    return color;
}

template <typename S, std::size_t N>
void ReadFields(const ObjectReader& reader, const std::array<Field<S>, N>& fields, S& out)
{
    for (const Field<S>& field : fields)
    {
        const Json* value = reader.Find(field.key);
        if (value == nullptr)
        {
            continue;
        }
        const std::string path = reader.FieldPath(field.key);
        DiagnosticList& diagnostics = reader.Diagnostics();
        std::visit(
            [&](auto member)
            {
                using T = std::remove_reference_t<decltype(out.*member)>;
                if constexpr (std::is_same_v<T, float>)
                {
                    out.*member = reader.Float(field.key, out.*member);
                }
                else if constexpr (std::is_same_v<T, bool>)
                {
                    out.*member = reader.Bool(field.key, out.*member);
                }
                else if constexpr (std::is_same_v<T, std::string>)
                {
                    out.*member = reader.String(field.key, out.*member);
                }
                else if constexpr (std::is_same_v<T, std::uint16_t>)
                {
                    out.*member = static_cast<std::uint16_t>(reader.Int(field.key, out.*member, 0, 0xFFFF));
                }
                else if constexpr (std::is_same_v<T, std::optional<float>>)
                {
                    out.*member = reader.OptionalFloat(field.key);
                }
                else
                {
                    if (std::optional<Color> color = ReadColor(*value, path, diagnostics))
                    {
                        out.*member = *color;
                    }
                }
            },
            field.member);
    }
}

// Reports fields that no table knows.
void CheckKnownKeys(const Json& object, const std::string& path,
                    std::initializer_list<std::string_view> extra, std::span<const char* const> known,
                    DiagnosticList& diagnostics)
{
    for (auto it = object.begin(); it != object.end(); ++it)
    {
        bool found = false;
        for (const char* key : known)
        {
            found = found || it.key() == key;
        }
        for (std::string_view key : extra)
        {
            found = found || it.key() == key;
        }
        if (!found)
        {
            diagnostics.Add(scene_detail::JoinPath(path, it.key()), "unknown field");
        }
    }
}

template <typename S, std::size_t N> std::vector<const char*> Keys(const std::array<Field<S>, N>& fields)
{
    std::vector<const char*> keys;
    for (const Field<S>& field : fields)
    {
        keys.push_back(field.key);
    }
    return keys;
}

// Calls `each(reader, index)` for every object of an array field.
template <typename F> void ForEachObject(const ObjectReader& parent, const char* key, F each)
{
    const Json* array = parent.Array(key);
    if (array == nullptr)
    {
        return;
    }
    for (std::size_t i = 0; i < array->size(); ++i)
    {
        const std::string path = scene_detail::IndexPath(parent.FieldPath(key), i);
        if (!(*array)[i].is_object())
        {
            parent.Diagnostics().Add(path,
                                     "expected an object, found " + scene_detail::Describe((*array)[i]));
            continue;
        }
        each(ObjectReader((*array)[i], path, parent.Diagnostics()), (*array)[i]);
    }
}

EffectsConfig ReadConfig(const Json& root, DiagnosticList& diagnostics)
{
    EffectsConfig config;
    if (!root.is_object())
    {
        diagnostics.Add("", "expected an object at the top level, found " + scene_detail::Describe(root));
        return config;
    }
    ObjectReader top(root, "", diagnostics);
    static constexpr const char* kTopKeys[] = {"name",  "materials", "particleTypes",
                                               "rules", "budget",    "assignments"};
    CheckKnownKeys(root, "", {}, kTopKeys, diagnostics);
    config.name = top.String("name");

    if (const Json* materials = top.Array("materials"))
    {
        for (std::size_t i = 0; i < materials->size(); ++i)
        {
            if (auto name = scene_detail::ReadString((*materials)[i], scene_detail::IndexPath("materials", i),
                                                     diagnostics))
            {
                config.materials.push_back(*name);
            }
        }
    }

    const std::vector<const char*> particleKeys = Keys(kParticleFields);
    ForEachObject(top, "particleTypes",
                  [&](const ObjectReader& reader, const Json& object)
                  {
                      ParticleTypeDef type;
                      CheckKnownKeys(object, reader.Path(), {"backend"}, particleKeys, diagnostics);
                      ReadFields(reader, kParticleFields, type);
                      ReadEnum(reader, "backend", kBackends, type.backend);
                      config.particleTypes.push_back(type);
                  });

    const std::vector<const char*> ruleKeys = Keys(kRuleFields);
    const std::vector<const char*> intensityKeys = Keys(kIntensityFields);
    ForEachObject(top, "rules",
                  [&](const ObjectReader& reader, const Json& object)
                  {
                      RuleDef rule;
                      CheckKnownKeys(object, reader.Path(), {"intensity", "emission", "placement"}, ruleKeys,
                                     diagnostics);
                      ReadFields(reader, kRuleFields, rule);
                      ReadEnum(reader, "emission", kEmissionModes, rule.emission);
                      ReadEnum(reader, "placement", kPlacements, rule.placement);
                      if (const Json* intensity = reader.Object("intensity"))
                      {
                          ObjectReader model(*intensity, reader.FieldPath("intensity"), diagnostics);
                          CheckKnownKeys(*intensity, model.Path(), {"speed", "friction", "points"},
                                         intensityKeys, diagnostics);
                          ReadFields(model, kIntensityFields, rule.intensity);
                          ReadEnum(model, "speed", kSpeedModes, rule.intensity.speed);
                          ReadEnum(model, "friction", kFrictionMixes, rule.intensity.friction);
                          ReadEnum(model, "points", kManifoldPoints, rule.intensity.points);
                      }
                      config.rules.push_back(rule);
                  });

    const std::vector<const char*> assignmentKeys = Keys(kAssignmentFields);
    ForEachObject(top, "assignments",
                  [&](const ObjectReader& reader, const Json& object)
                  {
                      MaterialAssignment assignment;
                      CheckKnownKeys(object, reader.Path(), {"bodyType"}, assignmentKeys, diagnostics);
                      ReadFields(reader, kAssignmentFields, assignment);
                      ReadEnum(reader, "bodyType", kBodyTypeFilters, assignment.bodyType);
                      config.assignments.push_back(assignment);
                  });

    if (const Json* budget = top.Object("budget"))
    {
        ObjectReader reader(*budget, "budget", diagnostics);
        static constexpr const char* kBudgetKeys[] = {"capacity", "recycle", "contacts"};
        CheckKnownKeys(*budget, "budget", {}, kBudgetKeys, diagnostics);
        config.budget.capacity = static_cast<std::uint32_t>(
            reader.Int("capacity", static_cast<int>(config.budget.capacity), 0, 1 << 30));
        ReadEnum(reader, "recycle", kRecyclePolicies, config.budget.recycle);
        config.budget.contacts = static_cast<std::uint32_t>(
            reader.Int("contacts", static_cast<int>(config.budget.contacts), 0, 1 << 30));
    }
    return config;
}

std::vector<Diagnostic> Parse(std::string_view text, std::string_view fileName, EffectsConfig& config)
{
    DiagnosticList diagnostics{std::string(fileName)};
    std::optional<Json> root = scene_detail::ParseJsonText(text, diagnostics);
    if (root)
    {
        config = ReadConfig(*root, diagnostics);
        if (diagnostics.Empty())
        {
            for (Diagnostic& problem : Validate(config, fileName))
            {
                diagnostics.Add(std::move(problem.path), std::move(problem.message));
            }
        }
    }
    return diagnostics.Take();
}

template <typename S, std::size_t N>
void WriteFields(Json& out, const std::array<Field<S>, N>& fields, const S& in)
{
    for (const Field<S>& field : fields)
    {
        std::visit(
            [&](auto member)
            {
                using T = std::remove_cvref_t<decltype(in.*member)>;
                if constexpr (std::is_same_v<T, float>)
                {
                    out[field.key] = scene_detail::ExactFloat(in.*member);
                }
                else if constexpr (std::is_same_v<T, std::optional<float>>)
                {
                    if (in.*member)
                    {
                        out[field.key] = scene_detail::ExactFloat(*(in.*member));
                    }
                }
                else if constexpr (std::is_same_v<T, Color>)
                {
                    const Color& c = in.*member;
                    out[field.key] =
                        Json::array({scene_detail::ExactFloat(c.r), scene_detail::ExactFloat(c.g),
                                     scene_detail::ExactFloat(c.b), scene_detail::ExactFloat(c.a)});
                }
                else
                {
                    out[field.key] = in.*member;
                }
            },
            field.member);
    }
}

} // namespace

EffectsConfig LoadEffectsString(std::string_view json, std::string_view fileName)
{
    EffectsConfig config;
    std::vector<Diagnostic> problems = Parse(json, fileName, config);
    if (!problems.empty())
    {
        throw InputError(std::move(problems));
    }
    return config;
}

EffectsConfig LoadEffectsFile(const std::filesystem::path& path)
{
    return LoadEffectsString(ReadTextFile(path), path.string());
}

std::vector<Diagnostic> ValidateEffectsFile(const std::filesystem::path& path)
{
    try
    {
        EffectsConfig config;
        return Parse(ReadTextFile(path), path.string(), config);
    }
    catch (const InputError& error)
    {
        return error.Diagnostics();
    }
}

std::string SaveEffectsString(const EffectsConfig& config)
{
    Json root = Json::object();
    root["name"] = config.name;
    root["materials"] = config.materials;
    root["particleTypes"] = Json::array();
    for (const ParticleTypeDef& type : config.particleTypes)
    {
        Json out = Json::object();
        WriteFields(out, kParticleFields, type);
        out["backend"] = NameOf(kBackends, type.backend);
        root["particleTypes"].push_back(out);
    }
    root["rules"] = Json::array();
    for (const RuleDef& rule : config.rules)
    {
        Json out = Json::object();
        WriteFields(out, kRuleFields, rule);
        out["emission"] = NameOf(kEmissionModes, rule.emission);
        out["placement"] = NameOf(kPlacements, rule.placement);
        Json intensity = Json::object();
        intensity["speed"] = NameOf(kSpeedModes, rule.intensity.speed);
        intensity["friction"] = NameOf(kFrictionMixes, rule.intensity.friction);
        intensity["points"] = NameOf(kManifoldPoints, rule.intensity.points);
        WriteFields(intensity, kIntensityFields, rule.intensity);
        out["intensity"] = intensity;
        root["rules"].push_back(out);
    }
    root["assignments"] = Json::array();
    for (const MaterialAssignment& assignment : config.assignments)
    {
        Json out = Json::object();
        WriteFields(out, kAssignmentFields, assignment);
        out["bodyType"] = NameOf(kBodyTypeFilters, assignment.bodyType);
        root["assignments"].push_back(out);
    }
    root["budget"] = Json{{"capacity", config.budget.capacity},
                          {"recycle", NameOf(kRecyclePolicies, config.budget.recycle)},
                          {"contacts", config.budget.contacts}};
    return root.dump(2) + "\n";
}

void SaveEffectsFile(const EffectsConfig& config, const std::filesystem::path& path)
{
    WriteTextFileAtomically(path, SaveEffectsString(config));
}

} // namespace cfx
