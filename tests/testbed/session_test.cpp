// What the testbed does without its window: the scene session (pause, single step, the car's keys,
// following, zoom and pan), dragging bodies, and the live effects editor.
#include "contactfx/scene/effects_json.h"
#include "effects_editor.h"
#include "keys.h"
#include "mouse_drag.h"
#include "scenes_dir.h"
#include "session.h"
#include "testbed/testbed_support.h"

#include <box2d/b2_body.h>
#include <box2d/b2_wheel_joint.h>
#include <box2d/b2_world.h>
#include <gtest/gtest.h>

namespace cfx::testbed
{

namespace
{

constexpr int kViewWidth = 890;
constexpr int kViewHeight = 720;

struct Opened
{
    explicit Opened(const char* scene) : session(kScenesDir)
    {
        session.Open(*FindScene(scene));
        session.ResetView(kViewWidth, kViewHeight);
    }
    void Advance(int frames)
    {
        for (int i = 0; i < frames; ++i)
        {
            session.Advance();
        }
    }
    Session session;
};

b2Vec2 Near(const Camera& camera, b2Vec2 world)
{
    return camera.ToPixels(world);
}

} // namespace

TEST(TestbedSession, OpensTheSceneWithItsViewAndKeepsItOnBadInput)
{
    Opened opened("grinder");
    Session& session = opened.session;
    EXPECT_EQ(session.Entry().name, "grinder");
    const SceneView& view = session.Entry().view;
    EXPECT_FLOAT_EQ(static_cast<float>(kViewHeight) / session.Camera().pixelsPerMetre, view.height);
    EXPECT_EQ(session.Camera().center.x, view.center.x);

    EffectsConfig invalid = DefaultPreset();
    invalid.budget.capacity = 0;
    EXPECT_THROW(session.Open(*FindScene("tutorial"), invalid), InputError);
    EXPECT_EQ(session.Entry().name, "grinder");
    opened.Advance(10);
    EXPECT_EQ(session.Sim().Steps(), 10u);
}

// A scene whose view is its whole world (rockslide: the slope, the floor and both walls) shows every body
// whole in the testbed's narrower picture too, not a fixed height that cuts off the top of the slope.
TEST(TestbedSession, AWholeWorldViewShowsEveryBody)
{
    Opened opened("rockslide");
    ASSERT_TRUE(opened.session.Entry().view.wholeWorld);
    const Camera& camera = opened.session.Camera();
    int fixtures = 0;
    for (const b2Body* body = opened.session.Sim().GetScene().world->GetBodyList(); body != nullptr;
         body = body->GetNext())
    {
        for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr;
             fixture = fixture->GetNext())
        {
            for (int child = 0; child < fixture->GetShape()->GetChildCount(); ++child)
            {
                const b2AABB box = fixture->GetAABB(child);
                for (const b2Vec2 corner : {box.lowerBound, box.upperBound})
                {
                    const b2Vec2 pixel = camera.ToPixels(corner);
                    EXPECT_GE(pixel.x, 0.0f);
                    EXPECT_LE(pixel.x, static_cast<float>(kViewWidth));
                    EXPECT_GE(pixel.y, 0.0f);
                    EXPECT_LE(pixel.y, static_cast<float>(kViewHeight));
                }
            }
            ++fixtures;
        }
    }
    EXPECT_GT(fixtures, 10);
}

TEST(TestbedSession, PauseHoldsAndSingleStepAdvancesOneStep)
{
    Opened opened("grinder");
    Session& session = opened.session;
    session.paused = true;
    opened.Advance(5);
    EXPECT_EQ(session.Sim().Steps(), 0u);
    session.stepOnce = true;
    opened.Advance(5);
    EXPECT_EQ(session.Sim().Steps(), 1u);
    EXPECT_FALSE(session.stepOnce);
    session.paused = false;
    opened.Advance(5);
    EXPECT_EQ(session.Sim().Steps(), 6u);
}

