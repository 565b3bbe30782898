#include "contactfx/config.h"
#include "contactfx/effects.h"
#include "contactfx/error.h"
#include "contactfx/presets.h"
#include "contactfx/rules.h"

#include <box2d/box2d.h>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <string>

namespace cfx
{

TEST(RuleTable, IsSymmetric)
{
    RuleTable table(4);
    table.Set(MaterialId{0}, MaterialId{2}, RuleId{7});
    EXPECT_EQ(table.Find(MaterialId{0}, MaterialId{2}), RuleId{7});
    EXPECT_EQ(table.Find(MaterialId{2}, MaterialId{0}), RuleId{7});
    EXPECT_EQ(table.FirstMaterial(RuleId{7}), MaterialId{0});
    EXPECT_FALSE(table.Find(MaterialId{0}, MaterialId{1}).IsValid());
    EXPECT_FALSE(table.Find(MaterialId{}, MaterialId{2}).IsValid());
    EXPECT_FALSE(table.Find(MaterialId{9}, MaterialId{2}).IsValid());
}

TEST(RuleTable, AnyNumberOfRules)
{
    const int materials = 40;
    RuleTable table(materials);
    std::uint16_t next = 0;
    for (int a = 0; a < materials; ++a)
    {
        for (int b = a; b < materials; ++b)
        {
            table.Set(MaterialId{static_cast<std::uint16_t>(a)}, MaterialId{static_cast<std::uint16_t>(b)},
                      RuleId{next++});
        }
    }
    EXPECT_EQ(table.RuleCount(), 40 * 41 / 2);
    EXPECT_EQ(table.Find(MaterialId{39}, MaterialId{3}), table.Find(MaterialId{3}, MaterialId{39}));
}

TEST(RuleTable, ManyMaterialsTakeRoomForTheirRulesOnly)
{
    // Above kDenseMaterials the table hashes the pairs: 65,535 materials would be 8.6 GB as a matrix
    // (and their count squared overflows an int).
    for (const int materials : {RuleTable::kDenseMaterials + 1, 50000, 65535})
    {
        RuleTable table(materials);
        std::uint16_t next = 0;
        for (int a = 0; a < 300; ++a)
        {
            const auto first = static_cast<std::uint16_t>(materials - 1 - a);
            const auto second = static_cast<std::uint16_t>((a * 7) % (materials - 300));
            table.Set(MaterialId{first}, MaterialId{second}, RuleId{next++});
        }
        for (int a = 0; a < 300; ++a)
        {
            const auto first = static_cast<std::uint16_t>(materials - 1 - a);
            const auto second = static_cast<std::uint16_t>((a * 7) % (materials - 300));
            EXPECT_EQ(table.Find(MaterialId{second}, MaterialId{first}),
                      RuleId{static_cast<std::uint16_t>(a)});
            EXPECT_EQ(table.Find(MaterialId{first}, MaterialId{second}),
                      RuleId{static_cast<std::uint16_t>(a)});
            EXPECT_EQ(table.FirstMaterial(RuleId{static_cast<std::uint16_t>(a)}), MaterialId{first});
        }
        EXPECT_FALSE(table.Find(MaterialId{1}, MaterialId{2}).IsValid());
        EXPECT_FALSE(table.Find(MaterialId{}, MaterialId{0}).IsValid());
        table.Set(MaterialId{0}, MaterialId{static_cast<std::uint16_t>(materials - 1)},
                  RuleId{9}); // replaces
        EXPECT_EQ(table.Find(MaterialId{static_cast<std::uint16_t>(materials - 1)}, MaterialId{0}),
                  RuleId{9});
        EXPECT_EQ(table.RuleCount(), 300);
    }
}

TEST(RuleTable, RefusesIdsOutOfRange)
{
    EXPECT_THROW(RuleTable(-1), InputError);
    EXPECT_THROW(RuleTable(65536), InputError);
    for (const int materials : {4, 2000})
    {
        RuleTable table(materials);
        const auto beyond = static_cast<std::uint16_t>(materials);
        EXPECT_THROW(table.Set(MaterialId{0}, MaterialId{beyond}, RuleId{0}), InputError);
        EXPECT_THROW(table.Set(MaterialId{}, MaterialId{0}, RuleId{0}), InputError);
        EXPECT_THROW(table.Set(MaterialId{0}, MaterialId{1}, RuleId{}), InputError);
        EXPECT_FALSE(table.Find(MaterialId{0}, MaterialId{1}).IsValid());
    }
}

TEST(Effects, FiftyThousandMaterialsFindTheirRule)
{
    EffectsConfig config = DefaultPreset();
    for (int i = 0; i < 50000; ++i)
    {
        config.materials.push_back("m" + std::to_string(i));
    }
    RuleDef rule = config.rules.front();
    rule.materialA = "m49999";
    rule.materialB = "m0";
    config.rules.push_back(rule);
    ASSERT_TRUE(Validate(config).empty());
    b2World world(b2Vec2(0.0f, -10.0f));
    EffectsDef def;
    def.config = config;
    Effects effects(world, def);
    EXPECT_EQ(effects.Rules().Find(effects.FindMaterial("m0"), effects.FindMaterial("m49999")),
              RuleId{static_cast<std::uint16_t>(config.rules.size() - 1)});
    EXPECT_EQ(effects.Rules().Find(effects.FindMaterial("steel"), effects.FindMaterial("concrete")),
              RuleId{0});
    EXPECT_FALSE(effects.Rules().Find(effects.FindMaterial("m1"), effects.FindMaterial("m2")).IsValid());
}

TEST(Presets, TutorialTableHasFourMaterialsAndFourRules)
{
    EffectsConfig tutorial = TutorialPreset();
    ASSERT_EQ(tutorial.materials.size(), 4u);
    ASSERT_EQ(tutorial.rules.size(), 4u);
    EXPECT_TRUE(Validate(tutorial).empty());
    EXPECT_TRUE(Validate(DefaultPreset()).empty());
    auto ruleFor = [&](const char* a, const char* b) -> std::string
    {
        for (const RuleDef& rule : tutorial.rules)
        {
            if ((rule.materialA == a && rule.materialB == b) || (rule.materialA == b && rule.materialB == a))
            {
                return rule.particleType;
            }
        }
        return "none";
    };
    EXPECT_EQ(ruleFor("steel", "concrete"), "sparks");
    EXPECT_EQ(ruleFor("concrete", "rubber"), "smoke");
    EXPECT_EQ(ruleFor("dirt", "steel"), "dirt");
    EXPECT_EQ(ruleFor("rubber", "dirt"), "dirt");
    EXPECT_EQ(ruleFor("steel", "rubber"), "none");
    EXPECT_EQ(tutorial.budget.capacity, 100u);
    for (const RuleDef& rule : tutorial.rules)
    {
        EXPECT_EQ(rule.threshold, 1.0f);
        EXPECT_EQ(rule.emission, EmissionMode::perStep);
        EXPECT_EQ(rule.intensity.speed, SpeedMode::full);
        EXPECT_EQ(rule.intensity.friction, FrictionMix::product);
        EXPECT_EQ(rule.intensity.points, ManifoldPoints::first);
    }
}

TEST(Config, ValidateNamesEveryBadField)
{
    EffectsConfig config = DefaultPreset();
    config.rules[1].threshold = std::nanf("");
    config.rules[2].materialB = "glass";
    config.particleTypes[0].radius = -1.0f;
    config.particleTypes[1].lifetime = 0.0f;
    config.rules.push_back(config.rules[0]);
    std::swap(config.rules.back().materialA, config.rules.back().materialB);
    config.budget.capacity = 0;
    std::vector<Diagnostic> problems = Validate(config, "fx.json");
    std::vector<std::string> paths;
    for (const Diagnostic& problem : problems)
    {
        EXPECT_EQ(problem.file, "fx.json");
        paths.push_back(problem.path);
    }
    EXPECT_EQ(paths, (std::vector<std::string>{"particleTypes[0].radius", "particleTypes[1].lifetime",
                                               "rules[1].threshold", "rules[2].materialB", "rules[4]",
                                               "budget.capacity"}));
    EXPECT_NE(problems[2].message.find("NaN"), std::string::npos);
}

// Values built in code get the same ranges as files (docs/effects-config.md): each keeps the simulation
// finite and its cost bounded.
TEST(Config, ValidateBoundsEveryNumber)
{
    EffectsConfig config = DefaultPreset();
    ParticleTypeDef& type = config.particleTypes[0];
    type.radius = 3e9f;
    type.gravityScale = std::numeric_limits<float>::max();
    type.normalSpeed = -std::numeric_limits<float>::max();
    type.spread = std::numeric_limits<float>::infinity();
    type.inheritA = 1e30f;
    type.slipFactor = -1e30f;
    RuleDef& rule = config.rules[0];
    rule.ratePerIntensity = 1e9f;
    rule.maxRate = 1e9f;
    rule.burstMax = 1e9f;
    config.assignments[0].massAbove = 1e30f;
    std::vector<std::string> paths;
    for (const Diagnostic& problem : Validate(config))
    {
        EXPECT_NE(problem.message.find("expected a number"), std::string::npos) << problem.ToString();
        paths.push_back(problem.path);
    }
    EXPECT_EQ(paths, (std::vector<std::string>{"particleTypes[0].inheritA", "particleTypes[0].slipFactor",
                                               "particleTypes[0].normalSpeed", "particleTypes[0].spread",
                                               "particleTypes[0].gravityScale", "particleTypes[0].radius",
                                               "rules[0].ratePerIntensity", "rules[0].maxRate",
                                               "rules[0].burstMax", "assignments[0].massAbove"}));
    EXPECT_TRUE(Validate(TutorialPreset()).empty());
}

// Each rule has room for budget.contacts touching contacts of its own: a trial's 45,150 rules with room
// for 1,000,000 contacts each reserved 2.9 TB at creation (15 s; on a system that does not overcommit,
// std::bad_alloc). Rules times contacts is bounded, and the message names budget.contacts.
// Ids are 16 bits with one value for "none": each list holds at most 65534 entries, and the message says how
// many it found (a trial saw it for materials only).
TEST(Config, EachListsLimitNamesTheCountFound)
{
    EffectsConfig config = DefaultPreset();
    config.particleTypes.resize(65535, config.particleTypes[0]);
    config.rules.resize(65535, config.rules[0]);
    std::vector<std::string> limits;
    for (const Diagnostic& problem : Validate(config))
    {
        if (problem.path == "particleTypes" || problem.path == "rules")
        {
            limits.push_back(problem.path + ": " + problem.message);
        }
    }
    EXPECT_EQ(limits,
              (std::vector<std::string>{"particleTypes: expected at most 65534 particle types, found 65535",
                                        "rules: expected at most 65534 rules, found 65535"}));
}

TEST(Config, TheContactRoomOfAllRulesIsBounded)
{
    EffectsConfig config = DefaultPreset();
    config.rules.resize(1);
    for (int i = 0; i < 12; ++i)
    {
        config.materials.push_back("m" + std::to_string(i));
    }
    for (int i = 0; i < 12; ++i)
    {
        for (int j = i; j < 12; ++j)
        {
            RuleDef rule = config.rules[0];
            rule.materialA = "m" + std::to_string(i);
            rule.materialB = "m" + std::to_string(j);
            config.rules.push_back(rule);
        }
    }
    ASSERT_EQ(config.rules.size(), 79u);
    config.budget.contacts = 1000000; // 79e6 > 2^22
    const std::vector<Diagnostic> problems = Validate(config);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].path, "budget.contacts");
    EXPECT_NE(problems[0].message.find("79 rules"), std::string::npos) << problems[0].message;
    config.budget.contacts = static_cast<std::uint32_t>(kMaxContactRoom / 79);
    EXPECT_TRUE(Validate(config).empty());
}

TEST(Config, EffectsRefusesAnInvalidConfig)
{
    b2World world(b2Vec2(0.0f, -10.0f));
    EffectsDef def;
    def.config = DefaultPreset();
    def.config.particleTypes[2].drag = -3.0f;
    try
    {
        Effects effects(world, def);
        FAIL() << "expected InputError";
    }
    catch (const InputError& error)
    {
        EXPECT_EQ(error.Diagnostics().size(), 1u);
        EXPECT_EQ(error.Diagnostics()[0].path, "particleTypes[2].drag");
        EXPECT_NE(std::string(error.what()).find("particleTypes[2].drag"), std::string::npos);
    }
}

} // namespace cfx
