// Effects::SetMaterial on a fixture whose contact goes on touching: the new material takes effect at the
// next world step, as for a contact that begins later (a user's trial found the old rule kept for as long
// as the contact lasted, while adding a material took effect at once).
#include "test_world.h"

#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

// A steel block held against a static wall (no material) while a kinematic concrete slab runs under it at
// 8 m/s: it grinds for as long as the test runs.
struct Grinder : TestWorld
{
    Grinder()
    {
        slab = CreateBox(b2Vec2(0.0f, -0.5f), 60.0f, 0.5f, 0.8f, b2_kinematicBody);
        slab->SetLinearVelocity(b2Vec2(8.0f, 0.0f));
        block = CreateBox(b2Vec2(0.0f, 0.25f), 0.5f, 0.25f, 0.5f);
        CreateBox(b2Vec2(1.0f, 0.75f), 0.5f, 0.5f, 0.0f, b2_staticBody); // the wall holding the block
        Attach();
        effects->SetMaterial(slab, Material("concrete"));
        effects->SetMaterial(block, Material("steel"));
    }

    // Steps `steps` times; returns the events of all of them.
    std::vector<EffectEvent> Run(int steps)
    {
        std::vector<EffectEvent> events;
        for (int i = 0; i < steps; ++i)
        {
            Step();
            if (slab->GetPosition().x > 20.0f)
            {
                slab->SetTransform(b2Vec2(0.0f, -0.5f), 0.0f); // keep the slab under the block
            }
            events.insert(events.end(), effects->Events().begin(), effects->Events().end());
        }
        return events;
    }

    std::vector<const EffectEvent*> Scrapes(const std::vector<EffectEvent>& events,
                                            EffectEventType type) const
    {
        std::vector<const EffectEvent*> found;
        for (const EffectEvent& event : events)
        {
            if (event.type == type)
            {
                found.push_back(&event);
            }
        }
        return found;
    }

    b2Body* slab = nullptr;
    b2Body* block = nullptr;
};

} // namespace

TEST(MaterialChange, AnotherMaterialOnATouchingFixtureSwitchesItsRuleAtTheNextStep)
{
    Grinder scene;
    const std::vector<EffectEvent> steel = scene.Run(60);
    ASSERT_EQ(scene.Scrapes(steel, EffectEventType::scrapeBegan).size(), 1u);
    const std::uint64_t sparks = scene.Spawned("sparks");
    EXPECT_GT(sparks, 100u);
    EXPECT_EQ(scene.Spawned("smoke"), 0u);

    scene.effects->SetMaterial(scene.block, scene.Material("rubber"));
    EXPECT_EQ(scene.effects->Material(scene.block->GetFixtureList()), scene.Material("rubber"));
    const std::vector<EffectEvent> rubber = scene.Run(60);
    EXPECT_EQ(scene.Spawned("sparks"), sparks);
    EXPECT_GT(scene.Spawned("smoke"), 10u);
    const auto ended = scene.Scrapes(rubber, EffectEventType::scrapeEnded);
    ASSERT_EQ(ended.size(), 1u);
    EXPECT_EQ(ended[0]->end, ScrapeEnd::materialChanged);
    EXPECT_EQ(ended[0]->id, scene.Scrapes(steel, EffectEventType::scrapeBegan)[0]->id);
    EXPECT_EQ(ended[0]->step, 60u); // reported by the first step after the change
    const auto began = scene.Scrapes(rubber, EffectEventType::scrapeBegan);
    ASSERT_EQ(began.size(), 1u);
    const MaterialId rubberId = scene.Material("rubber");
    EXPECT_TRUE(began[0]->materialA == rubberId || began[0]->materialB == rubberId);
}

TEST(MaterialChange, RemovingTheMaterialEndsTheScrapeAndTheEmission)
{
    Grinder scene;
    scene.Run(60);
    const std::uint64_t sparks = scene.Spawned("sparks");
    ASSERT_GT(sparks, 100u);
    scene.effects->SetMaterial(scene.block, MaterialId{});
    const std::vector<EffectEvent> after = scene.Run(60);
    EXPECT_EQ(scene.Spawned("sparks"), sparks);
    const auto ended = scene.Scrapes(after, EffectEventType::scrapeEnded);
    ASSERT_EQ(ended.size(), 1u);
    EXPECT_EQ(ended[0]->end, ScrapeEnd::materialChanged);
    EXPECT_TRUE(scene.Scrapes(after, EffectEventType::scrapeBegan).empty());
}

TEST(MaterialChange, TheSameMaterialAgainChangesNothing)
{
    Grinder scene;
    scene.Run(30);
    scene.effects->SetMaterial(scene.block, scene.Material("steel"));
    const std::vector<EffectEvent> after = scene.Run(30);
    EXPECT_TRUE(scene.Scrapes(after, EffectEventType::scrapeEnded).empty());
    EXPECT_TRUE(scene.Scrapes(after, EffectEventType::scrapeBegan).empty());
}

// A game that pauses its world but keeps stepping the effects (to let the particles settle) sprayed sparks
// from the frozen scrape, from the contacts the last world step left.
TEST(PausedWorld, StepsWithoutAWorldStepMoveTheParticlesButEmitNothing)
{
    Grinder scene;
    scene.Run(30);
    const std::uint64_t sparks = scene.Spawned("sparks");
    ASSERT_GT(sparks, 50u);
    const ParticleView before = scene.effects->Particles();
    const b2Vec2 first(before.positionX[before.Slot(0)], before.positionY[before.Slot(0)]);
    for (int i = 0; i < 20; ++i)
    {
        scene.effects->Step(1.0f / 60.0f);
        for (const EffectEvent& event : scene.effects->Events())
        {
            EXPECT_EQ(event.type, EffectEventType::particleHits) << "no scrape changes while paused";
        }
    }
    EXPECT_EQ(scene.Spawned("sparks"), sparks);
    const ParticleView after = scene.effects->Particles();
    ASSERT_GT(after.count, 0u);
    EXPECT_NE(b2Vec2(after.positionX[after.Slot(0)], after.positionY[after.Slot(0)]), first);
    scene.Run(10); // the world steps again: so does the grinding
    EXPECT_GT(scene.Spawned("sparks"), sparks);
}

} // namespace cfx::test
