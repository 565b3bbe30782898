// Effects config JSON <-> EffectsConfig.
//
// The field tables of contactfx/config_fields.h drive reading, writing and the unknown-field check, so the
// three cannot drift apart from each other, from cfx::Validate or from the docs. Value ranges and names are
// checked once, by cfx::Validate, whose paths are the JSON paths because field names are member names; it
// runs in the same pass as reading, so that a file with a misspelt field and a zero lifetime reports both.
#include "contactfx/scene/effects_json.h"

#include "contactfx/config_fields.h"
#include "contactfx/files/text_file.h"
#include "scene/json_reader.h"
#include "scene/json_text.h"
#include "scene/json_writer.h"
#include "scene/known_keys.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <variant>

namespace cfx
{

namespace
{

using scene_detail::DiagnosticList;
using scene_detail::Json;
using scene_detail::ObjectReader;

template <typename S> bool IsNested(const Field<S>& field)
{
    return std::holds_alternative<IntensityModel S::*>(field.member);
}

void ReadChoice(const ObjectReader& reader, std::string_view key, std::span<const std::string_view> names,
                int& out)
{
    const Json* value = reader.Find(key);
    if (value == nullptr)
    {
        return;
    }
    for (std::size_t i = 0; value->is_string() && i < names.size(); ++i)
    {
        if (value->get_ref<const std::string&>() == names[i])
        {
            out = static_cast<int>(i);
            return;
        }
    }
    // One message for any other value, a string or not: what the field takes.
    std::string expected;
    for (std::string_view name : names)
    {
        expected += (expected.empty() ? "\"" : ", \"") + std::string(name) + "\"";
    }
    reader.Diagnostics().Add(reader.FieldPath(key),
                             "expected one of " + expected + ", found " + scene_detail::Describe(*value));
}

// `range`: each channel's. When a channel is not a number, the colour is not read, and Validate sees none
// of it: the other channels' range problems are reported here, so that every problem comes at once.
std::optional<Color> ReadColor(const Json& value, const std::string& path, const FieldRange& range,
                               DiagnosticList& diagnostics)
{
    std::optional<std::vector<float>> channels =
        scene_detail::ReadFloatArray(value, path, diagnostics, scene_detail::kAnyFinite);
    if (!channels)
    {
        for (std::size_t i = 0; value.is_array() && i < value.size(); ++i)
        {
            const Json& channel = value[i];
            // Numbers beyond the float range are the array reader's to report.
            if (channel.is_number() && std::abs(channel.get<double>()) <= std::numeric_limits<float>::max() &&
                !range.Contains(channel.get<float>()))
            {
                diagnostics.Add(path + "[" + std::to_string(i) + "]",
                                "expected " + ExpectedNumber(range) + ", found " + channel.dump());
            }
        }
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

// The whole number `value` holds when it is one within `range`, else nothing.
std::optional<long long> IntegerIn(const Json& value, const FieldRange& range)
{
    double number = 0.0;
    if (value.is_number_unsigned())
    {
        const auto whole = value.get<std::uint64_t>();
        if (whole > static_cast<std::uint64_t>(range.max))
        {
            return std::nullopt;
        }
        number = static_cast<double>(whole);
    }
    else if (value.is_number())
    {
        number = value.get<double>(); // exact for every integer the ranges allow (at most 4e6)
    }
    else
    {
        return std::nullopt;
    }
    if (!std::isfinite(number) || std::floor(number) != number || number < range.min || number > range.max)
    {
        return std::nullopt;
    }
    return static_cast<long long>(number);
}

// One field of the object. Ranges of numbers are checked by Validate, in the same pass. Integers are checked
// here against their documented range (a value outside it may not fit the member), with the message Validate
// gives for them. A missing required field is reported as missing.
template <typename S> void ReadField(const ObjectReader& reader, const Field<S>& field, S& out)
{
    const std::string_view key = field.name;
    const Json* value = reader.Find(key);
    if (value == nullptr)
    {
        if (IsRequired(field))
        {
            reader.Diagnostics().Add(reader.FieldPath(key), "expected " +
                                                                std::string(ExpectedText(field.text)) +
                                                                ", but the required field is missing");
        }
        return;
    }
    std::visit(
        [&](auto member)
        {
            using M = decltype(member);
            if constexpr (std::is_same_v<M, float S::*>)
            {
                out.*member = reader.Float(key, out.*member);
            }
            else if constexpr (std::is_same_v<M, std::optional<float> S::*>)
            {
                out.*member = reader.OptionalFloat(key);
            }
            else if constexpr (std::is_same_v<M, bool S::*>)
            {
                out.*member = reader.Bool(key, out.*member);
            }
            else if constexpr (std::is_same_v<M, std::string S::*>)
            {
                out.*member = reader.String(key, out.*member);
            }
            else if constexpr (std::is_same_v<M, std::uint16_t S::*> || std::is_same_v<M, std::uint32_t S::*>)
            {
                if (const std::optional<long long> number = IntegerIn(*value, field.range))
                {
                    out.*member = static_cast<std::remove_reference_t<decltype(out.*member)>>(*number);
                }
                else
                {
                    reader.Diagnostics().Add(
                        reader.FieldPath(key),
                        "expected " + ExpectedInteger(field.range) + ", found " +
                            (value->is_number() ? value->dump() : scene_detail::Describe(*value)));
                }
            }
            else if constexpr (std::is_same_v<M, Color S::*>)
            {
                if (std::optional<Color> color =
                        ReadColor(*value, reader.FieldPath(key), field.range, reader.Diagnostics()))
                {
                    out.*member = *color;
                }
            }
            else if constexpr (std::is_same_v<M, ChoiceMember<S>>)
            {
                int index = member.get(out);
                ReadChoice(reader, key, field.choices, index);
                member.set(out, index);
            }
            // Nested objects are read by ReadObject, after the fields of their parent.
        },
        field.member);
}

// The top-level fields of an effects config.
constexpr std::string_view kTopKeys[] = {"name",   "materials",   "particleTypes", "rules",
                                         "budget", "assignments", "sound"};

// Where each field of an effects config belongs: a section ("rules[]", "" for the top level) and a name.
struct FieldPlace
{
    std::string_view section;
    std::string_view name;
};

template <typename S>
void AddPlaces(std::vector<FieldPlace>& places, std::string_view section, std::span<const Field<S>> fields)
{
    for (const Field<S>& field : fields)
    {
        places.push_back({section, field.name});
    }
}

const std::vector<FieldPlace>& FieldPlaces()
{
    static const std::vector<FieldPlace> places = []
    {
        std::vector<FieldPlace> all;
        for (std::string_view key : kTopKeys)
        {
            all.push_back({"", key});
        }
        AddPlaces(all, "particleTypes[]", ParticleTypeFields());
        AddPlaces(all, "rules[]", RuleFields());
        AddPlaces(all, "rules[].intensity", IntensityFields());
        AddPlaces(all, "assignments[]", AssignmentFields());
        AddPlaces(all, "budget", BudgetFields());
        AddPlaces(all, "sound", SoundFields());
        all.push_back({"sound", "rules"});
        AddPlaces(all, "sound.rules[]", SoundRuleFields());
        return all;
    }();
    return places;
}

// The section of an object's path: "rules[3].intensity" -> "rules[].intensity".
std::string SectionOf(std::string_view path)
{
    std::string section;
    bool inIndex = false;
    for (char c : path)
    {
        inIndex = c == '[' || (inIndex && c != ']');
        if (!inIndex || c == '[')
        {
            section += c;
        }
    }
    return section;
}

// " (a field of particleTypes[])" when `key` is no field of the section of `path` but is one elsewhere
// (a type's field written in its rule), naming every such section; empty otherwise.
std::string ElsewhereNote(std::string_view key, std::string_view path)
{
    const std::string own = SectionOf(path);
    std::string note;
    for (const FieldPlace& place : FieldPlaces())
    {
        if (place.name != key || place.section == own)
        {
            continue;
        }
        note += note.empty() ? " (a field of " : " and of ";
        note += place.section.empty() ? std::string_view("the top level") : place.section;
    }
    return note.empty() ? note : note + ")";
}

// Reports fields that no table knows, naming the nearest known one, else the sections where a field of
// that name belongs.
void CheckKnownKeys(const Json& object, const std::string& path, std::span<const std::string_view> names,
                    DiagnosticList& diagnostics)
{
    for (auto it = object.begin(); it != object.end(); ++it)
    {
        if (std::find(names.begin(), names.end(), it.key()) == names.end())
        {
            // A near key of this object first (`material` in a rule is a typo of `materialA` more likely than
            // an assignment's field written in a rule).
            const std::string elsewhere =
                scene_detail::NearestKey(it.key(), names) ? std::string() : ElsewhereNote(it.key(), path);
            diagnostics.Add(scene_detail::JoinPath(path, it.key()),
                            elsewhere.empty() ? scene_detail::UnknownKeyMessage(it.key(), names, "field", "")
                                              : "unknown field here" + elsewhere);
        }
    }
}

// The fields of one object of struct S: its unknown keys, then every field in table order, nested objects
// last (so problems are listed as the reader has always listed them).
// `lists` names the object's members that are lists read by the caller (the `rules` of `sound`).
template <typename S>
void ReadObject(const ObjectReader& reader, const Json& object, std::span<const Field<S>> fields, S& out,
                std::span<const std::string_view> lists = {})
{
    std::vector<std::string_view> known;
    for (const Field<S>& field : fields)
    {
        if (!IsNested(field))
        {
            known.push_back(field.name);
        }
    }
    for (const Field<S>& field : fields)
    {
        if (IsNested(field))
        {
            known.push_back(field.name);
        }
    }
    known.insert(known.end(), lists.begin(), lists.end());
    CheckKnownKeys(object, reader.Path(), known, reader.Diagnostics());
    for (const Field<S>& field : fields)
    {
        ReadField(reader, field, out);
    }
    for (const Field<S>& field : fields)
    {
        if (auto member = std::get_if<IntensityModel S::*>(&field.member))
        {
            if (const Json* nested = reader.Object(field.name))
            {
                ReadObject(ObjectReader(*nested, reader.FieldPath(field.name), reader.Diagnostics()), *nested,
                           IntensityFields(), out.**member);
            }
        }
    }
}

// Appends one S to `out` for every element of the array field `key`, read with `fields`.
template <typename S>
void ReadList(const ObjectReader& parent, const char* key, std::span<const Field<S>> fields,
              std::vector<S>& out)
{
    const Json* array = parent.Array(key);
    if (array == nullptr)
    {
        return;
    }
    for (std::size_t i = 0; i < array->size(); ++i)
    {
        const std::string path = scene_detail::IndexPath(parent.FieldPath(key), i);
        const Json& element = (*array)[i];
        S value;
        if (element.is_object())
        {
            ReadObject(ObjectReader(element, path, parent.Diagnostics()), element, fields, value);
        }
        else
        {
            // A bad element keeps its place as defaults so that the following elements keep their indices
            // for Validate's paths; what Validate says about it is covered by this error.
            parent.Diagnostics().Add(path, "expected an object, found " + scene_detail::Describe(element));
        }
        out.push_back(std::move(value));
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
    const std::string sceneKeys = scene_detail::RubeSceneKeys(root);
    if (!sceneKeys.empty() && scene_detail::EffectsConfigKeys(root).empty())
    {
        diagnostics.Add("", "expected an effects config, found a RUBE scene (top-level " + sceneKeys +
                                "; an effects config has \"materials\", \"particleTypes\", \"rules\"): load "
                                "it as a scene (contactfx: run SCENE.json)");
        return config;
    }
    ObjectReader top(root, "", diagnostics);
    CheckKnownKeys(root, "", kTopKeys, diagnostics);
    config.name = top.String("name");

    if (const Json* materials = top.Array("materials"))
    {
        for (std::size_t i = 0; i < materials->size(); ++i)
        {
            // A bad name keeps its place (as "") so that the indices of the following names stay right.
            config.materials.push_back(scene_detail::ReadString((*materials)[i],
                                                                scene_detail::IndexPath("materials", i),
                                                                diagnostics)
                                           .value_or(std::string()));
        }
    }

    ReadList(top, "particleTypes", ParticleTypeFields(), config.particleTypes);
    ReadList(top, "rules", RuleFields(), config.rules);
    ReadList(top, "assignments", AssignmentFields(), config.assignments);
    if (const Json* budget = top.Object("budget"))
    {
        ReadObject(ObjectReader(*budget, "budget", diagnostics), *budget, BudgetFields(), config.budget);
    }
    if (const Json* sound = top.Object("sound"))
    {
        static constexpr std::string_view kSoundLists[] = {"rules"};
        const ObjectReader reader(*sound, "sound", diagnostics);
        ReadObject(reader, *sound, SoundFields(), config.sound, kSoundLists);
        ReadList(reader, "rules", SoundRuleFields(), config.sound.rules);
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
        // Ranges and cross-references in the same pass, except where reading already failed: a field that
        // did not read keeps its (valid) default, and what Validate would add about a bad element or name
        // is that same problem again.
        const std::vector<Diagnostic> readProblems = diagnostics.Items();
        auto covered = [&](const std::string& path)
        {
            for (const Diagnostic& problem : readProblems)
            {
                const std::string& at = problem.path;
                if (at.empty() ||
                    (path.compare(0, at.size(), at) == 0 &&
                     (path.size() == at.size() || path[at.size()] == '.' || path[at.size()] == '[')))
                {
                    return true;
                }
            }
            return false;
        };
        for (Diagnostic& problem : Validate(config, fileName))
        {
            if (!covered(problem.path))
            {
                diagnostics.Add(std::move(problem.path), std::move(problem.message));
            }
        }
    }
    return diagnostics.Take();
}

template <typename S> Json WriteObject(std::span<const Field<S>> fields, const S& in)
{
    Json out = Json::object();
    for (const Field<S>& field : fields)
    {
        const std::string key(field.name);
        std::visit(
            [&](auto member)
            {
                using M = decltype(member);
                if constexpr (std::is_same_v<M, float S::*>)
                {
                    out[key] = scene_detail::ExactFloat(in.*member);
                }
                else if constexpr (std::is_same_v<M, std::optional<float> S::*>)
                {
                    if (in.*member) // written only when set
                    {
                        out[key] = scene_detail::ExactFloat(*(in.*member));
                    }
                }
                else if constexpr (std::is_same_v<M, Color S::*>)
                {
                    const Color& c = in.*member;
                    out[key] = Json::array({scene_detail::ExactFloat(c.r), scene_detail::ExactFloat(c.g),
                                            scene_detail::ExactFloat(c.b), scene_detail::ExactFloat(c.a)});
                }
                else if constexpr (std::is_same_v<M, ChoiceMember<S>>)
                {
                    const int index = member.get(in);
                    out[key] = index >= 0 && static_cast<std::size_t>(index) < field.choices.size()
                                   ? std::string(field.choices[static_cast<std::size_t>(index)])
                                   : std::string("?");
                }
                else if constexpr (std::is_same_v<M, IntensityModel S::*>)
                {
                    out[key] = WriteObject(IntensityFields(), in.*member);
                }
                else if constexpr (std::is_same_v<M, std::string S::*>)
                {
                    if (!(in.*member).empty() || field.text != TextRule::optionalParticleType)
                    {
                        out[key] = in.*member; // an optional name is written only when set
                    }
                }
                else
                {
                    out[key] = in.*member;
                }
            },
            field.member);
    }
    return out;
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
    // Only what LoadEffectsString reads back: JSON has no NaN or infinity, and a range error would be
    // found by the next load instead of by the code that made it.
    if (std::vector<Diagnostic> problems = Validate(config); !problems.empty())
    {
        throw InputError(std::move(problems));
    }
    Json root = Json::object();
    root["name"] = config.name;
    root["materials"] = config.materials;
    root["particleTypes"] = Json::array();
    for (const ParticleTypeDef& type : config.particleTypes)
    {
        root["particleTypes"].push_back(WriteObject(ParticleTypeFields(), type));
    }
    root["rules"] = Json::array();
    for (const RuleDef& rule : config.rules)
    {
        root["rules"].push_back(WriteObject(RuleFields(), rule));
    }
    root["assignments"] = Json::array();
    for (const MaterialAssignment& assignment : config.assignments)
    {
        root["assignments"].push_back(WriteObject(AssignmentFields(), assignment));
    }
    root["budget"] = WriteObject(BudgetFields(), config.budget);
    Json sound = WriteObject(SoundFields(), config.sound);
    sound["rules"] = Json::array();
    for (const SoundRuleDef& rule : config.sound.rules)
    {
        sound["rules"].push_back(WriteObject(SoundRuleFields(), rule));
    }
    root["sound"] = std::move(sound);
    return root.dump(2) + "\n";
}

void SaveEffectsFile(const EffectsConfig& config, const std::filesystem::path& path)
{
    WriteTextFileAtomically(path, SaveEffectsString(config));
}

} // namespace cfx
