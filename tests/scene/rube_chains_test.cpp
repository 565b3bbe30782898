// RUBE scenes are Box2D 2.3 scenes: chains (and edges with ghost vertices) collide on both sides there,
// whatever their winding. Box2D 2.4 makes them one-sided, so the loader gives each such fixture a back side
// (the same shape reversed): bodies and particles then rest on a chain from either side, the pair saves as
// the file's one fixture, and lookups find the entry from either fixture.
#include "contactfx/effects.h"
#include "contactfx/particle_system.h"
#include "contactfx/presets.h"
#include "contactfx/scene/scene_materials.h"
#include "scene/rube_test_util.h"

#include <gtest/gtest.h>

namespace cfx
{
namespace
{

using test::World;

// A static ground from x = -5 to 5 at y = 0, as a chain or a ghosted edge, drawn in `winding` (+1: left to
// right, whose Box2D 2.4 front is below it; -1: right to left, front above), and a unit box at (0, y).
std::string Ground(const std::string& kind, int winding, float boxY)
{
    const std::string x = winding > 0 ? "[-5, 0, 5]" : "[5, 0, -5]";
    std::string shape;
    if (kind == "chain")
    {
        shape = R"({"friction": 0.5, "chain": {"vertices": {"x": )" + x + R"(, "y": [0, 0, 0]}}})";
    }
    else
    {
        const float s = static_cast<float>(winding);
        shape = R"({"friction": 0.5, "edge": {"vertex1": {"x": )" + std::to_string(-5 * s) +
                R"(, "y": 0}, "vertex2": {"x": )" + std::to_string(5 * s) +
                R"(, "y": 0}, "hasVertex0": true, "hasVertex3": true, "vertex0": {"x": )" +
                std::to_string(-6 * s) + R"(, "y": 0}, "vertex3": {"x": )" + std::to_string(6 * s) +
                R"(, "y": 0}}})";
    }
    const std::string ground = R"({"type": 0, "fixture": [)" + shape + "]}";
    const std::string box = R"({"type": 2, "position": {"x": 0, "y": )" + std::to_string(boxY) +
                            R"(}, "awake": true, "fixture": [{"density": 1, "friction": 0.5,
              "polygon": {"vertices": {"x": [0.5, 0.5, -0.5, -0.5], "y": [-0.5, 0.5, 0.5, -0.5]}}}]})";
    return World(ground + ", " + box);
}

TEST(RubeChains, ABoxRestsOnAChainOrGhostedEdgeFromAboveWhateverItsWinding)
{
    for (const std::string kind : {"chain", "edge"})
    {
        for (const int winding : {1, -1})
        {
            Scene scene = LoadRubeString(Ground(kind, winding, 2.0f), "ground.json");
            b2Body* box = scene.bodies.at(1).body;
            for (int step = 0; step < 120; ++step)
            {
                scene.world->Step(1.0f / 60.0f, 8, 3);
            }
            // Resting on the ground: its centre half a metre up (Box2D's skins and slop within 2 cm).
            EXPECT_NEAR(box->GetPosition().y, 0.5f, 0.02f) << kind << ", winding " << winding;
        }
    }
}

TEST(RubeChains, ABoxThrownUpFromBelowStopsAtTheChain)
{
    for (const int winding : {1, -1})
    {
        Scene scene = LoadRubeString(Ground("chain", winding, -2.0f), "ground.json");
        b2Body* box = scene.bodies.at(1).body;
        box->SetLinearVelocity(b2Vec2(0.0f, 12.0f)); // would rise to y = 5.2 through nothing
        float highest = box->GetPosition().y;
        for (int step = 0; step < 60; ++step)
        {
            scene.world->Step(1.0f / 60.0f, 8, 3);
            highest = std::max(highest, box->GetPosition().y);
        }
        EXPECT_LT(highest, -0.45f) << "winding " << winding;
    }
}