TEST(TestbedSession, TheKeysTakeTheCarFromItsScript)
{
    // The demo script launches the car to the right; holding a drives it to the left instead.
    Opened opened("tutorial");
    Session& session = opened.session;
    session.SetKeys(false, false, false);
    EXPECT_FALSE(session.Manual());
    for (int i = 0; i < 90; ++i)
    {
        session.SetKeys(true, false, false);
        session.Advance();
    }
    EXPECT_TRUE(session.Manual());
    EXPECT_LT(session.Sim().GetCar()->Body()->GetLinearVelocity().x, -1.0f);

    const auto* front =
        static_cast<const b2WheelJoint*>(session.Sim().GetScene().FindJoint("suspension_front")->joint);
    EXPECT_FALSE(front->IsMotorEnabled()); // rear-wheel drive
    session.ToggleFourWheelDrive();
    opened.Advance(1);
    EXPECT_TRUE(front->IsMotorEnabled());
    session.SetKeys(false, false, true); // brake: both motors hold the wheels
    opened.Advance(1);
    EXPECT_TRUE(front->IsMotorEnabled());
    EXPECT_EQ(front->GetMotorSpeed(), 0.0f);
}

TEST(TestbedSession, FollowingKeepsTheCarInPlaceOnScreenAndPanningStopsIt)
{
    Opened opened("tutorial");
    Session& session = opened.session;
    ASSERT_TRUE(session.followCar);
    const b2Body& car = *session.Sim().GetCar()->Body();
    opened.Advance(1);
    const b2Vec2 onScreen = Near(session.Camera(), car.GetPosition());
    opened.Advance(120);
    EXPECT_NEAR(Near(session.Camera(), car.GetPosition()).x, onScreen.x, 0.01f);
    // Vertically the view holds the car's lowest point, which moves a little as the car tilts.
    EXPECT_NEAR(Near(session.Camera(), car.GetPosition()).y, onScreen.y, 10.0f);

    const b2Vec2 center = session.Camera().center;
    session.Pan(b2Vec2(100.0f, 0.0f)); // content moves right: the view looks further left
    EXPECT_FALSE(session.followCar);
    EXPECT_NEAR(session.Camera().center.x, center.x - 100.0f / session.Camera().pixelsPerMetre, 1e-3f);
    opened.Advance(60);
    EXPECT_GT(std::abs(Near(session.Camera(), car.GetPosition()).x - onScreen.x), 10.0f);
}

TEST(TestbedSession, ZoomKeepsThePointUnderTheCursorAndResizeKeepsTheHeightShown)
{
    Opened opened("rockslide");
    Session& session = opened.session;
    const b2Vec2 anchor(-12.0f, 3.0f);
    const b2Vec2 before = session.Camera().ToPixels(anchor);
    const float ppm = session.Camera().pixelsPerMetre;
    session.Zoom(2.0f, anchor); // shows twice as much
    EXPECT_FLOAT_EQ(session.Camera().pixelsPerMetre, ppm / 2.0f);
    EXPECT_NEAR(session.Camera().ToPixels(anchor).x, before.x, 1e-2f);
    EXPECT_NEAR(session.Camera().ToPixels(anchor).y, before.y, 1e-2f);

    const float metresHigh = static_cast<float>(session.Camera().height) / session.Camera().pixelsPerMetre;
    session.Resize(400, 300);
    EXPECT_EQ(session.Camera().width, 400);
    EXPECT_FLOAT_EQ(static_cast<float>(session.Camera().height) / session.Camera().pixelsPerMetre,
                    metresHigh);
    session.ResetView(400, 300); // the scene's own view again, as opened at that size
    Session fresh(kScenesDir);
    fresh.Open(*FindScene("rockslide"));
    fresh.ResetView(400, 300);
    EXPECT_EQ(session.Camera().pixelsPerMetre, fresh.Camera().pixelsPerMetre);
    EXPECT_EQ(session.Camera().center, fresh.Camera().center);
}

