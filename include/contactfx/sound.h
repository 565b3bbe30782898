// contactfx: voices, what an audio engine plays, built from the scrape, impact and particle hit events.
//
//     cfx::SoundVoices voices(fx.Config());
//     for (;;)
//     {
//         world.Step(dt, 8, 3);
//         fx.Step(dt);
//         voices.Step(fx.Events(), dt);
//         for (const cfx::VoiceChange& change : voices.Changes()) { /* start or stop a sound */ }
//         for (const cfx::SoundVoice& voice : voices.Voices()) { /* set its volume: voice.loudness */ }
//     }
//     voices.StopAll(); // at the end: every started voice is stopped exactly once
//
// The events are made for particles and gameplay; played as they come they chatter (a rock bouncing down
// a slope begins and ends a scrape every few steps, lands with an impact and a scrape at once). A voice is
// what should be heard: scrape voices start above a loudness threshold and go on above a lower one
// (hysteresis), sound at least a minimum duration and fade out over a release, during which a scrape of the
// same body pair takes them over again; impacts of one body pair within a window are one voice, and so are
// the particle hits of one particle type on one body (a short tick or tap, louder with more and faster
// particles); a cooldown spaces voice starts per body pair; and at most `maxVoices` sound at once, the
// loudest first. The
// parameters are the effects config's `sound` section (sound_config.h); docs/sound.md explains them.
//
// No audio dependency: the built-in synthesizer (sound_synth.h) is one consumer of the voices, an audio
// engine of the application's is another.
//
// Determinism: the same events and dt give the same voices, ids and loudness, bit for bit. Body pairs are
// matched by comparing body addresses for equality, never by ordering them.
// Allocation: none per step while no more than `sound.trackedPairs` body pairs are tracked at once.
// Threading: one thread.
#pragma once

#include "contactfx/config.h"
#include "contactfx/events.h"
#include "contactfx/materials.h"

#include <array>
#include <box2d/b2_math.h>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

class b2Body;