TEST(RubeChains, TheBackSideIsTheSameShapeReversedAndSavesAsTheOneFixtureOfTheFile)
{
    Scene scene = LoadRubeString(World(R"({"type": 0, "fixture": [
        {"name": "open", "friction": 0.4, "restitution": 0.1, "filter-categoryBits": 2,
         "chain": {"vertices": {"x": [0, 1, 2], "y": [0, 0, 1]}, "hasPrevVertex": true, "hasNextVertex": true,
                   "prevVertex": {"x": -1, "y": 1}, "nextVertex": {"x": 3, "y": 3}}},
        {"name": "loop", "chain": {"vertices": {"x": [0, 1, 1, 0, 0], "y": [0, 0, 1, 1, 0]}}},
        {"name": "ghosted", "edge": {"vertex1": {"x": 0, "y": 0}, "vertex2": {"x": 1, "y": 0},
         "hasVertex0": true, "hasVertex3": true, "vertex0": {"x": -1, "y": 0.5}, "vertex3": {"x": 2, "y": -0.5}}},
        {"name": "plain", "edge": {"vertex1": {"x": 0, "y": 0}, "vertex2": {"x": 1, "y": 0}}},
        {"name": "box", "polygon": {"vertices": {"x": [1, 1, -1, -1], "y": [-1, 1, 1, -1]}}}]})"),
                                 "shapes.json");
    ASSERT_EQ(scene.fixtures.size(), 5u);
    int fixturesInWorld = 0;
    for (const b2Fixture* f = scene.bodies.at(0).body->GetFixtureList(); f != nullptr; f = f->GetNext())
    {
        ++fixturesInWorld;
    }
    EXPECT_EQ(fixturesInWorld, 8); // three one-sided shapes with their back sides, two shapes without

    const SceneFixture& open = scene.fixtures[0];
    ASSERT_NE(open.backSide, nullptr);
    const auto& front = static_cast<const b2ChainShape&>(*open.fixture->GetShape());
    const auto& back = static_cast<const b2ChainShape&>(*open.backSide->GetShape());
    ASSERT_EQ(back.m_count, front.m_count);
    for (int i = 0; i < front.m_count; ++i)
    {
        EXPECT_EQ(back.m_vertices[i], front.m_vertices[front.m_count - 1 - i]) << i;
    }
    EXPECT_EQ(back.m_prevVertex, front.m_nextVertex);
    EXPECT_EQ(back.m_nextVertex, front.m_prevVertex);
    EXPECT_EQ(open.backSide->GetFriction(), 0.4f);
    EXPECT_EQ(open.backSide->GetRestitution(), 0.1f);
    EXPECT_EQ(open.backSide->GetFilterData().categoryBits, 2);
    EXPECT_EQ(scene.FindFixture(open.backSide), &open);

    const auto& loop = static_cast<const b2ChainShape&>(*scene.fixtures[1].backSide->GetShape());
    EXPECT_EQ(loop.m_count, 5); // CreateLoop closes it
    const auto& ghosted = static_cast<const b2EdgeShape&>(*scene.fixtures[2].backSide->GetShape());
    EXPECT_TRUE(ghosted.m_oneSided);
    EXPECT_EQ(ghosted.m_vertex0, b2Vec2(2.0f, -0.5f));
    EXPECT_EQ(ghosted.m_vertex1, b2Vec2(1.0f, 0.0f));
    EXPECT_EQ(ghosted.m_vertex2, b2Vec2(0.0f, 0.0f));
    EXPECT_EQ(ghosted.m_vertex3, b2Vec2(-1.0f, 0.5f));
    EXPECT_EQ(scene.fixtures[3].backSide, nullptr); // a plain edge is two-sided already
    EXPECT_EQ(scene.fixtures[4].backSide, nullptr);

    // Saved and loaded again: the same five fixtures, each one-sided shape with its back side again.
    const std::string saved = SaveRubeString(scene);
    const nlohmann::json json = nlohmann::json::parse(saved);
    EXPECT_EQ(json["body"][0]["fixture"].size(), 5u);
    const Scene again = LoadRubeString(saved, "saved.json");
    ASSERT_EQ(again.fixtures.size(), 5u);
    EXPECT_NE(again.fixtures[0].backSide, nullptr);
    EXPECT_EQ(SaveRubeString(again), saved);
}

TEST(RubeChains, PoolParticlesRestOnAChainFromAboveWhateverItsWinding)
{
    for (const int winding : {1, -1})
    {
        Scene scene = LoadRubeString(Ground("chain", winding, 50.0f), "ground.json");
        ParticleTypeDef type;
        type.name = "grit";
        type.radius = 0.05f;
        type.restitution = 0.0f;
        const std::vector<ParticleTypeDef> types{type};
        ParticleSystem particles(*scene.world, types, ParticleBudget{64, RecyclePolicy::oldest});
        for (int i = 0; i < 32; ++i)
        {
            particles.Spawn(ParticleSpawn{b2Vec2(-4.0f + 0.25f * static_cast<float>(i), 1.0f),
                                          b2Vec2(0.0f, -20.0f), 1.0f, ParticleTypeId{0}});
        }
        for (int step = 0; step < 30; ++step)
        {
            scene.world->Step(1.0f / 60.0f, 8, 3);
            particles.Step(1.0f / 60.0f, scene.world->GetGravity());
        }
        const ParticleView view = particles.View();
        ASSERT_EQ(particles.Count(), 32u);
        for (std::uint32_t i = 0; i < particles.Count(); ++i)
        {
            EXPECT_NEAR(view.positionY[view.Slot(i)], 0.05f, 1e-3f)
                << "winding " << winding << ", particle " << i;
        }
    }
}

