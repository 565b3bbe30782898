// The testbed's keys without a window: the table, and each action carried out on a session.
#include "keys.h"
#include "scenes_dir.h"
#include "testbed/testbed_support.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <box2d/b2_body.h>
#include <box2d/b2_world.h>
#include <gtest/gtest.h>
#include <set>

namespace cfx::testbed
{

namespace
{

struct Keys : ::testing::Test
{
    Keys() : session(kScenesDir)
    {
        session.Open(*FindScene("grinder"));
        session.ResetView(800, 600);
    }

    bool Press(int key) { return ApplyKey(ActionForKey(key), target); }

    Session session;
    bool hidden = false;
    std::string error;
    KeyTarget target{session, hidden, error, 800, 600};
};

int Index(const SceneEntry& entry)
{
    return static_cast<int>(&entry - Scenes().data());
}

} // namespace

TEST_F(Keys, XZoomsInAndZZoomsOutAboutTheViewsMiddleAsInBox2DsTestbed)
{
    const Camera before = session.Camera();
    ASSERT_TRUE(Press(GLFW_KEY_X));
    EXPECT_FLOAT_EQ(session.Camera().pixelsPerMetre, before.pixelsPerMetre * kKeyZoomStep) << "x: closer";
    EXPECT_FLOAT_EQ(session.Camera().center.x, before.center.x);
    ASSERT_TRUE(Press(GLFW_KEY_Z));
    EXPECT_FLOAT_EQ(session.Camera().pixelsPerMetre, before.pixelsPerMetre) << "z: back out";
    ASSERT_TRUE(Press(GLFW_KEY_Z));
    EXPECT_LT(session.Camera().pixelsPerMetre, before.pixelsPerMetre);
}

TEST_F(Keys, BracketsStepThroughTheScenesInOrderAndWrapAround)
{
    const std::size_t count = Scenes().size();
    ASSERT_GE(count, 2u);
    const int start = Index(session.Entry());
    ASSERT_TRUE(Press(GLFW_KEY_RIGHT_BRACKET));
    EXPECT_EQ(Index(session.Entry()), (start + 1) % static_cast<int>(count));
    ASSERT_TRUE(Press(GLFW_KEY_LEFT_BRACKET));
    EXPECT_EQ(Index(session.Entry()), start);
    for (std::size_t i = 0; i < count; ++i)
    {
        Press(GLFW_KEY_LEFT_BRACKET);
    }
    EXPECT_EQ(Index(session.Entry()), start) << "once around";
    EXPECT_TRUE(error.empty()) << error;
}

TEST_F(Keys, TabHidesAndShowsThePanels)
{
    ASSERT_TRUE(Press(GLFW_KEY_TAB));
    EXPECT_TRUE(hidden);
    Press(GLFW_KEY_TAB);
    EXPECT_FALSE(hidden);
}

TEST_F(Keys, SpaceLaunchesASteelBallIntoTheView)
{
    b2World& world = *session.Sim().GetScene().world;
    const int bodies = world.GetBodyCount();
    ASSERT_TRUE(Press(GLFW_KEY_SPACE));
    ASSERT_EQ(world.GetBodyCount(), bodies + 1);
    const b2Body* ball = world.GetBodyList(); // Box2D puts a new body first
    EXPECT_EQ(ball->GetType(), b2_dynamicBody);
    EXPECT_EQ(session.Sim().GetEffects().Material(ball->GetFixtureList()),
              session.Sim().GetEffects().FindMaterial("steel"));
    const b2Vec2 at = session.Camera().ToPixels(ball->GetPosition());
    EXPECT_GT(at.x, 0.0f);
    EXPECT_GT(at.y, 0.0f);
    EXPECT_LT(at.x, static_cast<float>(session.Camera().width));
    EXPECT_LT(at.y, static_cast<float>(session.Camera().height));
    EXPECT_LT(ball->GetLinearVelocity().y, 0.0f) << "down into the scene";
}

TEST_F(Keys, PauseStepRestartAndPanKeepTheirKeys)
{
    Press(GLFW_KEY_P);
    EXPECT_TRUE(session.paused);
    Press(GLFW_KEY_O);
    EXPECT_TRUE(session.stepOnce);
    const float x = session.Camera().center.x;
    Press(GLFW_KEY_LEFT);
    EXPECT_LT(session.Camera().center.x, x) << "the view moves left: the world slides right";
    const std::uint64_t generation = session.Generation();
    Press(GLFW_KEY_R);
    EXPECT_GT(session.Generation(), generation);
    EXPECT_EQ(ActionForKey(GLFW_KEY_ESCAPE), KeyAction::quit);
    EXPECT_FALSE(ApplyKey(KeyAction::quit, target)) << "quitting is the window's";
    EXPECT_EQ(ActionForKey(GLFW_KEY_Q), KeyAction::none);
}

TEST(KeyTable, EveryKeyIsBoundOnceAndHelpListsEveryNamedRow)
{
    std::set<int> keys;
    const std::string help = KeysHelp();
    for (const KeyBinding& binding : KeyBindings())
    {
        if (binding.key != 0)
        {
            EXPECT_TRUE(keys.insert(binding.key).second) << "key " << binding.key << " bound twice";
            EXPECT_EQ(ActionForKey(binding.key), binding.action);
        }
        if (binding.name != nullptr)
        {
            EXPECT_NE(help.find(std::string("  ") + binding.name), std::string::npos) << binding.name;
            EXPECT_NE(help.find(binding.meaning), std::string::npos) << binding.meaning;
        }
    }
}

TEST(KeyTable, TheTestbedsHelpListsTheKeys)
{
    const test::CliResult result = test::RunTestbed("--help");
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find(KeysHelp()), std::string::npos) << result.output;
}

} // namespace cfx::testbed
