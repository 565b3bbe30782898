// The field tables (contactfx/config_fields.h) against everything they drive: the JSON reader and writer,
// Validate and docs/effects-config.md. Each test walks every row, so a field added to a struct and its
// table is covered without touching this file, and a reader, validator or doc that leaves it out fails.
//
// CONTACTFX_UPDATE_DOCS=1 makes DocsShowEveryFieldWithItsRangeAndDefault rewrite the generated tables of
// docs/effects-config.md instead of failing.
#include "contactfx/config_fields.h"
#include "contactfx/files/text_file.h"
#include "contactfx/scene/effects_json.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <set>

namespace cfx
{

namespace
{

// A valid config with one of everything, named so that every name field has another valid value.
EffectsConfig BaseConfig()
{
    EffectsConfig config;
    config.name = "fields";
    config.materials = {"m1", "m2"};
    config.particleTypes.resize(2);
    config.particleTypes[0].name = "p1";
    config.particleTypes[1].name = "p2";
    RuleDef rule;
    rule.materialA = "m1";
    rule.materialB = "m2";
    rule.particleType = "p1";
    config.rules = {rule};
    MaterialAssignment assignment;
    assignment.material = "m1";
    config.assignments = {assignment};
    config.sound.rules = {SoundRuleDef{.materialA = "m1", .materialB = "m2"}};
    return config;
}

// Where each table's struct lives in BaseConfig, and its path.
template <typename S> struct Slot;
template <> struct Slot<ParticleTypeDef>
{
    static ParticleTypeDef& In(EffectsConfig& config) { return config.particleTypes[1]; }
    static std::string Path() { return "particleTypes[1]"; }
};
template <> struct Slot<RuleDef>
{
    static RuleDef& In(EffectsConfig& config) { return config.rules[0]; }
    static std::string Path() { return "rules[0]"; }
};
template <> struct Slot<IntensityModel>
{
    static IntensityModel& In(EffectsConfig& config) { return config.rules[0].intensity; }
    static std::string Path() { return "rules[0].intensity"; }
};
template <> struct Slot<MaterialAssignment>
{
    static MaterialAssignment& In(EffectsConfig& config) { return config.assignments[0]; }
    static std::string Path() { return "assignments[0]"; }
};
template <> struct Slot<ParticleBudget>
{
    static ParticleBudget& In(EffectsConfig& config) { return config.budget; }
    static std::string Path() { return "budget"; }
};
template <> struct Slot<SoundConfig>
{
    static SoundConfig& In(EffectsConfig& config) { return config.sound; }
    static std::string Path() { return "sound"; }
};
template <> struct Slot<SoundRuleDef>
{
    static SoundRuleDef& In(EffectsConfig& config) { return config.sound.rules[0]; }
    static std::string Path() { return "sound.rules[0]"; }
};

// The struct a table describes.
template <typename T> struct StructOfTable;
template <typename S> struct StructOfTable<std::span<const Field<S>>>
{
    using Type = S;
};
template <typename T> using StructOf = typename StructOfTable<T>::Type;

// Calls `each(table)` for every table of every table, with the struct type as S.
template <typename F> void ForEachTable(F&& each)
{
    each(ParticleTypeFields());
    each(RuleFields());
    each(IntensityFields());
    each(AssignmentFields());
    each(BudgetFields());
    each(SoundFields());
    each(SoundRuleFields());
}

// A valid value of the field other than the one `value` has.
float OtherNumber(float current, const FieldRange& range)
{
    for (float candidate : {0.375f, 1.5f, range.max * 0.75f, range.min + (range.max - range.min) * 0.25f})
    {
        if (candidate != current && range.Contains(candidate))
        {
            return candidate;
        }
    }
    ADD_FAILURE() << "no other valid number in the range";
    return current;
}

template <typename S> void SetOtherValue(S& value, const Field<S>& field)
{
    std::visit(
        [&](auto member)
        {
            using M = decltype(member);
            if constexpr (std::is_same_v<M, float S::*>)
            {
                value.*member = OtherNumber(value.*member, field.range);
            }
            else if constexpr (std::is_same_v<M, std::optional<float> S::*>)
            {
                value.*member = OtherNumber(value.*member ? *(value.*member) : 0.0f, field.range);
            }
            else if constexpr (std::is_same_v<M, bool S::*>)
            {
                value.*member = !(value.*member);
            }
            else if constexpr (std::is_same_v<M, std::string S::*>)
            {
                switch (field.text)
                {
                case TextRule::material:
                    value.*member = value.*member == "m2" ? "m1" : "m2";
                    break;
                case TextRule::particleType:
                case TextRule::optionalParticleType:
                    value.*member = value.*member == "p2" ? "p1" : "p2";
                    break;
                case TextRule::pattern:
                    value.*member = "wheel_?*";
                    break;
                default:
                    value.*member += "x";
                    break;
                }
            }
            else if constexpr (std::is_same_v<M, std::uint16_t S::*>)
            {
                value.*member = static_cast<std::uint16_t>(value.*member ^ 0x1234u);
            }
            else if constexpr (std::is_same_v<M, std::uint32_t S::*>)
            {
                value.*member =
                    static_cast<std::uint32_t>(OtherNumber(static_cast<float>(value.*member), field.range));
            }
            else if constexpr (std::is_same_v<M, Color S::*>)
            {
                value.*member = Color{0.25f, 0.5f, 0.75f, 0.125f};
            }
            else if constexpr (std::is_same_v<M, ChoiceMember<S>>)
            {
                member.set(value, (member.get(value) + 1) % static_cast<int>(field.choices.size()));
            }
            else
            {
                ADD_FAILURE() << field.name << ": a nested struct has a table of its own";
            }
        },
        field.member);
}

template <typename S> bool IsNested(const Field<S>& field)
{
    return std::holds_alternative<IntensityModel S::*>(field.member);
}

std::vector<std::string> Paths(const std::vector<Diagnostic>& problems)
{
    std::vector<std::string> paths;
    for (const Diagnostic& problem : problems)
    {
        paths.push_back(problem.path);
    }
    return paths;
}

bool Has(const std::vector<std::string>& paths, const std::string& path)
{
    return std::find(paths.begin(), paths.end(), path) != paths.end();
}

} // namespace

TEST(ConfigFields, TablesNameEveryFieldOnceWithADocLine)
{
    ForEachTable(
        [](auto fields)
        {
            std::set<std::string_view> names;
            for (const auto& field : fields)
            {
                EXPECT_TRUE(names.insert(field.name).second) << field.name << " twice";
                EXPECT_FALSE(field.doc.empty()) << field.name;
                const bool number = field.member.index() <= 1; // float, optional float
                if (number)
                {
                    EXPECT_GT(field.step, 0.0f) << field.name << ": the editor needs a drag step";
                    EXPECT_LT(field.range.min, field.range.max) << field.name;
                }
            }
        });
}

TEST(ConfigFields, EveryFieldRoundTripsThroughJson)
{
    const EffectsConfig base = BaseConfig();
    ASSERT_TRUE(Validate(base).empty());
    ForEachTable(
        [&](auto fields)
        {
            using S = StructOf<decltype(fields)>;
            for (const Field<S>& field : fields)
            {
                if (IsNested(field))
                {
                    continue; // its own table
                }
                EffectsConfig config = base;
                SetOtherValue(Slot<S>::In(config), field);
                // A sound rule must name the materials of a pair rule (Validate): the two change together.
                if constexpr (std::is_same_v<S, RuleDef>)
                {
                    config.sound.rules[0].materialA = config.rules[0].materialA;
                    config.sound.rules[0].materialB = config.rules[0].materialB;
                }
                else if constexpr (std::is_same_v<S, SoundRuleDef>)
                {
                    config.rules[0].materialA = config.sound.rules[0].materialA;
                    config.rules[0].materialB = config.sound.rules[0].materialB;
                }
                ASSERT_NE(config, base) << field.name;
                ASSERT_TRUE(Validate(config).empty()) << field.name << ": " << Validate(config)[0].message;
                const std::string json = SaveEffectsString(config);
                EXPECT_EQ(LoadEffectsString(json, "fields.json"), config)
                    << Slot<S>::Path() << "." << field.name;
            }
        });
}

TEST(ConfigFields, TheWriterWritesExactlyTheTablesFields)
{
    EffectsConfig config = BaseConfig();
    config.assignments[0].frictionAbove = 0.1f; // optional numbers are written when set
    config.assignments[0].frictionBelow = 0.2f;
    config.assignments[0].massAbove = 1.0f;
    config.assignments[0].massBelow = 2.0f;
    config.rules[0].burstParticleType = config.rules[0].particleType; // an optional name, when set
    const nlohmann::json root = nlohmann::json::parse(SaveEffectsString(config));
    auto keysOf = [](const nlohmann::json& object)
    {
        std::set<std::string> keys;
        for (auto it = object.begin(); it != object.end(); ++it)
        {
            keys.insert(it.key());
        }
        return keys;
    };
    auto namesOf = [](auto fields)
    {
        std::set<std::string> names;
        for (const auto& field : fields)
        {
            names.insert(std::string(field.name));
        }
        return names;
    };
    EXPECT_EQ(keysOf(root["particleTypes"][0]), namesOf(ParticleTypeFields()));
    EXPECT_EQ(keysOf(root["rules"][0]), namesOf(RuleFields()));
    EXPECT_EQ(keysOf(root["rules"][0]["intensity"]), namesOf(IntensityFields()));
    EXPECT_EQ(keysOf(root["assignments"][0]), namesOf(AssignmentFields()));
    EXPECT_EQ(keysOf(root["budget"]), namesOf(BudgetFields()));
    config.rules[0].burstParticleType.clear(); // and not when empty
    std::set<std::string> ruleKeys = namesOf(RuleFields());
    ruleKeys.erase("burstParticleType");
    EXPECT_EQ(keysOf(nlohmann::json::parse(SaveEffectsString(config))["rules"][0]), ruleKeys);
    std::set<std::string> soundKeys = namesOf(SoundFields());
    soundKeys.insert("rules");
    EXPECT_EQ(keysOf(root["sound"]), soundKeys);
    EXPECT_EQ(keysOf(root["sound"]["rules"][0]), namesOf(SoundRuleFields()));
}

TEST(ConfigFields, EveryKeyIsKnownAndAMisspeltOneIsNamed)
{
    ForEachTable(
        [&](auto fields)
        {
            using S = StructOf<decltype(fields)>;
            for (const Field<S>& field : fields)
            {
                nlohmann::json root = nlohmann::json::parse(SaveEffectsString(BaseConfig()));
                nlohmann::json* object = &root;
                const std::string path = Slot<S>::Path();
                if (path == "budget" || path == "sound")
                {
                    object = &root[path];
                }
                else if (path == "sound.rules[0]")
                {
                    object = &root["sound"]["rules"][0];
                }
                else
                {
                    const std::string list = path.substr(0, path.find('['));
                    object = &root[list][static_cast<std::size_t>(path[list.size() + 1] - '0')];
                    if (path.ends_with(".intensity"))
                    {
                        object = &(*object)["intensity"];
                    }
                }
                const nlohmann::json value = (*object)[std::string(field.name)];
                object->erase(std::string(field.name));
                (*object)[std::string(field.name) + "Q"] = value;
                try
                {
                    LoadEffectsString(root.dump(), "fields.json");
                    ADD_FAILURE() << field.name << "Q was accepted";
                }
                catch (const InputError& error)
                {
                    ASSERT_FALSE(error.Diagnostics().empty());
                    const Diagnostic& problem = error.Diagnostics()[0];
                    EXPECT_EQ(problem.path, path + "." + std::string(field.name) + "Q");
                    EXPECT_EQ(problem.message,
                              "unknown field, did you mean `" + std::string(field.name) + "`?");
                }
            }
        });
}

TEST(ConfigFields, EveryNumberIsValidatedAgainstItsRange)
{
    ForEachTable(
        [&](auto fields)
        {
            using S = StructOf<decltype(fields)>;
            for (const Field<S>& field : fields)
            {
                const std::string path = Slot<S>::Path() + "." + std::string(field.name);
                const FieldRange& range = field.range;
                // Values just outside and at the ends of the range, and whether each is valid.
                std::vector<std::pair<float, bool>> cases;
                std::visit(
                    [&](auto member)
                    {
                        using M = decltype(member);
                        if constexpr (std::is_same_v<M, float S::*> ||
                                      std::is_same_v<M, std::optional<float> S::*> ||
                                      std::is_same_v<M, Color S::*>)
                        {
                            cases = {{std::nextafter(range.min, -INFINITY), false},
                                     {range.min, !range.minExclusive},
                                     {std::nextafter(range.min, INFINITY), true},
                                     {range.max, true},
                                     {std::nextafter(range.max, INFINITY), false},
                                     {NAN, false}};
                        }
                        else if constexpr (std::is_same_v<M, std::uint32_t S::*>)
                        {
                            cases = {{range.min, true}, {range.max, true}, {range.max + 1.0f, false}};
                            if (range.min > 0.0f)
                            {
                                cases.push_back({range.min - 1.0f, false});
                            }
                        }
                    },
                    field.member);
                for (const auto& [givenNumber, givenValid] : cases)
                {
                    // Copies: a lambda may not capture a structured binding before C++20 as clang 14 reads
                    // it.
                    const float number = givenNumber;
                    const bool valid = givenValid;
                    EffectsConfig config = BaseConfig();
                    S& value = Slot<S>::In(config);
                    std::string at = path;
                    std::visit(
                        [&](auto member)
                        {
                            using M = decltype(member);
                            if constexpr (std::is_same_v<M, float S::*> ||
                                          std::is_same_v<M, std::optional<float> S::*>)
                            {
                                value.*member = number;
                            }
                            else if constexpr (std::is_same_v<M, std::uint32_t S::*>)
                            {
                                value.*member = static_cast<std::uint32_t>(number);
                            }
                            else if constexpr (std::is_same_v<M, Color S::*>)
                            {
                                (value.*member).g = number;
                                at += "[1]";
                            }
                        },
                        field.member);
                    EXPECT_EQ(Has(Paths(Validate(config)), at), !valid) << at << " = " << number;
                }
            }
        });
}

TEST(ConfigFields, EveryEnumIsValidatedAgainstItsNames)
{
    ForEachTable(
        [&](auto fields)
        {
            using S = StructOf<decltype(fields)>;
            for (const Field<S>& field : fields)
            {
                if (auto member = std::get_if<ChoiceMember<S>>(&field.member))
                {
                    const int count = static_cast<int>(field.choices.size());
                    for (int index : {0, count - 1, count, 200})
                    {
                        EffectsConfig config = BaseConfig();
                        member->set(Slot<S>::In(config), index);
                        const std::string path = Slot<S>::Path() + "." + std::string(field.name);
                        EXPECT_EQ(Has(Paths(Validate(config)), path), index >= count)
                            << path << " = " << index;
                    }
                }
            }
        });
}

namespace
{

// docs/effects-config.md: the generated tables.

std::string DocNumber(float value)
{
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    std::string text(buffer, result.ptr);
    for (const char* exponent : {"e+0", "e+"})
    {
        if (const std::size_t at = text.find(exponent); at != std::string::npos)
        {
            text.replace(at, std::string_view(exponent).size(), "e");
        }
    }
    return text;
}

std::string DocRange(const FieldRange& range)
{
    return (range.minExclusive ? "(" : "[") + DocNumber(range.min) + ", " + DocNumber(range.max) + "]";
}

std::string Quoted(std::string_view text)
{
    return "`\"" + std::string(text) + "\"`";
}

template <typename S>
void DocRows(std::span<const Field<S>> fields, const S& defaults, const std::string& prefix, std::string& out)
{
    for (const Field<S>& field : fields)
    {
        std::string values;
        std::string byDefault;
        std::visit(
            [&](auto member)
            {
                using M = decltype(member);
                if constexpr (std::is_same_v<M, float S::*>)
                {
                    values = DocRange(field.range);
                    byDefault = "`" + DocNumber(defaults.*member) + "`";
                }
                else if constexpr (std::is_same_v<M, std::optional<float> S::*>)
                {
                    values = DocRange(field.range) + " or absent";
                    byDefault = defaults.*member ? "`" + DocNumber(*(defaults.*member)) + "`" : "absent";
                }
                else if constexpr (std::is_same_v<M, bool S::*>)
                {
                    values = "`true`, `false`";
                    byDefault = defaults.*member ? "`true`" : "`false`";
                }
                else if constexpr (std::is_same_v<M, std::string S::*>)
                {
                    static constexpr const char* kRules[] = {"text",
                                                             "unique, non-empty, no control characters",
                                                             "non-empty glob",
                                                             "a material name",
                                                             "a particle type name",
                                                             "a particle type name or `\"\"`"};
                    values = kRules[static_cast<int>(field.text)];
                    // What the reader requires (IsRequired) has no default to show.
                    EXPECT_EQ(IsRequired(field), (defaults.*member).empty() && field.text != TextRule::any &&
                                                     field.text != TextRule::optionalParticleType)
                        << field.name;
                    byDefault = IsRequired(field) ? "(required)" : Quoted(defaults.*member);
                }
                else if constexpr (std::is_same_v<M, std::uint16_t S::*> ||
                                   std::is_same_v<M, std::uint32_t S::*>)
                {
                    values = "integer " + DocRange(field.range);
                    byDefault = "`" + std::to_string(defaults.*member) + "`";
                }
                else if constexpr (std::is_same_v<M, Color S::*>)
                {
                    values = "[r, g, b] or [r, g, b, a], each in " + DocRange(field.range);
                    const Color& c = defaults.*member;
                    byDefault = "`[" + DocNumber(c.r) + ", " + DocNumber(c.g) + ", " + DocNumber(c.b) + ", " +
                                DocNumber(c.a) + "]`";
                }
                else if constexpr (std::is_same_v<M, ChoiceMember<S>>)
                {
                    for (std::string_view name : field.choices)
                    {
                        values += (values.empty() ? "" : ", ") + Quoted(name);
                    }
                    byDefault = Quoted(field.choices[static_cast<std::size_t>(member.get(defaults))]);
                }
                else if constexpr (std::is_same_v<M, IntensityModel S::*>)
                {
                    DocRows(IntensityFields(), defaults.*member, prefix + std::string(field.name) + ".", out);
                }
            },
            field.member);
        if (!IsNested(field))
        {
            out += "| `" + prefix + std::string(field.name) + "` | " + std::string(field.unit) + " | " +
                   values + " | " + byDefault + " | " + std::string(field.doc) + " |\n";
        }
    }
}

template <typename S> std::string DocTable(std::span<const Field<S>> fields)
{
    std::string out = "| field | unit | values | default | meaning |\n|---|---|---|---|---|\n";
    DocRows(fields, S{}, "", out);
    return out;
}

// The generated block `name` of the docs: between its two marker lines.
struct DocBlock
{
    std::string name;
    std::string table;
};

std::string BeginMarker(const std::string& name)
{
    return "<!-- fields " + name +
           ": generated from include/contactfx/config_fields.h, checked by "
           "tests/scene/config_fields_test.cpp -->\n";
}
const std::string kEndMarker = "<!-- end of fields -->\n";

} // namespace

TEST(ConfigFields, DocsShowEveryFieldWithItsRangeAndDefault)
{
    const std::filesystem::path file =
        std::filesystem::path(CONTACTFX_SOURCE_DIR) / "docs" / "effects-config.md";
    std::string docs = ReadTextFile(file);
    const std::vector<DocBlock> blocks = {
        {"particleTypes", DocTable(ParticleTypeFields())},
        {"rules", DocTable(RuleFields())},
        {"assignments", DocTable(AssignmentFields())},
        {"budget", DocTable(BudgetFields())},
        {"sound", DocTable(SoundFields())},
        {"soundRules", DocTable(SoundRuleFields())},
    };
    const bool update = std::getenv("CONTACTFX_UPDATE_DOCS") != nullptr;
    for (const DocBlock& block : blocks)
    {
        const std::string begin = BeginMarker(block.name);
        const std::size_t start = docs.find(begin);
        ASSERT_NE(start, std::string::npos) << "docs/effects-config.md has no line " << begin;
        const std::size_t end = docs.find(kEndMarker, start);
        ASSERT_NE(end, std::string::npos) << "no end marker after " << begin;
        const std::size_t from = start + begin.size();
        if (update)
        {
            docs.replace(from, end - from, block.table);
            continue;
        }
        EXPECT_EQ(docs.substr(from, end - from), block.table)
            << "docs/effects-config.md differs from the field table " << block.name
            << " (CONTACTFX_UPDATE_DOCS=1 rewrites it)";
    }
    if (update)
    {
        WriteTextFileAtomically(file, docs);
    }
}

} // namespace cfx
