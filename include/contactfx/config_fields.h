// contactfx: every field of an effects configuration, declared once.
//
// The config structs (particle_types.h, rules.h, intensity.h, assignments.h, sound_config.h, config.h) stay
// plain structs that users fill in code. Beside them, one table per struct lists its fields: name (the
// member's name, which is also the JSON key and the last part of a diagnostic's path), a pointer to the
// member, unit, range, a one-line description and, for enums, the names of their values. Defaults are not
// repeated here: a field's default is its value in a default-constructed struct.
//
// The table is plain data in the spirit of Dear ImGui's style-variable table and Jolt's settings: no
// macros, no reflection library. What reads it:
//   - cfx::Validate (src/config.cpp): every number against its range, every enum against its names, every
//     name against the config, in table order;
//   - the effects config JSON reader and writer (contactfx_scene), and its unknown-field check;
//   - the testbed's effects editor: one widget per field, bounded by the range;
//   - docs/effects-config.md: its field tables are rendered from these tables, and a test fails when the
//     file and the tables differ (tests/scene/config_fields_test.cpp rewrites them with
//     CONTACTFX_UPDATE_DOCS=1).
// A new field is one member in its struct plus one row here; the tests fail until the docs show it.
#pragma once

#include "contactfx/config.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

namespace cfx
{

/// The allowed values of a number: [min, max], or (min, max] when minExclusive. Non-finite numbers are
/// never allowed. For colours, the range of each channel.
struct FieldRange
{
    float min = 0.0f;
    float max = 0.0f;
    bool minExclusive = false;

    /// Whether `value` is finite and in the range.
    bool Contains(float value) const;
};

/// What a text field must hold besides being a string.
enum class TextRule : std::uint8_t
{
    any,
    name,         ///< non-empty and unique in its list (Validate checks it with the list)
    pattern,      ///< a non-empty glob (assignments.h)
    material,     ///< the name of one of the config's materials
    particleType, ///< the name of one of the config's particle types
    /// The name of one of the config's particle types, or empty (the field then falls back to another;
    /// RuleDef::burstParticleType).
    optionalParticleType,
};

/// An enum member, read and written as the index of its value (enum values are 0, 1, ... in declaration
/// order; Field::choices names them).
template <typename S> struct ChoiceMember
{
    int (*get)(const S&);
    void (*set)(S&, int);
};

/// The member a field describes. `IntensityModel S::*` is a nested struct (RuleDef::intensity), described
/// by IntensityFields().
template <typename S>
using FieldMember =
    std::variant<float S::*, std::optional<float> S::*, bool S::*, std::string S::*, std::uint16_t S::*,
                 std::uint32_t S::*, Color S::*, ChoiceMember<S>, IntensityModel S::*>;

/// One field of struct S.
template <typename S> struct Field
{
    std::string_view name{}; ///< the member's name: JSON key and path element
    FieldMember<S> member{};
    std::string_view unit{};                     ///< "s", "m/s", "1/s", ...; empty when it has none
    FieldRange range{};                          ///< numbers, integers and colour channels
    std::string_view doc{};                      ///< one line: what the field does
    std::span<const std::string_view> choices{}; ///< enums: the names of the values, in value order
    TextRule text = TextRule::any;               ///< text fields
    /// Optional numbers: when both are set, this field must be greater than the named field of S.
    std::string_view greaterThan{};
    float step = 0.0f; ///< the testbed's drag speed for numbers, per pixel
};

/// What every message about an integer field states it expects: "an integer in [1, 4000000]" (the range the
/// docs show as "integer [1, 4000000]"), whatever the wrong value was (out of range, negative, too large for
/// the member, not a whole number, not a number), from the reader and from Validate alike.
std::string ExpectedInteger(const FieldRange& range);
/// The same for a number field: "a number between 0 and 1", or "a number > 0 and <= 3600" when the range
/// excludes its minimum.
std::string ExpectedNumber(const FieldRange& range);

/// What a text field of `rule` must hold, for messages: "a material name", "a particle type name", ...
std::string_view ExpectedText(TextRule rule);

/// Whether a field must be given: a name, or a reference to a material or particle type by name (their
/// defaults are empty; a pattern's is "*"). Such a field that is missing, or empty, is an error.
template <typename S> bool IsRequired(const Field<S>& field)
{
    return std::holds_alternative<std::string S::*>(field.member) &&
           (field.text == TextRule::name || field.text == TextRule::material ||
            field.text == TextRule::particleType);
}

/// The fields of each configuration struct, in the order they are checked and read. The top level of
/// EffectsConfig (name, materials and the lists of these structs) is not a table: its lists are checked
/// as lists (unique names, one rule per pair).
std::span<const Field<ParticleTypeDef>> ParticleTypeFields();
std::span<const Field<RuleDef>> RuleFields();
std::span<const Field<IntensityModel>> IntensityFields();
std::span<const Field<MaterialAssignment>> AssignmentFields();
std::span<const Field<ParticleBudget>> BudgetFields();
/// The `sound` section's own fields (its `rules` list is checked as a list) and those of one sound rule.
std::span<const Field<SoundConfig>> SoundFields();
std::span<const Field<SoundRuleDef>> SoundRuleFields();

} // namespace cfx