namespace cfx
{

/// What a voice sounds.
enum class VoiceKind : std::uint8_t
{
    scrape,       ///< a sliding contact: a loop whose loudness and brightness follow the scrape
    impact,       ///< a hit: a short transient whose loudness decays over the rule's impactLength
    particleHits, ///< particles of one type pattering on one body: a short tick (sparks) or tap (dirt)
};

/// One sounding voice.
struct SoundVoice
{
    std::uint32_t id = 0; ///< never 0, never reused; ids grow in start order
    VoiceKind kind = VoiceKind::scrape;
    RuleId rule;                 ///< scrapes and impacts; invalid for particle hits
    MaterialId materialA;        ///< the rule's materialA
    MaterialId materialB;        ///< the rule's materialB
    ParticleTypeId particleType; ///< particle hits: the particles' type; invalid otherwise
    /// 0..1 now: a scrape's loudness (held during its minimum duration, fading during its release), an
    /// impact's peak times ImpactEnvelope of its age.
    float loudness = 0.0f;
    /// Impacts: the loudness at the start, the loudest of the events merged into it. Particle hits: that of
    /// all the hits merged into it (their number and mean speed), which wait for their merge time before it
    /// starts, so it never changes. Scrapes: the loudest so far.
    float peak = 0.0f;
    float slipSpeed = 0.0f; ///< m/s, scrapes: tangential speed of the scrape's last event
    /// m/s, impacts: the fastest merged impact's approach speed; particle hits: the fastest mean speed
    float approachSpeed = 0.0f;
    b2Vec2 point{0.0f, 0.0f}; ///< m, world: where it was last reported
    double startTime = 0.0;   ///< s (SoundVoices::Time() when it started)
    bool releasing = false;   ///< scrapes: fading out after letting go
};

enum class VoiceChangeType : std::uint8_t
{
    started,
    stopped,
};

/// A voice started or stopped in the last step: the voice as it was then (a stopped voice's loudness is its
/// last; 0 after a full release or impact).
struct VoiceChange
{
    VoiceChangeType type = VoiceChangeType::started;
    double time = 0.0; ///< s
    SoundVoice voice;
};

/// What SoundVoices counted since it was created.
struct SoundStats
{
    std::uint64_t scrapeVoices = 0;       ///< scrape voices started
    std::uint64_t impactVoices = 0;       ///< impact voices started
    std::uint64_t impactsMerged = 0;      ///< impacts merged into an impact voice of their body pair
    std::uint64_t impactsCooling = 0;     ///< impacts dropped inside their body pair's cooldown
    std::uint64_t impactsOverCap = 0;     ///< impacts that never sounded: maxVoices louder voices sounded
    std::uint64_t voicesCut = 0;          ///< sounding voices stopped early by louder ones over the cap
    std::uint64_t particleHitVoices = 0;  ///< particle hits voices started
    std::uint64_t particleHitsMerged = 0; ///< particle hits events merged into a voice of their type and body
    std::uint64_t particleHitsOverCap = 0; ///< particle hits events that never sounded: over maxVoices
    /// Particle hits voices still waiting for their merge time when StopAll came: they never sounded (at
    /// most one per particle type and body, of hits in the last merge time before the stop).
    std::uint64_t particleHitVoicesNotStarted = 0;
    std::uint32_t soundingMax = 0; ///< most voices sounding at once
};

/// The sound rule of every pair rule of `config`, indexed by RuleId: the `sound.rules` entry naming its
/// materials (either order), else a default SoundRuleDef with the rule's materials; `timbre` is never
/// `automatic` (resolved from the material names, see SoundTimbre).
std::vector<SoundRuleDef> ResolveSoundRules(const EffectsConfig& config);

/// The sound of the particle hits of each particle type of `config`, indexed by ParticleTypeId, as a sound
/// rule: impactLength = sound.particleHitLength, approachSpeedGain = sound.particleHitGain, cooldown 0,
/// timbre from the type's name (as SoundTimbre::automatic resolves a material's: "dirt" rumbles, a soft
/// tap; "sparks" hisses, a bright tick). The other fields are unused.
std::vector<SoundRuleDef> ResolveParticleHitSounds(const EffectsConfig& config);

/// A voice's name for files and panels: its rule's materials, "A+B" sorted by name, or for particle hits
/// the particle type's name.
std::string VoiceName(const SoundVoice& voice, const EffectsConfig& config);

/// The shape of an impact's loudness over its life: 1 at x = 0 falling to 0 at x = 1 ((1 - x)^2), 0 outside
/// [0, 1]; x = age / impactLength.
float ImpactEnvelope(float x);

class SoundVoices
{
public:
    /// Throws InputError (file "<api>", field path) when `config` is invalid.
    explicit SoundVoices(const EffectsConfig& config);

    /// One step, after Effects::Step(dt): `events` are that step's (Effects::Events()), read before any
    /// fixture or body is destroyed (an event's body pair is found through its fixtures). dt in s, > 0:
    /// InputError (file "<api>", field "dt") otherwise, and nothing changes.
    void Step(std::span<const EffectEvent> events, float dt);

    /// Stops every sounding voice now (the end of a run, a level change); Changes() then lists the stops.
    /// Forgets every body pair too: the scrapes going on (a scrape that goes on after it starts a new
    /// voice at its next event) and the particle hits still waiting for their merge time, which never
    /// sound (SoundStats::particleHitVoicesNotStarted counts them). Enough at a level change: a new
    /// Effects' events, whose ids start from 1 again, never meet the old level's.
    void StopAll();

    /// The voices sounding after the last Step, in start order. Valid until the next Step or StopAll.
    std::span<const SoundVoice> Voices() const { return m_voices; }
    /// The voices started and stopped by the last Step or StopAll: stops first, then starts, each in id
    /// order. Every started voice is stopped exactly once (by a Step or by StopAll).
    std::span<const VoiceChange> Changes() const { return m_changes; }
    /// Time of the last Step: the sum of every dt so far, s.
    double Time() const { return m_time; }
    const SoundStats& Stats() const { return m_stats; }
    /// The resolved sound rule of `rule` (ResolveSoundRules).
    const SoundRuleDef& RuleSound(RuleId rule) const { return m_rules[rule.index]; }
    /// The sound of a voice (its rule's, or its particle type's: ResolveParticleHitSounds).
    const SoundRuleDef& VoiceSound(const SoundVoice& voice) const;

private:
    /// Buckets a scrape's window is kept in: a spike's loudness depends on where the window's oldest bucket
    /// starts by at most 1 / (kWindowBuckets - 1), 7 %.
    static constexpr std::size_t kWindowBuckets = 16;

