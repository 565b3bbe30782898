// Material assignment rules: globs, conditions, first match (their JSON: effects_json_test.cpp).
#include "contactfx/assignments.h"
#include "contactfx/presets.h"

#include <cmath>
#include <gtest/gtest.h>

namespace cfx
{

namespace
{

FixtureFacts Facts(b2BodyType type, float friction, float mass, std::string_view body = "body",
                   std::string_view fixture = "fixture")
{
    return FixtureFacts{body, fixture, type, friction, mass};
}

} // namespace

TEST(Glob, StarQuestionMarkAndLiterals)
{
    EXPECT_TRUE(GlobMatch("*", ""));
    EXPECT_TRUE(GlobMatch("*", "anything"));
    EXPECT_TRUE(GlobMatch("ground_*", "ground_dirt_3"));
    EXPECT_FALSE(GlobMatch("ground_*", "wheel_front"));
    EXPECT_TRUE(GlobMatch("*_front", "wheel_front"));
    EXPECT_TRUE(GlobMatch("wheel_????", "wheel_rear"));
    EXPECT_FALSE(GlobMatch("wheel_????", "wheel_front"));
    EXPECT_TRUE(GlobMatch("*dirt*", "ground_dirt_3"));
    EXPECT_TRUE(GlobMatch("a*b*c", "aXXbYYbZc"));
    EXPECT_FALSE(GlobMatch("a*b*c", "aXXbYYbZ"));
    EXPECT_TRUE(GlobMatch("car", "car"));
    EXPECT_FALSE(GlobMatch("car", "Car"));
    EXPECT_FALSE(GlobMatch("car", "cart"));
    EXPECT_FALSE(GlobMatch("", "x"));
    EXPECT_TRUE(GlobMatch("", ""));
    EXPECT_TRUE(GlobMatch("**?**", "x"));
    EXPECT_FALSE(GlobMatch("**?**", ""));
}

TEST(Glob, LongHostileNamesStayCheap)
{
    const std::string name(20000, 'a');
    EXPECT_FALSE(GlobMatch("*a*a*a*a*a*b", name));
    EXPECT_TRUE(GlobMatch("*a*a*a*a*a*", name));
}

TEST(Assignment, EveryConditionMustHold)
{
    MaterialAssignment rule;
    rule.material = "m";
    EXPECT_TRUE(Matches(rule, Facts(b2_staticBody, 0.0f, 0.0f))) << "no conditions: matches all";

    rule.bodyType = BodyTypeFilter::dynamicBody;
    EXPECT_FALSE(Matches(rule, Facts(b2_staticBody, 0.5f, 0.0f)));
    EXPECT_FALSE(Matches(rule, Facts(b2_kinematicBody, 0.5f, 0.0f)));
    EXPECT_TRUE(Matches(rule, Facts(b2_dynamicBody, 0.5f, 1.0f)));

    rule.frictionAbove = 0.5f; // strict
    EXPECT_FALSE(Matches(rule, Facts(b2_dynamicBody, 0.5f, 1.0f)));
    EXPECT_TRUE(Matches(rule, Facts(b2_dynamicBody, 0.51f, 1.0f)));
    rule.frictionBelow = 0.9f; // strict
    EXPECT_FALSE(Matches(rule, Facts(b2_dynamicBody, 0.9f, 1.0f)));
    EXPECT_TRUE(Matches(rule, Facts(b2_dynamicBody, 0.7f, 1.0f)));

    rule.massAbove = 2.0f;
    EXPECT_FALSE(Matches(rule, Facts(b2_dynamicBody, 0.7f, 2.0f)));
    rule.massBelow = 4.0f;
    EXPECT_TRUE(Matches(rule, Facts(b2_dynamicBody, 0.7f, 3.0f)));
    EXPECT_FALSE(Matches(rule, Facts(b2_dynamicBody, 0.7f, 4.0f)));

    rule.bodyName = "car*";
    rule.fixtureName = "*_body";
    EXPECT_TRUE(Matches(rule, Facts(b2_dynamicBody, 0.7f, 3.0f, "car2", "steel_body")));
    EXPECT_FALSE(Matches(rule, Facts(b2_dynamicBody, 0.7f, 3.0f, "truck", "steel_body")));
    EXPECT_FALSE(Matches(rule, Facts(b2_dynamicBody, 0.7f, 3.0f, "car2", "steel_door")));
}

TEST(Assignment, FirstMatchWins)
{
    const std::vector<MaterialAssignment> rules = TutorialPreset().assignments;
    ASSERT_EQ(rules.size(), 4u);
    auto materialOf = [&](const FixtureFacts& facts) -> std::string
    {
        const std::optional<std::size_t> index = FirstMatch(rules, facts);
        return index ? rules[*index].material : "none";
    };
    // The tutorial's guesses: the car (mass 3.4, dynamic, friction 0.5) would also pass rubber's test.
    EXPECT_EQ(materialOf(Facts(b2_dynamicBody, 0.5f, 3.4f)), "steel");
    EXPECT_EQ(materialOf(Facts(b2_dynamicBody, 0.9f, 0.75f)), "rubber");
    EXPECT_EQ(materialOf(Facts(b2_staticBody, 0.8f, 0.0f)), "concrete");
    EXPECT_EQ(materialOf(Facts(b2_staticBody, 0.25f, 0.0f)), "dirt");
    EXPECT_EQ(materialOf(Facts(b2_dynamicBody, 0.9f, 0.1f)), "none") << "light debris";
    EXPECT_EQ(materialOf(Facts(b2_kinematicBody, 0.9f, 0.0f)), "none");
    EXPECT_FALSE(FirstMatch({}, Facts(b2_staticBody, 0.8f, 0.0f)).has_value());
}

} // namespace cfx
