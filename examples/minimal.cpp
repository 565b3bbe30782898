// contactfx example: the smallest complete program.
//
// A driven tyre spins on a concrete floor and makes smoke. No window: it prints what was emitted and
// exits non-zero when nothing was (CI runs it as a check). Copy the four contactfx lines into your game:
// create Effects after the world, give fixtures materials, call fx.Step(dt) after every world.Step(dt),
// draw fx.Particles().
#include <box2d/box2d.h>
#include <contactfx/effects.h>
#include <contactfx/presets.h>
#include <cstddef>
#include <cstdio>

int main()
{
    b2World world(b2Vec2(0.0f, -10.0f)); // gravity, m/s^2

    // The floor: a static box 100 m wide whose top is at y = 0.
    b2BodyDef groundDef;
    groundDef.position.Set(0.0f, -0.5f);
    b2Body* ground = world.CreateBody(&groundDef);
    b2PolygonShape groundBox;
    groundBox.SetAsBox(50.0f, 0.5f);
    b2Fixture* roadFixture = ground->CreateFixture(&groundBox, 0.0f);
    roadFixture->SetFriction(0.8f);

    // The tyre: a disc of radius 0.4 m resting on the floor.
    b2BodyDef wheelDef;
    wheelDef.type = b2_dynamicBody;
    wheelDef.position.Set(0.0f, 0.4f);
    b2Body* wheel = world.CreateBody(&wheelDef);
    b2CircleShape tyreShape;
    tyreShape.m_radius = 0.4f;
    b2FixtureDef tyreDef;
    tyreDef.shape = &tyreShape;
    tyreDef.density = 1.5f; // kg/m^2
    tyreDef.friction = 0.9f;
    b2Fixture* tyreFixture = wheel->CreateFixture(&tyreDef);

    // contactfx: one Effects per world, created after it and destroyed before it.
    cfx::Effects fx(world, cfx::EffectsDef{cfx::DefaultPreset()});
    fx.SetMaterial(tyreFixture, "rubber");
    fx.SetMaterial(roadFixture, "concrete");

    const float dt = 1.0f / 60.0f;    // s
    const float engineSpeed = -40.0f; // rad/s, clockwise: the tyre's surface moves at 16 m/s
    for (int step = 0; step < 120; ++step)
    {
        wheel->SetAngularVelocity(engineSpeed); // an engine strong enough to hold the tyre spinning
        world.Step(dt, 8, 3);
        fx.Step(dt); // same dt, right after the world step
        // A game would draw fx.Particles() here (see sdl2_car.cpp).
    }

    const cfx::EffectsStats& stats = fx.Stats();
    unsigned long long emitted = 0;
    for (std::size_t type = 0; type < stats.spawnedByType.size(); ++type)
    {
        std::printf("%-8s %llu emitted\n", fx.Config().particleTypes[type].name.c_str(),
                    static_cast<unsigned long long>(stats.spawnedByType[type]));
        emitted += stats.spawnedByType[type];
    }
    std::printf("%llu particles emitted in %llu steps, %u alive at the end\n", emitted,
                static_cast<unsigned long long>(stats.steps), stats.live);
    return emitted > 0 ? 0 : 1;
}