// A trial's artist opened the testbed with --effects, edited a threshold and went to the next scene: it
// opened with its own effects, the file and the edit silently gone. The configuration chosen (given to Open,
// or applied) goes with the user to every scene; a scene it does not fit is refused and the old one stays.
TEST(TestbedSession, TheChosenEffectsGoWithTheUserToOtherScenes)
{
    Session session(kScenesDir);
    EffectsConfig given = DefaultPreset();
    given.rules[0].threshold = 0.85f;
    session.Open(*FindScene("skidpad"), given);
    session.OpenNeighbour(1);
    EXPECT_NE(session.Entry().name, "skidpad");
    EXPECT_EQ(session.Sim().GetEffects().Config(), given);

    EffectsConfig edited = given;
    edited.rules[0].threshold = 5.0f;
    session.ApplyConfig(edited);
    session.OpenNeighbour(-1);
    EXPECT_EQ(session.Entry().name, "skidpad");
    EXPECT_EQ(session.Sim().GetEffects().Config(), edited);
    session.Open(*FindScene("grinder"));
    EXPECT_EQ(session.Sim().GetEffects().Config(), edited);

    EffectsConfig invalid = edited;
    invalid.budget.capacity = 0;
    EXPECT_THROW(session.Open(*FindScene("tutorial"), invalid), InputError);
    session.Open(*FindScene("rockslide"));
    EXPECT_EQ(session.Sim().GetEffects().Config(), edited) << "a refused configuration is not chosen";

    Session plain(kScenesDir);
    plain.Open(*FindScene("grinder"));
    const EffectsConfig grinderOwn = plain.Sim().GetEffects().Config();
    plain.OpenNeighbour(1);
    plain.OpenNeighbour(-1);
    EXPECT_EQ(plain.Sim().GetEffects().Config(), grinderOwn) << "without a choice, each scene its own";
}

TEST(TestbedSession, RestartStartsOverWithTheEffectsInForce)
{
    Opened opened("grinder");
    Session& session = opened.session;
    EffectsConfig edited = DefaultPreset();
    edited.rules[0].threshold = 5.0f;
    session.ApplyConfig(edited);
    opened.Advance(30);
    session.Restart();
    EXPECT_EQ(session.Sim().Steps(), 0u);
    EXPECT_EQ(session.Sim().GetEffects().Config(), edited);
}

TEST(TestbedMouseDrag, PullsTheGrabbedBodyAndLetsGo)
{
    Opened opened("grinder");
    Session& session = opened.session;
    Scene& scene = session.Sim().GetScene();
    const int joints = scene.world->GetJointCount();
    b2Body* bar = scene.FindBody("steel_bar")->body;
    const b2Vec2 start = bar->GetPosition();

    MouseDrag& drag = session.Drag();
    EXPECT_FALSE(drag.Grab(scene, b2Vec2(-8.0f, 8.0f))); // empty space
    EXPECT_FALSE(drag.Grab(scene, b2Vec2(0.0f, -1.0f))); // the static floor
    EXPECT_FALSE(drag.Active());
    ASSERT_TRUE(drag.Grab(scene, start));
    EXPECT_TRUE(drag.Active());
    EXPECT_EQ(scene.world->GetJointCount(), joints + 1);
    drag.MoveTo(start + b2Vec2(0.0f, 3.0f));
    opened.Advance(60);
    EXPECT_GT(bar->GetPosition().y, start.y + 1.0f);
    drag.Release();
    EXPECT_FALSE(drag.Active());
    EXPECT_EQ(scene.world->GetJointCount(), joints);
}

TEST(TestbedEffectsEditor, AppliesAValidDraftAndRefusesAnInvalidOne)
{
    Opened opened("grinder");
    Session& session = opened.session;
    EffectsEditor editor;
    editor.Follow(session);
    EXPECT_EQ(editor.draft, session.Sim().GetEffects().Config());

    editor.draft.rules[0].threshold = -2.0f;
    editor.Apply(session);
    EXPECT_TRUE(editor.messageIsError);
    ASSERT_FALSE(editor.problems.empty());
    EXPECT_EQ(editor.problems.front().path, "rules[0].threshold");
    EXPECT_EQ(session.Sim().GetEffects().Config(), DefaultPreset());

    editor.draft.rules[0].threshold = 2.0f;
    editor.Apply(session);
    EXPECT_FALSE(editor.messageIsError) << editor.message;
    EXPECT_TRUE(editor.problems.empty());
    EXPECT_EQ(session.Sim().GetEffects().Config().rules[0].threshold, 2.0f);

    editor.draft.rules[0].threshold = 9.0f;
    editor.Follow(session, true); // revert
    EXPECT_EQ(editor.draft.rules[0].threshold, 2.0f);
}

