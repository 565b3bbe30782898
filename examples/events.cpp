// contactfx example: effect events as sound hooks.
//
// A steel crate is thrown onto a concrete floor: it lands (an impact), slides to a stop (a scrape that
// begins, changes every step and ends), and is kicked back once. After every step the game reads
// fx.Events() and calls its sound engine: a one-shot per impact, a looping sound per scrape that follows
// the scrape's id from began to ended. No window; exits non-zero when the expected events did not come
// or a loop was left playing. (An EffectEventListener given in EffectsDef gets the same events as
// callbacks at the end of fx.Step, if a game prefers that.)
#include <algorithm>
#include <box2d/box2d.h>
#include <contactfx/effects.h>
#include <contactfx/events.h>
#include <contactfx/presets.h>
#include <cstdint>
#include <cstdio>
#include <string>
#include <unordered_map>
#include <vector>

namespace
{

// Stand-ins for a game's sound engine: they print what a real one would do. A real engine returns a
// voice handle for a loop; here it is a counter.
using Voice = int;

void PlayOneShot(const std::string& sound, float volume, b2Vec2 where)
{
    std::printf("    PlayOneShot(%s, volume %.2f, at %.2f %.2f)\n", sound.c_str(), volume, where.x, where.y);
}

Voice StartLoop(const std::string& sound, float volume, float pitch)
{
    static Voice next = 1;
    std::printf("    StartLoop(%s, volume %.2f, pitch %.2f) -> voice %d\n", sound.c_str(), volume, pitch,
                next);
    return next++;
}

void UpdateLoop(Voice voice, float volume, float pitch, bool print)
{
    if (print) // a real engine is told every step; printing every one would drown the output
    {
        std::printf("    UpdateLoop(voice %d, volume %.2f, pitch %.2f)\n", voice, volume, pitch);
    }
}

void StopLoop(Voice voice)
{
    std::printf("    StopLoop(voice %d)\n", voice);
}

const char* EndReason(cfx::ScrapeEnd end)
{
    switch (end)
    {
    case cfx::ScrapeEnd::contactEnded:
        return "contact ended";
    case cfx::ScrapeEnd::asleep:
        return "asleep";
    case cfx::ScrapeEnd::belowThreshold:
        return "below threshold";
    case cfx::ScrapeEnd::destroyed:
        return "destroyed";
    case cfx::ScrapeEnd::stopped:
        return "stopped";
    case cfx::ScrapeEnd::materialChanged:
        return "material changed";
    case cfx::ScrapeEnd::none:
        break;
    }
    return "none";
}

} // namespace

int main()
{
    b2World world(b2Vec2(0.0f, -10.0f)); // gravity, m/s^2

    // Concrete floor: a static box 80 m wide whose top is at y = 0.
    b2BodyDef floorDef;
    floorDef.position.Set(0.0f, -0.5f);
    b2Body* floor = world.CreateBody(&floorDef);
    b2PolygonShape floorBox;
    floorBox.SetAsBox(40.0f, 0.5f);
    b2Fixture* floorFixture = floor->CreateFixture(&floorBox, 0.0f);
    floorFixture->SetFriction(0.8f);

    // Steel crate, 1 m x 1 m, 2.5 m up, thrown to the right at 9 m/s.
    b2BodyDef crateDef;
    crateDef.type = b2_dynamicBody;
    crateDef.position.Set(-10.0f, 3.0f);
    crateDef.linearVelocity.Set(9.0f, 0.0f);
    b2Body* crate = world.CreateBody(&crateDef);
    b2PolygonShape crateBox;
    crateBox.SetAsBox(0.5f, 0.5f);
    b2FixtureDef crateFixtureDef;
    crateFixtureDef.shape = &crateBox;
    crateFixtureDef.density = 4.0f; // kg/m^2
    crateFixtureDef.friction = 0.6f;
    b2Fixture* crateFixture = crate->CreateFixture(&crateFixtureDef);

    cfx::Effects fx(world, cfx::EffectsDef{cfx::DefaultPreset()});
    fx.SetMaterial(floorFixture, "concrete");
    fx.SetMaterial(crateFixture, "steel");
    const std::vector<std::string>& materials = fx.Config().materials;
    // "steel_concrete": the sound bank's name for a material pair.
    auto pairName = [&](const cfx::EffectEvent& event)
    { return materials[event.materialA.index] + "_" + materials[event.materialB.index]; };

    std::unordered_map<std::uint32_t, Voice> loops; // scrape id -> the voice playing its loop
    int impacts = 0, scrapesBegun = 0, scrapesEnded = 0;

    const float dt = 1.0f / 60.0f; // s
    const int kickStep = 150;      // 2.5 s: the player kicks the crate back
    for (int step = 0; step < 300; ++step)
    {
        if (step == kickStep)
        {
            crate->SetLinearVelocity(b2Vec2(-7.0f, 5.0f)); // m/s
            crate->SetAwake(true);
        }
        world.Step(dt, 8, 3);
        fx.Step(dt);
        const float time = static_cast<float>(step + 1) * dt; // s, at the end of this step

        // The events of this step, in order; valid until the next fx.Step.
        for (const cfx::EffectEvent& event : fx.Events())
        {
            // Map physics to sound: louder with intensity or approach speed, higher with sliding speed.
            const float scrapeVolume = std::min(1.0f, event.intensity / 10.0f);
            const float scrapePitch = std::clamp(0.5f + event.tangentialSpeed / 10.0f, 0.5f, 2.0f);
            switch (event.type)
            {
            case cfx::EffectEventType::impact:
                ++impacts;
                std::printf("t=%.2f s  impact %s, approach %.2f m/s\n", time, pairName(event).c_str(),
                            event.approachSpeed);
                PlayOneShot("impact_" + pairName(event), std::min(1.0f, event.approachSpeed / 10.0f),
                            event.point);
                break;
            case cfx::EffectEventType::scrapeBegan:
                ++scrapesBegun;
                std::printf("t=%.2f s  scrape %u began %s, intensity %.2f, sliding %.2f m/s\n", time,
                            event.id, pairName(event).c_str(), event.intensity, event.tangentialSpeed);
                loops[event.id] = StartLoop("scrape_" + pairName(event), scrapeVolume, scrapePitch);
                break;
            case cfx::EffectEventType::scrapeChanged:
                UpdateLoop(loops.at(event.id), scrapeVolume, scrapePitch, event.step % 10 == 0);
                break;
            case cfx::EffectEventType::scrapeEnded:
                ++scrapesEnded;
                std::printf("t=%.2f s  scrape %u ended (%s)\n", time, event.id, EndReason(event.end));
                StopLoop(loops.at(event.id));
                loops.erase(event.id);
                break;
            case cfx::EffectEventType::particleHits:
                break; // particles pattering on a body: cfx::SoundVoices turns them into short ticks and taps
            }
        }
    }

    std::printf("%d impacts, %d scrapes began, %d ended, %zu loops still playing\n", impacts, scrapesBegun,
                scrapesEnded, loops.size());
    const bool ok = impacts > 0 && scrapesBegun > 0 && scrapesEnded == scrapesBegun && loops.empty();
    return ok ? 0 : 1;
}
