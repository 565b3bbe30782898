// The README's snippet in a complete program, built against an installed contactfx. Exits 0 only when
// particles were emitted and the headers' version is the one CMake found.
#include <box2d/box2d.h>
#include <contactfx/effects.h>
#include <contactfx/presets.h>
#include <contactfx/version.h>
#include <cstdio>
#include <cstring>

int main(int argc, char** argv)
{
    b2World world(b2Vec2(0.0f, -10.0f));
    b2BodyDef roadDef;
    b2Body* road = world.CreateBody(&roadDef);
    b2PolygonShape roadShape;
    roadShape.SetAsBox(50.0f, 0.5f, b2Vec2(0.0f, -0.5f), 0.0f);
    b2Fixture* roadFixture = road->CreateFixture(&roadShape, 0.0f);
    b2BodyDef tyreDef;
    tyreDef.type = b2_dynamicBody;
    tyreDef.position.Set(0.0f, 0.4f);
    b2Body* tyre = world.CreateBody(&tyreDef);
    b2CircleShape tyreShape;
    tyreShape.m_radius = 0.4f;
    b2Fixture* tyreFixture = tyre->CreateFixture(&tyreShape, 1.0f);

    cfx::Effects fx(world, cfx::EffectsDef{cfx::DefaultPreset()});
    fx.SetMaterial(tyreFixture, fx.FindMaterial("rubber"));
    fx.SetMaterial(roadFixture, fx.FindMaterial("concrete"));
    const float dt = 1.0f / 60.0f;
    for (int step = 0; step < 120; ++step)
    {
        tyre->SetAngularVelocity(-40.0f); // wheelspin
        world.Step(dt, 8, 3);
        fx.Step(dt);
    }
    unsigned long long emitted = 0;
    for (unsigned long long count : fx.Stats().spawnedByType)
    {
        emitted += count;
    }
    std::printf("contactfx %s: %llu particles emitted, %u alive\n", cfx::kVersion, emitted,
                fx.Particles().count);
    if (argc > 1 && std::strcmp(argv[1], cfx::kVersion) != 0)
    {
        std::printf("expected version %s\n", argv[1]);
        return 1;
    }
    return emitted > 0 ? 0 : 1;
}