TEST(TestbedEffectsEditor, KeepsItsDraftUntilAnotherSimulationOpens)
{
    Opened opened("grinder");
    Session& session = opened.session;
    EffectsEditor editor;
    editor.Follow(session);
    editor.draft.rules[0].threshold = 9.0f; // an edit in progress
    editor.Follow(session);
    EXPECT_EQ(editor.draft.rules[0].threshold, 9.0f);
    for (const char* scene : {"skidpad", "grinder"})
    {
        session.Open(*FindScene(scene));
        editor.Follow(session);
        EXPECT_EQ(editor.draft, session.Sim().GetEffects().Config()) << scene;
        editor.draft.rules[0].threshold = 9.0f;
    }
    session.Restart();
    editor.Follow(session);
    EXPECT_EQ(editor.draft, session.Sim().GetEffects().Config());
}

TEST(TestbedEffectsEditor, SavesTheDraftAsAnEffectsConfigFile)
{
    Opened opened("grinder");
    EffectsEditor editor;
    editor.Follow(opened.session);
    editor.draft.rules[0].particleType = "smoke";
    const std::filesystem::path dir = test::ScratchDir("testbed_editor_save");
    editor.savePath = (dir / "edited.effects.json").string();
    editor.Save(opened.session);
    EXPECT_FALSE(editor.messageIsError) << editor.message;
    EXPECT_EQ(LoadEffectsFile(editor.savePath), editor.draft);

    editor.savePath = (dir / "missing" / "edited.effects.json").string();
    editor.Save(opened.session);
    EXPECT_TRUE(editor.messageIsError);
    EXPECT_NE(editor.message.find(editor.savePath), std::string::npos) << editor.message;

    editor.savePath = (dir / "invalid.effects.json").string();
    editor.draft.budget.capacity = 0;
    editor.Save(opened.session);
    EXPECT_TRUE(editor.messageIsError);
    EXPECT_FALSE(std::filesystem::exists(editor.savePath));
}

// Save as never writes over the scene on show: a trial saved its effects over its own level file (the same
// name, relative or absolute), and the level was gone.
TEST(TestbedEffectsEditor, DoesNotSaveOverTheSceneFileOnShow)
{
    const std::filesystem::path dir = test::ScratchDir("testbed_editor_save_scene");
    const std::filesystem::path level = dir / "level.json";
    std::filesystem::copy_file(kScenesDir / "grinder.json", level);
    std::filesystem::create_symlink(level, dir / "link.json");
    const std::string text = test::FileText(level);
    Opened opened("grinder");
    opened.session.OpenFile(level);
    EffectsEditor editor;
    editor.Follow(opened.session);
    for (const std::filesystem::path& name : {level, dir / "." / "level.json", dir / "link.json"})
    {
        editor.savePath = name.string();
        editor.Save(opened.session);
        EXPECT_TRUE(editor.messageIsError) << name;
        EXPECT_NE(editor.message.find("is a file the testbed's scenes are read from"), std::string::npos)
            << editor.message;
    }
    EXPECT_TRUE(test::FileText(level) == text) << "the level was replaced";
    // Nor, with another scene on show, the level still listed, nor a registered scene's files.
    opened.session.Open(*FindScene("grinder"));
    for (const std::filesystem::path& name :
         {level, kScenesDir / "grinder.json", kScenesDir / "tutorial.effects.json"})
    {
        editor.savePath = name.string();
        editor.Save(opened.session);
        EXPECT_TRUE(editor.messageIsError) << name;
    }
    EXPECT_TRUE(test::FileText(level) == text) << "the level was replaced";
    // Elsewhere it saves, and says where.
    editor.savePath = (dir / "fx.json").string();
    editor.Save(opened.session);
    EXPECT_FALSE(editor.messageIsError) << editor.message;
    EXPECT_EQ(editor.message, "saved " + std::filesystem::weakly_canonical(dir / "fx.json").string());
}

} // namespace cfx::testbed

