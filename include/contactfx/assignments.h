// contactfx: material assignment rules.
//
// Scenes made in RUBE rarely carry a `material` property on every fixture, and a plain scene should give
// effects without editing. An assignment rule names a material and says which fixtures get it: by body
// or fixture name (a glob), by body type, by a friction range and by a body mass range, much as the
// tutorial guessed its materials from fixture properties. Rules are tried in order and the first match
// wins; a fixture no rule matches has no material. A fixture's own `material` property always takes
// precedence (contactfx_scene applies the rules only to fixtures without one).
//
// Everything here is a pure function of plain values: no Box2D object is read except through FactsOf.
#pragma once

#include <box2d/b2_body.h>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

class b2Fixture;

namespace cfx
{

/// Which body types an assignment accepts.
enum class BodyTypeFilter : std::uint8_t
{
    any,
    staticBody,
    kinematicBody,
    dynamicBody,
};

/// One assignment rule. Every condition must hold; an absent bound does not constrain.
struct MaterialAssignment
{
    std::string material;          ///< a material of the config (required)
    std::string bodyName = "*";    ///< glob on the body's name: `*` any run, `?` one character
    std::string fixtureName = "*"; ///< glob on the fixture's name
    BodyTypeFilter bodyType = BodyTypeFilter::any;
    std::optional<float> frictionAbove; ///< fixture friction > this, [-1000, 1000]
    std::optional<float> frictionBelow; ///< fixture friction < this, [-1000, 1000], > frictionAbove
    std::optional<float> massAbove;     ///< body mass > this, kg, [-1e12, 1e12] (static, kinematic: 0)
    std::optional<float> massBelow;     ///< body mass < this, kg, [-1e12, 1e12], > massAbove

    bool operator==(const MaterialAssignment&) const = default;
};

/// What an assignment looks at, for one fixture. Views must outlive the call they are passed to.
struct FixtureFacts
{
    std::string_view bodyName;
    std::string_view fixtureName;
    b2BodyType bodyType = b2_staticBody;
    float friction = 0.0f;
    float bodyMass = 0.0f; ///< kg
};

/// The facts of a Box2D fixture (type, friction, its body's current mass) with the given names.
FixtureFacts FactsOf(const b2Fixture& fixture, std::string_view bodyName, std::string_view fixtureName);

/// Whether `text` matches the glob `pattern` as a whole: `*` matches any run (also empty), `?` any one
/// character, every other character itself (case-sensitive).
bool GlobMatch(std::string_view pattern, std::string_view text);

/// Whether every condition of `rule` holds for `facts`.
bool Matches(const MaterialAssignment& rule, const FixtureFacts& facts);

/// Index of the first rule that matches, or nothing.
std::optional<std::size_t> FirstMatch(std::span<const MaterialAssignment> rules, const FixtureFacts& facts);

} // namespace cfx
