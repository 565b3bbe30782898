// Effects::IsParticleBody: the application's listeners hear of the tutorial preset's particle bodies and
// must be able to tell them apart.
#include "contact_tracker.h"
#include "effects_access.h"
#include "test_world.h"

#include <algorithm>
#include <box2d/b2_contact.h>
#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

// A steel block sliding at 12 m/s on concrete, sparking with the tutorial preset (a Box2D body a particle),
// `goodbyes` given as the application's destruction listener.
Effects& AttachToASlidingBlock(TestWorld& scene, b2DestructionListener& goodbyes)
{
    b2Body* ground = scene.CreateGround(0.8f);
    b2Body* block = scene.CreateBox(b2Vec2(0.0f, 0.25f), 0.5f, 0.25f, 0.5f);
    block->SetLinearVelocity(b2Vec2(12.0f, 0.0f));
    EffectsDef def;
    def.config = TutorialPreset();
    def.destructionListener = &goodbyes;
    scene.effects = std::make_unique<Effects>(*scene.world, def);
    scene.effects->SetMaterial(ground, scene.Material("concrete"));
    scene.effects->SetMaterial(block, scene.Material("steel"));
    return *scene.effects;
}

} // namespace

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

// A trial gave the tutorial preset's particle bodies a material (sparks that make effects of their own).
// Once the pool is full, every spawn recycles the oldest particle; destroying its body ended contacts the
// tracker was still handing to the emission, which then read a destroyed b2Contact (ASan). The bodies the
// emission recycles are now destroyed after it, once the tracker has ended its step.
TEST(ParticleBodies, OnesTheEmissionRecyclesAreDestroyedAfterIt)
{
    class Goodbyes final : public b2DestructionListener
    {
    public:
        void SayGoodbye(b2Fixture* fixture) override
        {
            if (!stepping || !effects->IsParticleBody(fixture->GetBody()))
            {
                return;
            }
            // The emission runs between the tracker's Prune and its EndStep, which moves its step on.
            const bool emitting = detail::EffectsAccess::Tracker(*effects).Step() == stepBefore;
            (emitting ? duringEmission : afterEmission) += 1;
        }
        void SayGoodbye(b2Joint*) override {}
        const Effects* effects = nullptr;
        bool stepping = false;
        std::uint64_t stepBefore = 0;
        int duringEmission = 0, afterEmission = 0;
    } goodbyes;
    TestWorld scene;
    b2Body* ground = scene.CreateGround(0.8f);
    b2Body* block = scene.CreateBox(b2Vec2(0.0f, 0.25f), 0.5f, 0.25f, 0.5f);
    EffectsDef def;
    def.config = TutorialPreset();
    def.config.budget.capacity = 20;
    def.destructionListener = &goodbyes;
    scene.effects = std::make_unique<Effects>(*scene.world, def);
    goodbyes.effects = scene.effects.get();
    const MaterialId steel = scene.Material("steel");
    scene.effects->SetMaterial(ground, scene.Material("concrete"));
    scene.effects->SetMaterial(block, steel);
    for (int i = 0; i < 120; ++i)
    {
        block->SetLinearVelocity(b2Vec2(i % 60 < 30 ? 12.0f : -12.0f, 0.0f));
        scene.world->Step(1.0f / 60.0f, 8, 3);
        goodbyes.stepBefore = detail::EffectsAccess::Tracker(*scene.effects).Step();
        goodbyes.stepping = true;
        scene.effects->Step(1.0f / 60.0f);
        goodbyes.stepping = false;
        for (b2Body* body = scene.world->GetBodyList(); body != nullptr; body = body->GetNext())
        {
            if (scene.effects->IsParticleBody(body))
            {
                scene.effects->SetMaterial(body, steel); // sparks are steel: their contacts are tracked
            }
        }
    }
    ASSERT_GT(scene.effects->Stats().recycled, 100u) << "the pool was full, and spawns recycled";
    EXPECT_GT(goodbyes.afterEmission, 100) << "recycled bodies are destroyed within Effects::Step";
    EXPECT_EQ(goodbyes.duringEmission, 0) << "none while the emission reads the contacts";
}