namespace cfx::testbed
{

TEST(TestbedEvents, TheSessionLogsScrapesAndImpactsAsTheyHappen)
{
    Session session(std::filesystem::path(CONTACTFX_SOURCE_DIR) / "scenes");
    session.Open(*FindScene("tutorial"));
    session.ResetView(890, 720);
    std::size_t begun = 0;
    std::size_t impacts = 0;
    for (int frame = 0; frame < 600; ++frame)
    {
        session.Advance();
        for (const EffectEvent& event : session.Sim().GetEffects().Events())
        {
            begun += event.type == EffectEventType::scrapeBegan ? 1 : 0;
            impacts += event.type == EffectEventType::impact ? 1 : 0;
        }
    }
    ASSERT_GT(begun, 0u);
    ASSERT_GT(impacts, 0u);
    const std::deque<LoggedEvent>& log = session.Events().Entries();
    ASSERT_FALSE(log.empty());
    EXPECT_LE(log.size(), EventLog::kCapacity);
    // Newest last, times in order, each with its line of text naming the pair.
    for (std::size_t i = 1; i < log.size(); ++i)
    {
        EXPECT_LE(log[i - 1].time, log[i].time);
    }
    for (const LoggedEvent& logged : log)
    {
        // Particle hits name their particle type instead.
        EXPECT_EQ(logged.text.find('+') != std::string::npos,
                  logged.event.type != EffectEventType::particleHits)
            << logged.text;
    }
    session.Restart();
    EXPECT_TRUE(session.Events().Entries().empty()) << "a new simulation starts a new log";
}

TEST(TestbedEvents, DescribeNamesTypePairAndMeasure)
{
    EffectsConfig config = DefaultPreset();
    EffectEvent impact;
    impact.type = EffectEventType::impact;
    impact.rule = RuleId{0};
    impact.id = 7;
    impact.approachSpeed = 4.25f;
    const std::string text = DescribeEvent(impact, config, 1.5f);
    EXPECT_NE(text.find("impact"), std::string::npos) << text;
    EXPECT_NE(text.find("#7"), std::string::npos) << text;
    EXPECT_NE(text.find("concrete+steel"), std::string::npos)
        << text << ": the pair named as the events file does";
    EXPECT_NE(text.find("4.2"), std::string::npos) << text;
    EffectEvent ended;
    ended.type = EffectEventType::scrapeEnded;
    ended.end = ScrapeEnd::asleep;
    ended.rule = RuleId{1};
    EXPECT_NE(DescribeEvent(ended, config, 2.0f).find("asleep"), std::string::npos);
}

} // namespace cfx::testbed