// A steel block sliding at 14 m/s on concrete, the ground a box or a chain of 2 m segments drawn either
// way: the chain's pair of opposite fixtures makes the same sparks as the box (only the side the block is
// on touches it), and none starts inside, ends a step inside or crosses the chain.
TEST(RubeChains, ABlockSlidingOnAChainOfEitherWindingMakesTheSameSparksAsOnABox)
{
    auto run = [](const std::string& ground)
    {
        const std::string json = World(R"({"type": 0, "fixture": [{"friction": 0.5, "customProperties":
            [{"name": "material", "string": "concrete"}], )" +
                                       ground + R"(}]},
            {"type": 2, "position": {"x": -15, "y": 0.25}, "linearVelocity": {"x": 14, "y": 0}, "awake": true,
             "fixture": [{"density": 8, "friction": 0.3, "customProperties": [{"name": "material", "string": "steel"}],
             "polygon": {"vertices": {"x": [0.5, 0.5, -0.5, -0.5], "y": [-0.25, 0.25, 0.25, -0.25]}}}]})");
        Scene scene = LoadRubeString(json, "slide.json");
        EffectsDef def;
        def.config = DefaultPreset();
        def.particles.checkParticles = true;
        Effects effects(*scene.world, def);
        AssignSceneMaterials(scene, effects, "slide.json");
        for (int step = 0; step < 180; ++step)
        {
            scene.world->Step(1.0f / 60.0f, 8, 3);
            effects.Step(1.0f / 60.0f);
        }
        return effects.Stats();
    };
    auto spawned = [](const EffectsStats& stats)
    {
        std::uint64_t all = 0;
        for (const std::uint64_t n : stats.spawnedByType)
        {
            all += n;
        }
        return static_cast<double>(all);
    };
    std::string forward = R"("chain": {"vertices": {"x": [)";
    std::string backward = forward;
    for (int i = 0; i <= 20; ++i)
    {
        forward += std::to_string(-20 + 2 * i) + (i < 20 ? ", " : "");
        backward += std::to_string(20 - 2 * i) + (i < 20 ? ", " : "");
    }
    const std::string zeros = R"(], "y": [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]}})";
    const EffectsStats box =
        run(R"("polygon": {"vertices": {"x": [20, 20, -20, -20], "y": [-1, 0, 0, -1]}})");
    ASSERT_GT(spawned(box), 500.0);
    for (const std::string& chain : {forward + zeros, backward + zeros})
    {
        const EffectsStats stats = run(chain);
        EXPECT_NEAR(spawned(stats), spawned(box), 0.1 * spawned(box));
        EXPECT_EQ(stats.spawnedInsideSolid, 0u);
        EXPECT_EQ(stats.particleStepsInside, 0u);
        EXPECT_EQ(stats.crossings, 0u);
    }
}

// RUBE's own car sample: its ground is a chain whose Box2D 2.4 front faces down. The car must drive on it,
// not fall through.
TEST(RubeChains, TheCarSampleStaysOnItsGround)
{
    CONTACTFX_REQUIRE_RUBE_SAMPLES();
    Scene car = LoadRubeFile(test::RubeSamplesDir() / "car.json");
    float lowestGround = b2_maxFloat;
    for (const SceneFixture& fixture : car.fixtures)
    {
        if (fixture.fixture->GetBody()->GetType() != b2_staticBody)
        {
            continue;
        }
        for (int child = 0; child < fixture.fixture->GetShape()->GetChildCount(); ++child)
        {
            lowestGround = std::min(lowestGround, fixture.fixture->GetAABB(child).lowerBound.y);
        }
    }
    ASSERT_LT(lowestGround, b2_maxFloat);
    for (int step = 0; step < 180; ++step)
    {
        car.world->Step(1.0f / 60.0f, 8, 3);
    }
    for (const SceneBody& body : car.bodies)
    {
        if (body.body->GetType() == b2_dynamicBody)
        {
            EXPECT_GT(body.body->GetPosition().y, lowestGround) << body.name;
        }
    }
}

} // namespace
} // namespace cfx
