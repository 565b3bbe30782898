// Material assignment rules: first match wins, conditions are plain comparisons.
//
// The glob matcher walks pattern and text once, remembering the last `*` to back up to: O(|pattern| *
// |text|) at worst, no recursion, no allocation, so a hostile name in a scene cannot blow the stack.
#include "contactfx/assignments.h"

#include <box2d/b2_fixture.h>

namespace cfx
{

FixtureFacts FactsOf(const b2Fixture& fixture, std::string_view bodyName, std::string_view fixtureName)
{
    const b2Body& body = *fixture.GetBody();
    return FixtureFacts{bodyName, fixtureName, body.GetType(), fixture.GetFriction(), body.GetMass()};
}

bool GlobMatch(std::string_view pattern, std::string_view text)
{
    std::size_t p = 0;
    std::size_t t = 0;
    std::size_t starAt = std::string_view::npos; // pattern index just after the last `*`
    std::size_t starText = 0;                    // text index that `*` currently stretches to
    while (t < text.size())
    {
        if (p < pattern.size() && pattern[p] == '*')
        {
            starAt = ++p;
            starText = t;
        }
        else if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == text[t]))
        {
            ++p;
            ++t;
        }
        else if (starAt != std::string_view::npos)
        {
            p = starAt;
            t = ++starText;
        }
        else
        {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == '*')
    {
        ++p;
    }
    return p == pattern.size();
}

namespace
{

bool TypeMatches(BodyTypeFilter filter, b2BodyType type)
{
    switch (filter)
    {
    case BodyTypeFilter::any:
        return true;
    case BodyTypeFilter::staticBody:
        return type == b2_staticBody;
    case BodyTypeFilter::kinematicBody:
        return type == b2_kinematicBody;
    case BodyTypeFilter::dynamicBody:
        return type == b2_dynamicBody;
    }
    return false;
}

bool InRange(float value, const std::optional<float>& above, const std::optional<float>& below)
{
    return (!above || value > *above) && (!below || value < *below);
}

} // namespace

bool Matches(const MaterialAssignment& rule, const FixtureFacts& facts)
{
    return TypeMatches(rule.bodyType, facts.bodyType) &&
           InRange(facts.friction, rule.frictionAbove, rule.frictionBelow) &&
           InRange(facts.bodyMass, rule.massAbove, rule.massBelow) &&
           GlobMatch(rule.bodyName, facts.bodyName) && GlobMatch(rule.fixtureName, facts.fixtureName);
}

std::optional<std::size_t> FirstMatch(std::span<const MaterialAssignment> rules, const FixtureFacts& facts)
{
    for (std::size_t i = 0; i < rules.size(); ++i)
    {
        if (Matches(rules[i], facts))
        {
            return i;
        }
    }
    return std::nullopt;
}

} // namespace cfx