namespace cfx::testbed
{

// A RUBE file of the user's own opens as `contactfx run FILE` runs it: no drive, the default preset, the
// whole world in view; a bad one is reported with its name and leaves the scene on show as it was.
TEST(TestbedSceneFile, OpensAUsersSceneFileAsItIsAndKeepsTheSceneOnABadOne)
{
    Opened opened("grinder");
    Session& session = opened.session;
    const std::filesystem::path file = kScenesDir / "rockslide.json";
    session.OpenFile(file);
    EXPECT_EQ(session.Entry().name, "rockslide.json");
    EXPECT_EQ(session.Entry().file, std::filesystem::absolute(file).lexically_normal().string());
    EXPECT_TRUE(session.Entry().view.wholeWorld);
    EXPECT_EQ(session.Entry().beforeStep, nullptr); // rockslide's registered action puts rocks back
    EXPECT_EQ(session.Sim().GetEffects().Config(), DefaultPreset());
    opened.Advance(5);
    EXPECT_EQ(session.Sim().Steps(), 5u);

    const std::filesystem::path dir = test::ScratchDir("testbed_scene_file");
    const std::filesystem::path bad = dir / "bad.json";
    std::FILE* handle = std::fopen(bad.c_str(), "w");
    ASSERT_NE(handle, nullptr);
    std::fputs("{\"body\": 3}", handle);
    std::fclose(handle);
    try
    {
        session.OpenFile(bad);
        ADD_FAILURE() << "a scene file whose body is not a list was opened";
    }
    catch (const InputError& error)
    {
        EXPECT_NE(std::string(error.what()).find(bad.string()), std::string::npos) << error.what();
    }
    EXPECT_EQ(session.Entry().name, "rockslide.json");
    EXPECT_EQ(session.Sim().Steps(), 5u);

    // Restart opens the file again; the chosen configuration goes with it.
    EffectsConfig tutorial = TutorialPreset();
    session.OpenFile(file, tutorial);
    opened.Advance(3);
    session.Restart();
    EXPECT_EQ(session.Entry().name, "rockslide.json");
    EXPECT_EQ(session.Sim().Steps(), 0u);
    EXPECT_EQ(session.Sim().GetEffects().Config(), tutorial);
}

// The scene file stays listed first once opened, also after leaving it (a trial could not get back to its
// level), and the brackets go through it and the registered scenes in that order.
TEST(TestbedSceneFile, StaysListedFirstAndTheBracketsGoThroughIt)
{
    Opened opened("grinder");
    Session& session = opened.session;
    const std::span<const SceneEntry> scenes = Scenes();
    EXPECT_EQ(session.Listed().size(), scenes.size());
    session.OpenFile(kScenesDir / "grinder.json");
    const SceneEntry* file = &session.Entry();
    ASSERT_EQ(session.Listed().size(), scenes.size() + 1);
    EXPECT_EQ(session.Listed().front(), file);
    session.OpenNeighbour(1);
    EXPECT_EQ(&session.Entry(), &scenes.front());
    session.OpenNeighbour(-1);
    EXPECT_EQ(&session.Entry(), file) << "back to the file";
    session.OpenNeighbour(-1);
    EXPECT_EQ(&session.Entry(), &scenes.back());
    session.OpenNeighbour(1);
    EXPECT_EQ(&session.Entry(), file) << "the list wraps around through the file";
    session.Open(scenes[1]);
    session.Open(*session.Listed().front()); // chosen in the Scenes panel
    EXPECT_EQ(&session.Entry(), file);
    EXPECT_EQ(session.Sim().Steps(), 0u);
}

// Save as keeps out of the bundled scenes' folder however the name reaches it: a trial wrote into it through
// a symbolic link followed by `..`, and through a dangling link, each time naming another file as saved.
TEST(TestbedEffectsEditor, DoesNotSaveIntoTheScenesFolderThroughLinks)
{
    const std::filesystem::path dir = test::ScratchDir("testbed_editor_save_links");
    const std::filesystem::path scenes = dir / "scenes";
    std::filesystem::create_directories(scenes / "sub");
    std::filesystem::copy_file(kScenesDir / "grinder.json", scenes / "grinder.json");
    std::filesystem::create_directory_symlink(scenes / "sub", dir / "linkToSub");
    std::filesystem::create_symlink(scenes / "new.json", dir / "dangling.json");
    Session session(scenes);
    session.Open(*FindScene("grinder"));
    EffectsEditor editor;
    editor.Follow(session);
    for (const std::filesystem::path& name : {scenes / "x.json", scenes / "sub" / "x.json",
                                              dir / "linkToSub" / ".." / "x.json", dir / "dangling.json"})
    {
        editor.savePath = name.string();
        editor.Save(session);
        EXPECT_TRUE(editor.messageIsError) << name << ": " << editor.message;
    }
    EXPECT_FALSE(std::filesystem::exists(scenes / "x.json"));
    EXPECT_FALSE(std::filesystem::exists(scenes / "sub" / "x.json"));
    EXPECT_FALSE(std::filesystem::exists(scenes / "new.json"));
    // A link to a listed level that has been deleted since: the write would bring it back as a config.
    std::filesystem::copy_file(kScenesDir / "grinder.json", dir / "level.json");
    session.OpenFile(dir / "level.json");
    session.Open(*FindScene("grinder"));
    std::filesystem::remove(dir / "level.json");
    std::filesystem::create_symlink(dir / "level.json", dir / "toLevel.json");
    editor.savePath = (dir / "toLevel.json").string();
    editor.Save(session);
    EXPECT_TRUE(editor.messageIsError) << editor.message;
    EXPECT_FALSE(std::filesystem::exists(dir / "level.json"));
    // Through a link elsewhere it saves, and names the file the link leads to.
    std::filesystem::create_directory(dir / "elsewhere");
    std::filesystem::create_symlink(dir / "elsewhere" / "fx.json", dir / "toElsewhere.json");
    editor.savePath = (dir / "toElsewhere.json").string();
    editor.Save(session);
    EXPECT_FALSE(editor.messageIsError) << editor.message;
    EXPECT_EQ(editor.message,
              "saved " + std::filesystem::weakly_canonical(dir / "elsewhere" / "fx.json").string());
    EXPECT_TRUE(std::filesystem::exists(dir / "elsewhere" / "fx.json"));
}

// A scene file deleted after it was opened does not block the brackets: they pass over it (a trial's `[`
// from the first registered scene failed every time).
TEST(TestbedSceneFile, TheBracketsPassOverAFileThatCannotBeOpened)
{
    const std::filesystem::path dir = test::ScratchDir("testbed_scene_file_deleted");
    const std::filesystem::path level = dir / "level.json";
    std::filesystem::copy_file(kScenesDir / "grinder.json", level);
    Opened opened("grinder");
    Session& session = opened.session;
    const std::span<const SceneEntry> scenes = Scenes();
    session.OpenFile(level);
    session.OpenNeighbour(1);
    ASSERT_EQ(&session.Entry(), &scenes.front());
    std::filesystem::remove(level);
    session.OpenNeighbour(-1);
    EXPECT_EQ(&session.Entry(), &scenes.back()) << "past the deleted file";
    session.OpenNeighbour(1);
    EXPECT_EQ(&session.Entry(), &scenes.front()) << "past it the other way";
    EXPECT_THROW(session.Open(*session.Listed().front()), InputError) << "chosen itself, it says why";
    EXPECT_EQ(&session.Entry(), &scenes.front());
}

// Writes the grinder's file with `gravity` misspelt and the step rate `hz`, as `level.json` in `dir`.
std::filesystem::path GrinderFileAt(const std::filesystem::path& dir, std::string_view hz)
{
    const std::filesystem::path level = dir / "level.json";
    std::string text = test::FileText(kScenesDir / "grinder.json");
    const std::size_t gravity = text.find("\"gravity\"");
    const std::size_t rate = text.find("\"stepsPerSecond\"");
    if (gravity == std::string::npos || rate == std::string::npos)
    {
        ADD_FAILURE() << "grinder.json has no gravity or stepsPerSecond";
        return level;
    }
    text.replace(gravity, 9, "\"gravty\"");
    const std::size_t rateAgain = text.find("\"stepsPerSecond\"");
    text.replace(rateAgain, text.find(',', rateAgain) - rateAgain, "\"stepsPerSecond\": " + std::string(hz));
    std::FILE* handle = std::fopen(level.c_str(), "w");
    EXPECT_NE(handle, nullptr);
    if (handle != nullptr)
    {
        std::fputs(text.c_str(), handle);
        std::fclose(handle);
    }
    return level;
}

std::string WarningsText(const Session& session)
{
    std::string all;
    for (const Diagnostic& warning : session.Warnings())
    {
        EXPECT_TRUE(warning.warning);
        all += warning.ToString() + "\n";
    }
    return all;
}

// What `contactfx run` warns of in a scene file, the testbed says too: unknown keys (a trial's level with
// "gravty" fell nowhere, silently). It steps a scene at the file's own rate (it stepped every file at 60 Hz
// and only warned), which also holds after a restart; a rate under its lowest, 1 Hz, is a warning.
TEST(TestbedSceneFile, StepsAtTheFilesRateAndWarnsOfUnknownKeys)
{
    const std::filesystem::path dir = test::ScratchDir("testbed_scene_warnings");
    Opened opened("grinder");
    EXPECT_TRUE(opened.session.Warnings().empty());
    EXPECT_EQ(opened.session.Sim().Dt(), 1.0f / 60.0f) << "the grinder's file steps at 60 Hz";
    opened.session.OpenFile(GrinderFileAt(dir, "30"));
    const std::string all = WarningsText(opened.session);
    EXPECT_NE(all.find("gravty"), std::string::npos) << all;
    EXPECT_NE(all.find("gravity"), std::string::npos) << all;
    EXPECT_EQ(all.find("stepsPerSecond"), std::string::npos) << all;
    EXPECT_EQ(opened.session.Sim().Dt(), 1.0f / 30.0f);
    opened.session.Restart();
    EXPECT_EQ(opened.session.Sim().Dt(), 1.0f / 30.0f) << "after a restart";

    opened.session.OpenFile(GrinderFileAt(dir, "0.5"));
    EXPECT_EQ(opened.session.Sim().Dt(), 1.0f);
    EXPECT_NE(WarningsText(opened.session)
                  .find("stepsPerSecond: warning: the scene steps at 0.5 Hz; the testbed steps at 1 Hz, its "
                        "lowest rate"),
              std::string::npos)
        << WarningsText(opened.session);
}

// Zooming goes the way asked, also from views far out or far in (a 40 km level fitted at 0.02 px/m zoomed
// in to 0.5 px/m when zoomed out; a 5 cm one zoomed out when zoomed in), and never jumps to a limit.
TEST(TestbedSession, ZoomGoesTheWayAskedFromAnyView)
{
    for (const int height : {1, 10000000}) // 10 m of grinder on 1 px, or on 10^7 px: 0.1 and 10^6 px/m
    {
        Opened opened("grinder");
        Session& session = opened.session;
        session.Resize(kViewWidth, height);
        const float fitted = session.Camera().pixelsPerMetre;
        const b2Vec2 middle = session.Camera().center;
        session.Zoom(kKeyZoomStep, middle); // z: out
        const float out = session.Camera().pixelsPerMetre;
        EXPECT_LT(out, fitted) << height;
        EXPECT_NEAR(out, fitted / kKeyZoomStep, 1e-3f * fitted) << height;
        session.Zoom(1.0f / kKeyZoomStep, middle); // x: in, never out
        EXPECT_GE(session.Camera().pixelsPerMetre, out) << height;
    }
}

// An effects edit keeps the material of a fixture the scene file does not name: the steel ball the testbed
// launched turned grey (no material) after the edit.
TEST(TestbedSession, AnEffectsEditKeepsTheLaunchedBallsMaterial)
{
    Opened opened("grinder");
    Session& session = opened.session;
    session.Launch();
    const b2Fixture* ball = session.Sim().GetScene().world->GetBodyList()->GetFixtureList();
    ASSERT_EQ(session.Sim().GetEffects().Material(ball), session.Sim().GetEffects().FindMaterial("steel"));
    EffectsConfig edited = session.Sim().GetEffects().Config();
    edited.materials.insert(edited.materials.begin(), "glass"); // every id moves
    session.ApplyConfig(edited);
    EXPECT_EQ(session.Sim().GetEffects().Material(ball), session.Sim().GetEffects().FindMaterial("steel"));
}

// ...but the scene's own fixtures take their materials from the new configuration, as a restart would: a
// trial's level without `material` properties kept the tutorial preset's guessed materials after an edit
// that removed the guesses, and lost them on restart.
TEST(TestbedSession, AnEffectsEditGivesTheScenesFixturesTheNewAssignments)
{
    const std::filesystem::path dir = test::ScratchDir("testbed_edit_assignments");
    const std::filesystem::path level = dir / "unnamed.json";
    std::string text = test::FileText(kScenesDir / "grinder.json");
    for (std::size_t at = text.find("\"material\""); at != std::string::npos; at = text.find("\"material\""))
    {
        text.replace(at, 10, "\"surface\"");
    }
    std::FILE* handle = std::fopen(level.c_str(), "w");
    ASSERT_NE(handle, nullptr);
    std::fputs(text.c_str(), handle);
    std::fclose(handle);
    Opened opened("grinder");
    Session& session = opened.session;
    session.OpenFile(level, TutorialPreset()); // its guesses give every fixture a material
    const auto materials = [&session]
    {
        int given = 0;
        for (const b2Body* body = session.Sim().GetScene().world->GetBodyList(); body != nullptr;
             body = body->GetNext())
        {
            for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr;
                 fixture = fixture->GetNext())
            {
                given += session.Sim().GetEffects().Material(fixture).IsValid() ? 1 : 0;
            }
        }
        return given;
    };
    ASSERT_GT(materials(), 0);
    EffectsConfig edited = TutorialPreset();
    edited.assignments.clear();
    session.ApplyConfig(edited);
    EXPECT_EQ(materials(), 0) << "as after a restart";
    session.Restart();
    EXPECT_EQ(materials(), 0);
}

} // namespace cfx::testbed
