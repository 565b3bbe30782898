#include "contactfx/config.h"

#include "contactfx/config_fields.h"
#include "float_text.h"
#include "nearest_name.h"
#include "quoted_text.h"

#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <utility>

namespace cfx
{

MaterialId EffectsConfig::FindMaterial(std::string_view wanted) const
{
    for (std::size_t i = 0; i < materials.size(); ++i)
    {
        if (materials[i] == wanted)
        {
            return MaterialId{static_cast<std::uint16_t>(i)};
        }
    }
    return MaterialId{};
}

ParticleTypeId EffectsConfig::FindParticleType(std::string_view wanted) const
{
    for (std::size_t i = 0; i < particleTypes.size(); ++i)
    {
        if (particleTypes[i].name == wanted)
        {
            return ParticleTypeId{static_cast<std::uint16_t>(i)};
        }
    }
    return ParticleTypeId{};
}

namespace
{

// Every field is checked against its row of the field tables (contactfx/config_fields.h): numbers against
// their ranges, enums against their names, names against the config. docs/effects-config.md shows the same
// rows, and a test keeps the two in step.

// Collects diagnostics with paths built from a prefix.
class Checker
{
public:
    Checker(std::string_view file, std::vector<Diagnostic>& out) : m_file(file), m_out(out) {}

    detail::SuggestionBudget suggestions; // for every "did you mean" of the file

    void Fail(const std::string& path, const std::string& message)
    {
        m_out.push_back(Diagnostic{std::string(m_file), path, message});
    }

