// Test support for the sound layer: hand-made events on real fixtures, and a recorder of voice changes.
#pragma once

#include "contactfx/presets.h"
#include "contactfx/sound.h"
#include "test_world.h"

#include <map>
#include <vector>

namespace cfx::test
{

/// `count` resting boxes on a ground, each a body pair with the ground for hand-made events of rule 0 of
/// the default preset (steel on concrete). Its sound rule has the defaults but scrapeWindow 0: a scrape
/// event's loudness is its own (the window has tests of its own).
struct EventBench
{
    explicit EventBench(int count)
    {
        SoundRuleDef instant;
        instant.materialA = config.rules[0].materialA;
        instant.materialB = config.rules[0].materialB;
        instant.scrapeWindow = 0.0f;
        config.sound.rules.push_back(instant);
        ground = world.CreateGround(0.8f, 0.5f * static_cast<float>(count) + 2.0f)->GetFixtureList();
        for (int i = 0; i < count; ++i)
        {
            const float x = static_cast<float>(i) - 0.5f * static_cast<float>(count);
            boxes.push_back(world.CreateBox(b2Vec2(x, 0.5f), 0.25f, 0.25f, 0.5f)->GetFixtureList());
        }
    }

    EffectEvent Event(EffectEventType type, int box, std::uint32_t id) const
    {
        EffectEvent event;
        event.type = type;
        event.rule = RuleId{0};
        event.materialA = config.FindMaterial(config.rules[0].materialA);
        event.materialB = config.FindMaterial(config.rules[0].materialB);
        event.fixtureA = boxes[static_cast<std::size_t>(box)];
        event.fixtureB = ground;
        event.id = id;
        return event;
    }
    /// A scrape event of `box` whose loudness (default gains: intensity only) is `loudness`.
    EffectEvent Scrape(EffectEventType type, int box, std::uint32_t id, float loudness,
                       float slip = 5.0f) const
    {
        EffectEvent event = Event(type, box, id);
        event.intensity = -std::log(1.0f - loudness) / SoundRuleDef{}.intensityGain;
        event.tangentialSpeed = slip;
        return event;
    }
    /// An impact of `box` whose loudness (default gains: approach speed only) is `loudness`.
    EffectEvent Impact(int box, std::uint32_t id, float loudness) const
    {
        EffectEvent event = Event(EffectEventType::impact, box, id);
        event.approachSpeed = -std::log(1.0f - loudness) / SoundRuleDef{}.approachSpeedGain;
        return event;
    }

    EffectsConfig config = DefaultPreset();
    TestWorld world;
    b2Fixture* ground = nullptr;
    std::vector<b2Fixture*> boxes;
};

/// Every voice's start and stop, from the changes of each step.
struct VoiceLog
{
    struct Life
    {
        VoiceKind kind = VoiceKind::scrape;
        double start = -1.0;
        double stop = -1.0;
        int starts = 0;
        int stops = 0;
        bool stoppedAtEnd = false; ///< by StopAll
    };

    void Record(const SoundVoices& voices, bool atEnd = false)
    {
        for (const VoiceChange& change : voices.Changes())
        {
            Life& life = lives[change.voice.id];
            life.kind = change.voice.kind;
            if (change.type == VoiceChangeType::started)
            {
                life.start = change.time;
                ++life.starts;
            }
            else
            {
                life.stop = change.time;
                ++life.stops;
                life.stoppedAtEnd = atEnd;
            }
        }
    }

    int Count(VoiceKind kind) const
    {
        int count = 0;
        for (const auto& [id, life] : lives)
        {
            count += life.kind == kind ? 1 : 0;
        }
        return count;
    }

    std::map<std::uint32_t, Life> lives;
};

} // namespace cfx::test
