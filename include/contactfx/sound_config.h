// contactfx: the `sound` section of an effects configuration, plain data.
//
// How scrape, impact and particle hit events become voices (sound.h) and how the built-in synthesizer
// (sound_synth.h) colours them. The fields are declared once in config_fields.h (SoundFields(),
// SoundRuleFields()), which drives validation, the JSON reader and writer, the testbed's editor and
// docs/effects-config.md; the meaning of every field is in docs/sound.md.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace cfx
{

/// The colour the built-in synthesizer gives a rule's voices.
enum class SoundTimbre : std::uint8_t
{
    /// From the rule's material names: a name containing "rubber", "tyre" or "tire" squeals; else one
    /// containing "dirt", "sand", "soil", "mud", "grass" or "gravel" rumbles; else it hisses.
    automatic,
    hiss,   ///< bright filtered noise with crackle: metal or stone grinding on concrete
    squeal, ///< a tone whose pitch rises with slip speed over a little noise: rubber on concrete
    rumble, ///< low filtered noise: dirt, gravel
};

/// The sound of one pair rule, matched by its two materials (either order). A rule that no sound rule
/// names takes the defaults of a default-constructed SoundRuleDef.
struct SoundRuleDef
{
    std::string materialA;
    std::string materialB;
    /// Loudness (0..1) at or above which a scrape starts a voice.
    float scrapeStart = 0.1f;
    /// A sounding scrape voice continues while its loudness stays at or above scrapeStart times this,
    /// [0, 1]; below it (or when the scrape ends) the voice releases.
    float scrapeContinueRatio = 0.5f;
    /// A scrape voice sounds at least this long before it may release, s, [0, 10].
    float minDuration = 0.15f;
    /// Fade from the voice's loudness to silence after it lets go, s, [0, 10]. A scrape of the same body
    /// pair that comes back above the continue threshold meanwhile takes the voice over again.
    float release = 0.12f;
    /// Least time between two voice starts of the same kind for one body pair of this rule, s, [0, 60].
    float cooldown = 0.1f;
    /// Scrape loudness = 1 - exp(-(intensityGain * intensity + slipSpeedGain * tangential speed +
    /// forceGain * normal force)), normal force = the pair's normal impulse / dt, that sum (the drive)
    /// averaged over the last scrapeWindow.
    float intensityGain = 0.05f; ///< per unit of intensity, [0, 1000]
    float slipSpeedGain = 0.0f;  ///< per m/s, [0, 1000]
    float forceGain = 0.0f;      ///< per N, [0, 1000]
    /// s, [0, 1]: a scrape's drive is averaged over this much of the past, so that the one-step spike of a
    /// landing (its normal force is the landing's impulse over the step, and grows with the step rate)
    /// sounds alike at every step rate from 1 / scrapeWindow up (25 Hz by default; in a trial the scrape
    /// of a block landing while sliding peaked at 0, 0.15, 0.27 and 0.47 at 30, 60, 120 and 240 Hz). A
    /// steady scrape reaches its loudness over the window. 0: each step's own drive.
    float scrapeWindow = 0.04f;
    /// Impact loudness = 1 - exp(-(approachSpeedGain * approach speed + impulseGain * normal impulse)).
    float approachSpeedGain = 0.15f; ///< per m/s, [0, 1000]
    float impulseGain = 0.0f;        ///< per N*s, [0, 1000]
    /// How long an impact voice lasts; its loudness decays to 0 over it (ImpactEnvelope), s, (0, 10].
    float impactLength = 0.15f;
    SoundTimbre timbre = SoundTimbre::automatic;
    /// Slip speed at which a scrape is brightest (highest filter, highest pitch), m/s, (0, 1000].
    float brightSpeed = 12.0f;

    bool operator==(const SoundRuleDef&) const = default;
};

/// The `sound` section.
struct SoundConfig
{
    /// Most voices sounding at once, 1 .. 4096; beyond it the loudest win (ties: the older voice).
    std::uint32_t maxVoices = 16;
    /// Impacts of one body pair within this time of its impact voice's start merge into that voice,
    /// which takes the loudest, s, [0, 10].
    float impactMergeWindow = 0.05f;
    /// Body pairs tracked at once (scraping, sounding, releasing or cooling down) room is made for at
    /// creation, 0 .. 1,000,000: with no more at once, SoundVoices::Step does not allocate.
    std::uint32_t trackedPairs = 256;
    /// The synthesizer's output level: each voice's amplitude is gain * loudness before the soft limiter,
    /// [0, 4].
    float gain = 0.35f;
    /// Particle hits (pool particles of one type hitting one body in a step) sound as short ticks or taps:
    /// loudness = 1 - exp(-particleHitGain * mean approach speed * sqrt(count)), per m/s, [0, 1000].
    float particleHitGain = 0.03f;
    /// How long a particle hits voice lasts; its loudness decays to 0 over it (ImpactEnvelope), s, (0, 10].
    float particleHitLength = 0.04f;
    std::vector<SoundRuleDef> rules; ///< at most one per unordered material pair

    bool operator==(const SoundConfig&) const = default;
};

} // namespace cfx
