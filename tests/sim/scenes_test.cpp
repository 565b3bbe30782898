// The scene registry: every registered scene loads, gives each fixture its material, and makes the
// particle types it promises when simulated headless, the same way every time.
#include "harness/scenes.h"
#include "scenes_dir.h"

#include <box2d/b2_body.h>
#include <cmath>
#include <gtest/gtest.h>
#include <set>

namespace cfx
{

namespace
{

std::unique_ptr<Simulation> Open(const SceneEntry& entry)
{
    return std::make_unique<Simulation>(SceneSimulationDef(entry, kScenesDir));
}

void RunFor(const SceneEntry& entry, Simulation& simulation, float seconds)
{
    const auto steps = static_cast<int>(std::lround(seconds / simulation.Dt()));
    for (int i = 0; i < steps; ++i)
    {
        StepScene(entry, simulation);
    }
}

} // namespace

TEST(SceneRegistry, HasTheTutorialAndThreeOfOurOwnWithUniqueNames)
{
    std::set<std::string_view> names;
    for (const SceneEntry& entry : Scenes())
    {
        EXPECT_TRUE(names.insert(entry.name).second) << entry.name;
        EXPECT_EQ(FindScene(entry.name), &entry);
        EXPECT_NE(SceneNames().find(entry.name), std::string::npos);
        EXPECT_FALSE(entry.makes.empty()) << entry.name;
        EXPECT_GT(entry.view.height, 0.0f) << entry.name;
    }
    EXPECT_GE(names.size(), 4u);
    ASSERT_NE(FindScene("tutorial"), nullptr);
    EXPECT_EQ(Scenes().front().name, "tutorial");
    EXPECT_EQ(FindScene("tutorial")->file, "physics_driven_particles.json");
    EXPECT_EQ(FindScene("no-such-scene"), nullptr);
}

TEST(SceneRegistry, EverySceneLoadsAndEveryFixtureHasItsMaterial)
{
    for (const SceneEntry& entry : Scenes())
    {
        SCOPED_TRACE(std::string(entry.name));
        std::unique_ptr<Simulation> simulation = Open(entry);
        const Effects& effects = simulation->GetEffects();
        for (const SceneFixture& fixture : simulation->GetScene().fixtures)
        {
            const std::string* material = fixture.properties.FindString("material");
            ASSERT_NE(material, nullptr) << fixture.name;
            EXPECT_TRUE(effects.Material(fixture.fixture).IsValid()) << fixture.name;
            EXPECT_EQ(effects.Material(fixture.fixture), effects.FindMaterial(*material)) << fixture.name;
        }
        // A scene that drives or follows a car has one.
        if (!entry.drive.empty() || entry.followCar)
        {
            EXPECT_TRUE(simulation->GetCar().has_value());
        }
        for (std::string_view type : entry.makes)
        {
            EXPECT_TRUE(effects.Config().FindParticleType(type).IsValid()) << type;
        }
    }
}

TEST(SceneRegistry, EverySceneMakesTheParticlesItPromisesWithinEightSeconds)
{
    for (const SceneEntry& entry : Scenes())
    {
        SCOPED_TRACE(std::string(entry.name));
        std::unique_ptr<Simulation> simulation = Open(entry);
        RunFor(entry, *simulation, entry.name == "tutorial" ? 12.0f : 8.0f);
        const Effects& effects = simulation->GetEffects();
        for (std::string_view type : entry.makes)
        {
            const ParticleTypeId id = effects.Config().FindParticleType(type);
            EXPECT_GT(effects.Stats().spawnedByType[id.index], 0u) << type;
        }
    }
}

TEST(SceneRegistry, TheSameSceneRunsTheSameEveryTime)
{
    const SceneEntry& entry = *FindScene("rockslide");
    std::unique_ptr<Simulation> first = Open(entry);
    std::unique_ptr<Simulation> second = Open(entry);
    RunFor(entry, *first, 4.0f);
    RunFor(entry, *second, 4.0f);
    const std::vector<SceneBody>& a = first->GetScene().bodies;
    const std::vector<SceneBody>& b = second->GetScene().bodies;
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        EXPECT_EQ(a[i].body->GetPosition().x, b[i].body->GetPosition().x) << a[i].name;
        EXPECT_EQ(a[i].body->GetPosition().y, b[i].body->GetPosition().y) << a[i].name;
        EXPECT_EQ(a[i].body->GetAngle(), b[i].body->GetAngle()) << a[i].name;
    }
    EXPECT_EQ(first->GetEffects().Stats().spawnedByType, second->GetEffects().Stats().spawnedByType);
    EXPECT_EQ(first->GetEffects().Stats().live, second->GetEffects().Stats().live);
}

// The rock slide keeps going: rocks that came to rest at the bottom start again from their home.
TEST(SceneRegistry, RockslideSendsRocksThatCameToRestBackHome)
{
    const SceneEntry& entry = *FindScene("rockslide");
    ASSERT_NE(entry.beforeStep, nullptr);
    std::unique_ptr<Simulation> simulation = Open(entry);
    std::vector<const SceneBody*> rocks;
    for (const SceneBody& body : simulation->GetScene().bodies)
    {
        if (body.properties.Find("home") != nullptr)
        {
            rocks.push_back(&body);
        }
    }
    ASSERT_FALSE(rocks.empty());
    const float bottom = 1.0f; // m: the concrete floor is at y = 0
    const float top = rocks.front()->body->GetPosition().y - 5.0f;
    std::vector<bool> reachedBottom(rocks.size(), false);
    int returned = 0;
    for (int step = 0; step < 15 * 60; ++step)
    {
        StepScene(entry, *simulation);
        for (std::size_t i = 0; i < rocks.size(); ++i)
        {
            const float y = rocks[i]->body->GetPosition().y;
            if (y < bottom)
            {
                reachedBottom[i] = true;
            }
            else if (reachedBottom[i] && y > top)
            {
                reachedBottom[i] = false;
                ++returned;
            }
        }
    }
    EXPECT_GT(returned, 0);
}

// The skid pad's car is built to stay on its wheels through the whole scripted drive of launches and
// skids (the tutorial's short car flips over under the same drive), and every part of the drive smokes.
TEST(SceneRegistry, SkidpadCarStaysOnItsWheelsAndSmokesThroughTheWholeDrive)
{
    const SceneEntry& entry = *FindScene("skidpad");
    std::unique_ptr<Simulation> simulation = Open(entry);
    ASSERT_TRUE(simulation->GetCar().has_value());
    const b2Body* car = simulation->GetCar()->Body();
    const Effects& effects = simulation->GetEffects();
    const std::size_t smoke = effects.Config().FindParticleType("smoke").index;
    float worstTilt = 0.0f;
    for (const DriveSegment& segment : entry.drive)
    {
        const std::uint64_t before = effects.Stats().spawnedByType[smoke];
        while (simulation->Time() < segment.until)
        {
            StepScene(entry, *simulation);
            worstTilt = std::max(worstTilt, std::abs(std::remainder(car->GetAngle(), 2.0f * b2_pi)));
        }
        EXPECT_GT(effects.Stats().spawnedByType[smoke], before) << "segment ending at " << segment.until;
    }
    EXPECT_LT(worstTilt, 0.5f);
    EXPECT_GT(car->GetPosition().y, 0.0f);
}

} // namespace cfx