    // A finite number within `range`.
    void Number(const std::string& path, float value, const FieldRange& range)
    {
        if (range.Contains(value))
        {
            return;
        }
        Fail(path, "expected " + ExpectedNumber(range) + ", found " + detail::FloatText(value));
    }
    // An integer within `range` (whose bounds are whole numbers).
    void Integer(const std::string& path, std::uint32_t value, const FieldRange& range)
    {
        if (value < static_cast<long long>(range.min) || value > static_cast<long long>(range.max))
        {
            Fail(path, "expected " + ExpectedInteger(range) + ", found " + std::to_string(value));
        }
    }
    void Enum(const std::string& path, int value, int count)
    {
        if (value < 0 || value >= count)
        {
            Fail(path, "expected one of the " + std::to_string(count) + " named values, found " +
                           std::to_string(value));
        }
    }
    // Named by index, as the element of the file's [r, g, b, a] array (and as its type errors are).
    void Colour(const std::string& path, const Color& color, const FieldRange& range)
    {
        Number(path + "[0]", color.r, range);
        Number(path + "[1]", color.g, range);
        Number(path + "[2]", color.b, range);
        Number(path + "[3]", color.a, range);
    }

private:
    std::string_view m_file;
    std::vector<Diagnostic>& m_out;
};

// Names show in line-based output (validate, the run summary): a control character in one (a line break,
// a NUL, U+0085 NEXT LINE) would forge or cut a line (detail::HasControlCharacter).
const std::string kNoControlCharacters = "expected a name without control characters, found ";

void CheckText(Checker& check, const std::string& path, const std::string& text, TextRule rule,
               const EffectsConfig& config)
{
    switch (rule)
    {
    case TextRule::any:
    case TextRule::name: // unique within its list: checked with the list
        break;
    case TextRule::pattern:
        if (text.empty())
        {
            check.Fail(path, "expected a non-empty pattern (\"*\" matches any name)");
        }
        break;
    case TextRule::optionalParticleType:
        if (!text.empty())
        {
            CheckText(check, path, text, TextRule::particleType, config);
        }
        break;
    case TextRule::material:
    case TextRule::particleType:
        if (text.empty()) // not set: never a match, even for a nameless entry (itself an error)
        {
            check.Fail(path, "expected " + std::string(ExpectedText(rule)) + ", found \"\"");
        }
        else if (rule == TextRule::material && !config.FindMaterial(text).IsValid())
        {
            check.Fail(path, "unknown material " + detail::QuotedText(text) +
                                 detail::DidYouMean(text, config.materials, check.suggestions) +
                                 " (materials: " + detail::NameList(config.materials, "none") + ")");
        }
        else if (rule == TextRule::particleType && !config.FindParticleType(text).IsValid())
        {
            std::vector<std::string> types;
            for (const ParticleTypeDef& type : config.particleTypes)
            {
                types.push_back(type.name);
            }
            check.Fail(path, "unknown particle type " + detail::QuotedText(text) +
                                 detail::DidYouMean(text, types, check.suggestions) +
                                 " (particle types: " + detail::NameList(types, "none") + ")");
        }
        break;
    }
}

// The value of the optional number `name` of `value`, or nothing.
template <typename S>
std::optional<float> OptionalNamed(const S& value, std::span<const Field<S>> fields, std::string_view name)
{
    for (const Field<S>& field : fields)
    {
        if (field.name == name)
        {
            if (auto member = std::get_if<std::optional<float> S::*>(&field.member))
            {
                return value.**member;
            }
        }
    }
    return std::nullopt;
}

template <typename S>
void CheckFields(Checker& check, const std::string& at, const S& value, std::span<const Field<S>> fields,
                 const EffectsConfig& config)
{
    for (const Field<S>& field : fields)
    {
        const std::string path = at + "." + std::string(field.name);
        std::visit(
            [&](auto member)
            {
                using M = decltype(member);
                if constexpr (std::is_same_v<M, float S::*>)
                {
                    check.Number(path, value.*member, field.range);
                }
                else if constexpr (std::is_same_v<M, std::optional<float> S::*>)
                {
                    const std::optional<float>& number = value.*member;
                    if (number)
                    {
                        check.Number(path, *number, field.range);
                    }
                    // Both bounds set: a non-empty open interval.
                    const std::optional<float> lower = field.greaterThan.empty()
                                                           ? std::nullopt
                                                           : OptionalNamed(value, fields, field.greaterThan);
                    if (number && lower && std::isfinite(*lower) && std::isfinite(*number) &&
                        !(*number > *lower))
                    {
                        check.Fail(path, "expected a number > " + std::string(field.greaterThan) + " (" +
                                             detail::FloatText(*lower) + "), found " +
                                             detail::FloatText(*number) + " (no value would match)");
                    }
                }
                else if constexpr (std::is_same_v<M, std::string S::*>)
                {
                    CheckText(check, path, value.*member, field.text, config);
                }
                else if constexpr (std::is_same_v<M, std::uint32_t S::*> ||
                                   std::is_same_v<M, std::uint16_t S::*>)
                {
                    check.Integer(path, value.*member, field.range);
                }
                else if constexpr (std::is_same_v<M, Color S::*>)
                {
                    check.Colour(path, value.*member, field.range);
                }
                else if constexpr (std::is_same_v<M, ChoiceMember<S>>)
                {
                    check.Enum(path, member.get(value), static_cast<int>(field.choices.size()));
                }
                else if constexpr (std::is_same_v<M, IntensityModel S::*>)
                {
                    CheckFields(check, path, value.*member, IntensityFields(), config);
                }
                // bool: any value is valid
            },
            field.member);
    }
}

// Unordered material pairs seen so far in a list (rules, sound rules), each with the index of its first
// entry.
using MaterialPairs = std::map<std::pair<std::string_view, std::string_view>, std::size_t>;

// The unordered pair {a, b} as the key of MaterialPairs.
std::pair<std::string_view, std::string_view> Unordered(std::string_view a, std::string_view b)
{
    return b < a ? std::pair(b, a) : std::pair(a, b);
}

// "A+B" (sorted).
std::string PairName(std::string_view a, std::string_view b)
{
    const auto [first, second] = Unordered(a, b);
    return detail::EscapedText(first) + "+" + detail::EscapedText(second); // one line whatever the names
}

// Notes entry `index` of `list` (its path, "rules") for the unordered pair {a, b}; when an earlier entry
// has that pair, fails at entry `index` naming the pair and that entry, and returns true.
bool NoteRepeatedPair(Checker& check, MaterialPairs& seen, std::string_view list, std::size_t index,
                      std::string_view a, std::string_view b, std::string_view what)
{
    const auto [first, inserted] = seen.emplace(Unordered(a, b), index);
    if (!inserted)
    {
        const std::string path = std::string(list) + "[";
        check.Fail(path + std::to_string(index) + "]", "a second " + std::string(what) + " for the pair " +
                                                           PairName(a, b) + " (the first is " + path +
                                                           std::to_string(first->second) + "])");
    }
    return !inserted;
}

// Materials, particle types and rules are each counted by a 16-bit id whose all-ones value means none.
void CheckCount(Checker& check, std::string_view path, std::string_view what, std::size_t count)
{
    constexpr std::size_t kMaxCount = 0xFFFE; // MaterialId, ParticleTypeId and RuleId's kNone less one
    static_assert(MaterialId::kNone == kMaxCount + 1 && ParticleTypeId::kNone == kMaxCount + 1 &&
                  RuleId::kNone == kMaxCount + 1);
    if (count > kMaxCount)
    {
        check.Fail(std::string(path), "expected at most " + std::to_string(kMaxCount) + " " +
                                          std::string(what) + ", found " + std::to_string(count));
    }
}

// A material's or particle type's name at `at`: not empty, no control characters, not one seen before.
void CheckName(Checker& check, const std::string& at, std::string_view kind, const std::string& name,
               std::set<std::string_view>& seen)
{
    if (name.empty())
    {
        check.Fail(at, "expected a non-empty name");
    }
    else if (detail::HasControlCharacter(name))
    {
        check.Fail(at, kNoControlCharacters + detail::QuotedText(name));
    }
    else if (!seen.insert(name).second)
    {
        check.Fail(at, "duplicate " + std::string(kind) + " " + detail::QuotedText(name));
    }
}

} // namespace

std::vector<Diagnostic> Validate(const EffectsConfig& config, std::string_view file)
{
    std::vector<Diagnostic> out;
    Checker check(file, out);

    if (detail::HasControlCharacter(config.name))
    {
        check.Fail("name", kNoControlCharacters + detail::QuotedText(config.name));
    }
    CheckCount(check, "materials", "materials", config.materials.size());
    std::set<std::string_view> seen;
    for (std::size_t i = 0; i < config.materials.size(); ++i)
    {
        CheckName(check, "materials[" + std::to_string(i) + "]", "material", config.materials[i], seen);
    }

    CheckCount(check, "particleTypes", "particle types", config.particleTypes.size());
    seen.clear();
    for (std::size_t i = 0; i < config.particleTypes.size(); ++i)
    {
        const std::string at = "particleTypes[" + std::to_string(i) + "]";
        const ParticleTypeDef& type = config.particleTypes[i];
        CheckName(check, at + ".name", "particle type", type.name, seen);
        CheckFields(check, at, type, ParticleTypeFields(), config);
    }

    CheckCount(check, "rules", "rules", config.rules.size());
    MaterialPairs pairs;
    std::map<std::string, std::size_t> pairNames;
    for (std::size_t i = 0; i < config.rules.size(); ++i)
    {
        const std::string at = "rules[" + std::to_string(i) + "]";
        const RuleDef& rule = config.rules[i];
        CheckFields(check, at, rule, RuleFields(), config);
        if (!NoteRepeatedPair(check, pairs, "rules", i, rule.materialA, rule.materialB, "rule"))
        {
            // Files and events name a rule by its pair ("a+b"): "a+b" with "c" and "a" with "b+c" would both
            // be "a+b+c" (a trial's stats file lost one of them).
            const auto [named, inserted] = pairNames.emplace(PairName(rule.materialA, rule.materialB), i);
            if (!inserted)
            {
                check.Fail(at, "the pair name \"" + named->first + "\" is also rules[" +
                                   std::to_string(named->second) +
                                   "]'s, of other materials (a name with \"+\" in it): rename a material");
            }
        }
    }

    for (std::size_t i = 0; i < config.assignments.size(); ++i)
    {
        CheckFields(check, "assignments[" + std::to_string(i) + "]", config.assignments[i],
                    AssignmentFields(), config);
    }

    CheckFields(check, "budget", config.budget, BudgetFields(), config);
    // Each rule keeps its touching contacts in a list of its own, each with room for budget.contacts.
    const std::size_t contactRoom = config.ContactRoom();
    if (contactRoom > kMaxContactRoom)
    {
        check.Fail("budget.contacts",
                   "room for " + std::to_string(config.budget.contacts) +
                       " touching contacts for each of the " + std::to_string(config.rules.size()) +
                       " rules is " + std::to_string(contactRoom) +
                       " entries; rules times contacts may be at most " + std::to_string(kMaxContactRoom) +
                       " (about 3.4 GB): lower contacts");
    }

    CheckFields(check, "sound", config.sound, SoundFields(), config);
    MaterialPairs soundPairs;
    for (std::size_t i = 0; i < config.sound.rules.size(); ++i)
    {
        const std::string at = "sound.rules[" + std::to_string(i) + "]";
        const SoundRuleDef& rule = config.sound.rules[i];
        CheckFields(check, at, rule, SoundRuleFields(), config);
        const bool repeated = NoteRepeatedPair(check, soundPairs, "sound.rules", i, rule.materialA,
                                               rule.materialB, "sound rule");
        // Sound rules only tune the voices of a pair rule's events (docs/sound.md): without one, a typo in
        // a material name would silently do nothing. Unknown materials are reported above.
        if (!repeated && config.FindMaterial(rule.materialA).IsValid() &&
            config.FindMaterial(rule.materialB).IsValid() &&
            !pairs.contains(Unordered(rule.materialA, rule.materialB)))
        {
            check.Fail(at, "no rule for the pair " + PairName(rule.materialA, rule.materialB) +
                               " in \"rules\": this sound rule would never apply");
        }
    }
    return out;
}

std::vector<Diagnostic> ValidateParticles(std::span<const ParticleTypeDef> types,
                                          const ParticleBudget& budget, std::string_view file)
{
    std::vector<Diagnostic> out;
    Checker check(file, out);
    CheckCount(check, "particleTypes", "particle types", types.size());
    const EffectsConfig none; // particle types have no field naming a material or another type
    for (std::size_t i = 0; i < types.size(); ++i)
    {
        CheckFields(check, "particleTypes[" + std::to_string(i) + "]", types[i], ParticleTypeFields(), none);
    }
    CheckFields(check, "budget", budget, BudgetFields(), none);
    return out;
}

} // namespace cfx