// A trial destroyed particle bodies itself: its own destruction listener then heard them as no particle's,
// because Effects forgot them before passing the goodbye on.
TEST(ParticleBodies, TheApplicationHearsTheOnesItDestroysAsParticleBodies)
{
    class Goodbyes final : public b2DestructionListener
    {
    public:
        void SayGoodbye(b2Fixture* fixture) override
        {
            (effects->IsParticleBody(fixture->GetBody()) ? particle : other) += 1;
        }
        void SayGoodbye(b2Joint*) override {}
        const Effects* effects = nullptr;
        int particle = 0, other = 0;
    } goodbyes;
    TestWorld scene;
    goodbyes.effects = &AttachToASlidingBlock(scene, goodbyes);
    for (int i = 0; i < 10; ++i)
    {
        scene.Step();
    }
    std::vector<b2Body*> particleBodies;
    for (b2Body* body = scene.world->GetBodyList(); body != nullptr; body = body->GetNext())
    {
        if (scene.effects->IsParticleBody(body))
        {
            particleBodies.push_back(body);
        }
    }
    ASSERT_GE(particleBodies.size(), 3u);
    for (b2Body* body : particleBodies)
    {
        scene.world->DestroyBody(body);
    }
    EXPECT_EQ(goodbyes.particle, static_cast<int>(particleBodies.size()));
    EXPECT_EQ(goodbyes.other, 0);
    for (const b2Body* body : particleBodies)
    {
        EXPECT_FALSE(scene.effects->IsParticleBody(body)) << "forgotten once destroyed";
    }
    scene.Step(); // and the particles whose bodies went leave the pool cleanly
}

// Destroying Effects destroys its particles' bodies, and the application's destruction listener hears of
// their fixtures: a trial's listener called ForgetFixture and Material from there, after the Effects had
// freed what they read (a crash, and a heap-use-after-free under ASan). The bodies now go first, while the
// Effects is whole, their goodbyes forwarded as in a step; a Step called from there does nothing.
TEST(ParticleBodies, TheApplicationsListenerMayCallIntoTheEffectsWhileItsDestructorDestroysThem)
{
    class Goodbyes final : public b2DestructionListener
    {
    public:
        void SayGoodbye(b2Fixture* fixture) override
        {
            particles += effects->IsParticleBody(fixture->GetBody()) ? 1 : 0;
            unmaterialled += effects->Material(fixture).IsValid() ? 0 : 1;
            effects->ForgetFixture(fixture);
            if (destroying)
            {
                // A step from here does nothing (it read the particles being destroyed: a re-check's
                // crash).
                effects->Step(1.0f / 60.0f);
            }
        }
        void SayGoodbye(b2Joint*) override {}
        Effects* effects = nullptr;
        bool destroying = false;
        int particles = 0, unmaterialled = 0;
    } goodbyes;
    TestWorld scene;
    goodbyes.effects = &AttachToASlidingBlock(scene, goodbyes);
    for (int i = 0; i < 20; ++i)
    {
        scene.Step();
    }
    const std::uint32_t live = scene.effects->Particles().count;
    ASSERT_GT(live, 5u);
    goodbyes.particles = 0;
    goodbyes.unmaterialled = 0;
    goodbyes.destroying = true;
    scene.effects.reset();
    EXPECT_EQ(goodbyes.particles, static_cast<int>(live))
        << "one fixture a particle body, each still a particle's";
    EXPECT_EQ(goodbyes.unmaterialled, static_cast<int>(live));
    EXPECT_EQ(scene.world->GetBodyCount(), 2) << "only the ground and the block are left";
}

} // namespace cfx::test