    // One body pair of one rule and one kind: its scrape (or its impacts), its voice, its cooldown. Particle
    // hits: one particle type (no rule) and one body (bodyA; bodyB null).
    struct Pair
    {
        VoiceKind kind = VoiceKind::scrape;
        RuleId rule;
        ParticleTypeId particleType;
        const b2Body* bodyA = nullptr;
        const b2Body* bodyB = nullptr;
        std::uint32_t scrapeId = 0; ///< the attached scrape event id; 0: none (the scrape ended)
        float drive = 0.0f;         ///< the attached scrape's drive in this step (0: no scrape event)
        float target = 0.0f;        ///< loudness of the scrape: its drive over the window (ScrapeWindow)
        /// The scrape's drive summed over time (drive * s) in kWindowBuckets buckets of scrapeWindow /
        /// kWindowBuckets each, aligned on the voices' clock; `newestBucket` is the absolute index of the
        /// one that holds the end of the last step (-1: none yet).
        std::array<float, kWindowBuckets> window{};
        std::int64_t newestBucket = -1;
        float pending = 0.0f; ///< impacts, particle hits: loudness of one waiting to start a voice; 0: none
        std::uint32_t pendingId = 0;
        float pendingSpeed = 0.0f;       ///< m/s: the approach speed the waiting voice starts with
        b2Vec2 pendingPoint{0.0f, 0.0f}; ///< where the waiting voice's events were last reported
        /// Particle hits: the hits waiting to start a voice, their approach speeds summed (m/s), and when the
        /// step of the first of them began (s): they wait for their merge time to be over, and the voice
        /// starts with the loudness of all of them, however many steps they came in.
        float mergedHits = 0.0f;
        float mergedSpeedSum = 0.0f;
        double mergeStart = 0.0;
        double lastStart = -1.0e300; ///< time of the pair's last voice start
        double releaseStart = 0.0;
        float releaseFrom = 0.0f;
        SoundVoice voice; ///< voice.id == 0: none
    };
    // A voice that wants to sound this step, for the cap.
    struct Claim
    {
        std::uint32_t pair;
        bool isProtected; ///< a scrape voice within its minimum duration
        float loudness;
        std::uint64_t order; ///< sounding: voice id; new: 2^32 + event id (particle hits: 2^33 + their index)
    };

    Pair& FindOrAdd(VoiceKind kind, const EffectEvent& event);
    const SoundRuleDef& SoundOf(const Pair& pair) const;
    double MergeWindow(const Pair& pair) const;
    bool Merges(const Pair& pair) const;
    void Hit(Pair& pair, float loudness, const EffectEvent& event, bool merges);
    Pair* FindScrape(std::uint32_t scrapeId);
    void OnEvent(const EffectEvent& event, float dt);
    void Advance(Pair& pair);
    void ApplyCap();
    void Stop(Pair& pair);
    void Start(Pair& pair, float loudness);

    std::uint32_t m_maxVoices;
    float m_mergeWindow; ///< s
    std::vector<SoundRuleDef> m_rules;
    std::vector<SoundRuleDef> m_hitSounds; ///< by particle type
    std::vector<Pair> m_pairs;
    std::vector<Claim> m_claims;
    std::vector<SoundVoice> m_voices;
    std::vector<VoiceChange> m_changes;
    double m_time = 0.0;
    double m_stepStart = 0.0; ///< m_time before the step now being taken
    std::uint32_t m_nextId = 1;
    std::uint32_t m_hitsThisStep = 0; ///< particle hits events read so far in this Step
    SoundStats m_stats;
};

} // namespace cfx
