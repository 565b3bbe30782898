// Effects::IsParticleBody: the application's listeners hear of the tutorial preset's particle bodies and
// must be able to tell them apart.
#include "test_world.h"

#include <algorithm>
#include <box2d/b2_contact.h>
#include <gtest/gtest.h>

namespace cfx::test
{

// With the tutorial preset every particle is a Box2D body: the application's contact and destruction
// listeners hear of them, and IsParticleBody names them, and only them, in either (a re-check found it false
// for the fixtures of a particle body the system was destroying).
TEST(ParticleBodies, TheApplicationCanTellThemApartInItsListeners)
{
    // Asked at the callback: a particle body may be gone (its particle died) by the end of the step.
    class Bodies final : public b2ContactListener, public b2DestructionListener
    {
    public:
        void BeginContact(b2Contact* contact) override
        {
            Note(contact->GetFixtureA()->GetBody());
            Note(contact->GetFixtureB()->GetBody());
        }
        void EndContact(b2Contact* contact) override
        {
            Note(contact->GetFixtureA()->GetBody());
            Note(contact->GetFixtureB()->GetBody());
        }
        void SayGoodbye(b2Fixture* fixture) override
        {
            goodbyes += effects->IsParticleBody(fixture->GetBody()) ? 1 : 0;
            Note(fixture->GetBody());
        }
        void SayGoodbye(b2Joint*) override {}
        void Note(const b2Body* body)
        {
            const bool own = std::find(ownBodies.begin(), ownBodies.end(), body) != ownBodies.end();
            const bool particle = effects->IsParticleBody(body);
            (own ? ownCalledParticle : particle ? particleBodies : unknown) += (own && !particle) ? 0 : 1;
        }
        const Effects* effects = nullptr;
        std::vector<const b2Body*> ownBodies;
        int particleBodies = 0, ownCalledParticle = 0, unknown = 0, goodbyes = 0;
    } listener;
    TestWorld scene;
    b2Body* ground = scene.CreateGround(0.8f);
    b2Body* block = scene.CreateBox(b2Vec2(0.0f, 0.25f), 0.5f, 0.25f, 0.5f);
    block->SetLinearVelocity(b2Vec2(12.0f, 0.0f));
    listener.ownBodies = {ground, block};
    EffectsDef def;
    def.config = TutorialPreset();
    def.contactListener = &listener;
    def.destructionListener = &listener;
    scene.effects = std::make_unique<Effects>(*scene.world, def);
    listener.effects = scene.effects.get();
    scene.effects->SetMaterial(ground, scene.Material("concrete"));
    scene.effects->SetMaterial(block, scene.Material("steel"));
    for (int i = 0; i < 120; ++i) // sparks live under a second: many particle bodies die
    {
        scene.Step();
    }
    ASSERT_GT(scene.Spawned("sparks"), 10u);
    EXPECT_GT(listener.particleBodies, 0) << "the listeners heard of particle bodies";
    EXPECT_GT(listener.goodbyes, 0) << "and of the fixtures of the particle bodies the system destroyed";
    EXPECT_EQ(listener.unknown, 0) << "bodies neither the application's nor particles'";
    EXPECT_EQ(listener.ownCalledParticle, 0);
    EXPECT_FALSE(scene.effects->IsParticleBody(nullptr));
}

} // namespace cfx::test
