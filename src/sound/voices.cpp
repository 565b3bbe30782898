// Events -> voices (contactfx/sound.h).
//
// Why a layer between events and sound at all: the events follow the physics step by step, and the physics
// chatters. In the rockslide most impacts come with a scrape that begins in the same step, the median
// scrape lasts two steps, and nearly every scrape ends because the rock bounced off. Each body pair of a
// rule therefore gets one slot per kind (Pair) that outlives its scrapes: a scrape voice sounds while the
// pair keeps scraping loudly enough, however many scrape ids come and go underneath, holds for its
// minimum duration, and fades over its release, during which a new scrape of the pair takes it over. An
// impact slot remembers its voice's start for the merge window and the cooldown. Particle hits are impacts
// of many small bodies at once: one slot per particle type and body hit, merged and capped like impacts,
// with the particle type's sound (ResolveParticleHitSounds) in place of a rule's.
//
// Each step: the events update the slots (in event order); each slot advances its voice (hold, release,
// decay, stop) and says whether it wants to start one; then the cap keeps the loudest claims. Slots live in
// one array in the order they were added, removed by swap-remove when idle: the order depends only on the
// events, so the result is deterministic. Voices get their ids when they start, in the order the cap ranks
// them.
#include "contactfx/error.h"
#include "contactfx/sound.h"
#include "step_check.h"

#include <algorithm>
#include <box2d/b2_fixture.h>
#include <cmath>
#include <string_view>

namespace cfx
{

namespace
{

bool Contains(std::string_view name, std::initializer_list<std::string_view> parts)
{
    return std::any_of(parts.begin(), parts.end(),
                       [&](std::string_view part) { return name.find(part) != std::string_view::npos; });
}

SoundTimbre TimbreOf(std::string_view a, std::string_view b)
{
    auto squeals = [](std::string_view name) { return Contains(name, {"rubber", "tyre", "tire"}); };
    auto rumbles = [](std::string_view name) {
        return Contains(name, {"dirt", "sand", "soil", "mud", "grass", "gravel"});
    };
    if (squeals(a) || squeals(b))
    {
        return SoundTimbre::squeal;
    }
    if (rumbles(a) || rumbles(b))
    {
        return SoundTimbre::rumble;
    }
    return SoundTimbre::hiss;
}

const b2Body* BodyOf(const b2Fixture* fixture)
{
    return fixture != nullptr ? fixture->GetBody() : nullptr;
}

// Step times summed in doubles from floats land a little off the sum of their values (3 x 1/60 s as floats
// is 5.0000000707e-2 s): a merge time is compared with this much room (s).
constexpr double kTimeSlop = 1.0e-6;

float Saturate(float drive)
{
    return 1.0f - std::exp(-std::max(drive, 0.0f));
}

// What a scrape event drives its loudness with (before Saturate).
float ScrapeDrive(const SoundRuleDef& rule, const EffectEvent& event, float dt)
{
    return rule.intensityGain * event.intensity + rule.slipSpeedGain * event.tangentialSpeed +
           rule.forceGain * event.normalImpulse / dt;
}

// Adds `drive` over the step [from, to) (s) to `window` (sums of drive * s over kCount buckets of
// `width` s, aligned on multiples of `width`; `newest`: the absolute index of the last one filled), and
// returns the mean drive from the oldest bucket's start to `to`: a steady drive's own, and a one-step spike's
// area over about the window, whatever the step's length up to the window.
template <std::size_t kCount>
float WindowMean(std::array<float, kCount>& window, std::int64_t& newest, double width, double from,
                 double to, float drive)
{
    const auto count = static_cast<std::int64_t>(kCount);
    // The bucket holding the end of the step: the one the time just before `to` falls in.
    const std::int64_t last = std::max<std::int64_t>(0, static_cast<std::int64_t>(std::ceil(to / width)) - 1);
    for (std::int64_t bucket = std::max(newest + 1, last - count + 1); bucket <= last; ++bucket)
    {
        window[static_cast<std::size_t>(bucket % count)] = 0.0f;
    }
    newest = last;
    const std::int64_t oldest = last - count + 1;
    for (std::int64_t bucket = std::max(oldest, static_cast<std::int64_t>(std::floor(from / width)));
         bucket <= last; ++bucket)
    {
        const double overlap = std::min(to, static_cast<double>(bucket + 1) * width) -
                               std::max(from, static_cast<double>(bucket) * width);
        window[static_cast<std::size_t>(bucket % count)] +=
            static_cast<float>(drive * std::max(overlap, 0.0));
    }
    float sum = 0.0f;
    for (const float part : window)
    {
        sum += part;
    }
    const double span = to - static_cast<double>(oldest) * width;
    return span > 0.0 ? static_cast<float>(sum / span) : drive;
}

float ImpactLoudness(const SoundRuleDef& rule, const EffectEvent& event)
{
    return Saturate(rule.approachSpeedGain * event.approachSpeed + rule.impulseGain * event.normalImpulse);
}

// Many particles sound louder than one, as independent taps add: by the square root of their number.
// `speedSum`: their approach speeds summed (m/s), so the mean speed times sqrt(count).
float ParticleHitLoudness(const SoundRuleDef& sound, float speedSum, float count)
{
    return Saturate(sound.approachSpeedGain * speedSum / std::sqrt(count));
}

} // namespace

std::vector<SoundRuleDef> ResolveSoundRules(const EffectsConfig& config)
{
    std::vector<SoundRuleDef> resolved;
    resolved.reserve(config.rules.size());
    for (const RuleDef& rule : config.rules)
    {
        SoundRuleDef sound;
        for (const SoundRuleDef& candidate : config.sound.rules)
        {
            if ((candidate.materialA == rule.materialA && candidate.materialB == rule.materialB) ||
                (candidate.materialA == rule.materialB && candidate.materialB == rule.materialA))
            {
                sound = candidate;
                break;
            }
        }
        sound.materialA = rule.materialA;
        sound.materialB = rule.materialB;
        if (sound.timbre == SoundTimbre::automatic)
        {
            sound.timbre = TimbreOf(rule.materialA, rule.materialB);
        }
        resolved.push_back(std::move(sound));
    }
    return resolved;
}

std::vector<SoundRuleDef> ResolveParticleHitSounds(const EffectsConfig& config)
{
    std::vector<SoundRuleDef> resolved;
    resolved.reserve(config.particleTypes.size());
    for (const ParticleTypeDef& type : config.particleTypes)
    {
        SoundRuleDef sound;
        sound.approachSpeedGain = config.sound.particleHitGain;
        sound.impulseGain = 0.0f;
        sound.impactLength = config.sound.particleHitLength;
        sound.cooldown = 0.0f;
        sound.timbre = TimbreOf(type.name, "");
        resolved.push_back(sound);
    }
    return resolved;
}

std::string VoiceName(const SoundVoice& voice, const EffectsConfig& config)
{
    if (voice.kind == VoiceKind::particleHits)
    {
        return config.particleTypes[voice.particleType.index].name;
    }
    const RuleDef& rule = config.rules[voice.rule.index];
    return PairName(rule);
}

float ImpactEnvelope(float x)
{
    if (!(x >= 0.0f && x < 1.0f))
    {
        return 0.0f;
    }
    const float rest = 1.0f - x;
    return rest * rest;
}

SoundVoices::SoundVoices(const EffectsConfig& config)
    : m_maxVoices(config.sound.maxVoices), m_mergeWindow(config.sound.impactMergeWindow)
{
    std::vector<Diagnostic> problems = Validate(config);
    if (!problems.empty())
    {
        throw InputError(std::move(problems));
    }
    m_rules = ResolveSoundRules(config);
    m_hitSounds = ResolveParticleHitSounds(config);
    m_pairs.reserve(config.sound.trackedPairs);
    m_claims.reserve(config.sound.trackedPairs);
    m_voices.reserve(std::max(config.sound.maxVoices, config.sound.trackedPairs));
    m_changes.reserve(2 * static_cast<std::size_t>(config.sound.trackedPairs));
}

SoundVoices::Pair& SoundVoices::FindOrAdd(VoiceKind kind, const EffectEvent& event)
{
    const b2Body* a = kind == VoiceKind::particleHits ? event.body : BodyOf(event.fixtureA);
    const b2Body* b = BodyOf(event.fixtureB);
    for (Pair& pair : m_pairs)
    {
        // Equality only (a rule of one material with itself may list the bodies either way round).
        if (pair.kind == kind && pair.rule == event.rule && pair.particleType == event.particleType &&
            ((pair.bodyA == a && pair.bodyB == b) || (pair.bodyA == b && pair.bodyB == a)))
        {
            return pair;
        }
    }
    Pair& pair = m_pairs.emplace_back();
    pair.kind = kind;
    pair.rule = event.rule;
    pair.particleType = event.particleType;
    pair.bodyA = a;
    pair.bodyB = b;
    pair.voice.kind = kind;
    pair.voice.rule = event.rule;
    pair.voice.materialA = event.materialA;
    pair.voice.materialB = event.materialB;
    pair.voice.particleType = event.particleType;
    return pair;
}

const SoundRuleDef& SoundVoices::SoundOf(const Pair& pair) const
{
    return pair.kind == VoiceKind::particleHits ? m_hitSounds[pair.particleType.index]
                                                : m_rules[pair.rule.index];
}

const SoundRuleDef& SoundVoices::VoiceSound(const SoundVoice& voice) const
{
    return voice.kind == VoiceKind::particleHits ? m_hitSounds[voice.particleType.index]
                                                 : m_rules[voice.rule.index];
}

// How long after its start an impact or particle hits voice of `pair` takes in events (s): the merge
// window, or less when the voice is shorter (an event merged into a voice that stops in the same step
// would be lost).
double SoundVoices::MergeWindow(const Pair& pair) const
{
    return std::min(static_cast<double>(m_mergeWindow), static_cast<double>(SoundOf(pair).impactLength));
}

// Whether an impact or particle hits event of `pair` merges into its voice: one waits to start (particle
// hits wait for their merge time, see Advance), or an impact voice sounds and is within the merge window
// after its start (and not its whole length). Nothing merges into a sounding particle hits voice: its
// loudness is known when it starts, as a one-shot needs it, and the loudest start of its decay is played
// at it whatever the step rate.
bool SoundVoices::Merges(const Pair& pair) const
{
    if (pair.pending > 0.0f)
    {
        return true;
    }
    if (pair.voice.id == 0 || pair.kind == VoiceKind::particleHits)
    {
        return false;
    }
    const double age = m_time - pair.voice.startTime;
    return age <= m_mergeWindow && age < static_cast<double>(SoundOf(pair).impactLength);
}

// An impact or particle hits event of `pair` at `loudness`: merged into the voice it starts or sounds when
// `merges` (Merges, asked before the event changed the pair), dropped inside the cooldown or when silent,
// else waiting to start a voice.
void SoundVoices::Hit(Pair& pair, float loudness, const EffectEvent& event, bool merges)
{
    const bool impact = pair.kind == VoiceKind::impact;
    const bool sounding = pair.voice.id != 0;
    if (merges)
    {
        ++(impact ? m_stats.impactsMerged : m_stats.particleHitsMerged);
        if (sounding && pair.pending <= 0.0f) // an impact voice within its merge window
        {
            pair.voice.peak = std::max(pair.voice.peak, loudness);
            pair.voice.approachSpeed = std::max(pair.voice.approachSpeed, event.approachSpeed);
        }
        else // into the one waiting to start (a sounding voice goes on meanwhile)
        {
            pair.pending = std::max(pair.pending, loudness);
            pair.pendingSpeed = std::max(pair.pendingSpeed, event.approachSpeed);
            pair.pendingPoint = event.point;
        }
    }
    else if (m_time - pair.lastStart < SoundOf(pair).cooldown)
    {
        ++m_stats.impactsCooling; // particle hits have no cooldown
    }
    else if (loudness > 0.0f) // a silent event (a gain of 0) starts nothing
    {
        pair.pending = loudness;
        // Particle hits have no id: they rank after impacts and scrapes among equals, in event order.
        pair.pendingId = impact ? event.id : m_hitsThisStep;
        pair.pendingSpeed = event.approachSpeed;
        pair.pendingPoint = event.point;
    }
}

SoundVoices::Pair* SoundVoices::FindScrape(std::uint32_t scrapeId)
{
    for (Pair& pair : m_pairs)
    {
        if (pair.kind == VoiceKind::scrape && pair.scrapeId == scrapeId)
        {
            return &pair;
        }
    }
    return nullptr;
}

void SoundVoices::OnEvent(const EffectEvent& event, float dt)
{
    if (event.type == EffectEventType::particleHits)
    {
        if (event.particleType.index < m_hitSounds.size() && event.body != nullptr && event.count > 0)
        {
            // The hits of one merge time count together, whatever steps they came in, and start one voice
            // when it is over (Advance): a rain of hits sounds alike at any step rate (more steps, fewer
            // hits a step).
            Pair& pair = FindOrAdd(VoiceKind::particleHits, event);
            const bool merges = Merges(pair);
            const float hits = static_cast<float>(event.count);
            pair.mergedHits = (merges ? pair.mergedHits : 0.0f) + hits;
            pair.mergedSpeedSum = (merges ? pair.mergedSpeedSum : 0.0f) + event.approachSpeed * hits;
            pair.mergeStart = merges ? pair.mergeStart : m_stepStart;
            Hit(pair,
                ParticleHitLoudness(m_hitSounds[event.particleType.index], pair.mergedSpeedSum,
                                    pair.mergedHits),
                event, merges);
        }
        return;
    }
    if (!event.rule.IsValid() || event.rule.index >= m_rules.size())
    {
        return;
    }
    const SoundRuleDef& rule = m_rules[event.rule.index];
    switch (event.type)
    {
    case EffectEventType::scrapeBegan:
    case EffectEventType::scrapeChanged:
    {
        Pair* pair = FindScrape(event.id);
        if (pair == nullptr) // a new scrape, or one that began before these voices existed
        {
            pair = &FindOrAdd(VoiceKind::scrape, event);
            pair->scrapeId = event.id;
        }
        pair->drive = ScrapeDrive(rule, event, dt);
        pair->voice.slipSpeed = event.tangentialSpeed;
        pair->voice.point = event.point;
        break;
    }
    case EffectEventType::scrapeEnded:
        if (Pair* pair = FindScrape(event.id))
        {
            pair->scrapeId = 0;
            pair->drive = 0.0f;
        }
        break;
    case EffectEventType::impact:
    {
        Pair& pair = FindOrAdd(VoiceKind::impact, event);
        Hit(pair, ImpactLoudness(rule, event), event, Merges(pair));
        break;
    }
    case EffectEventType::particleHits:
        break; // handled above
    }
}

// The pair's voice one step on (hold, release, decay, stop), and its claim to sound this step.
void SoundVoices::Advance(Pair& pair)
{
    const SoundRuleDef& rule = SoundOf(pair);
    const auto index = static_cast<std::uint32_t>(&pair - m_pairs.data());
    SoundVoice& voice = pair.voice;
    if (pair.kind != VoiceKind::scrape)
    {
        // Particle hits wait until a next step as long as this one would no longer fit in their merge time
        // (from the start of the step of the first of them, steps without hits included): the whole steps
        // that fit make one voice.
        const bool ready = pair.pending > 0.0f && (pair.kind != VoiceKind::particleHits ||
                                                   (m_time - pair.mergeStart) + (m_time - m_stepStart) >
                                                       MergeWindow(pair) + kTimeSlop);
        if (voice.id != 0)
        {
            const auto age = static_cast<float>(m_time - voice.startTime);
            voice.loudness = voice.peak * ImpactEnvelope(age / rule.impactLength);
            // Decayed, or a new hit after the merge window and the cooldown replaces it.
            if (voice.loudness <= 0.0f || ready)
            {
                Stop(pair);
            }
        }
        if (ready)
        {
            const std::uint64_t after = pair.kind == VoiceKind::impact ? 1ull << 32 : 2ull << 32;
            m_claims.push_back({index, false, pair.pending, after + pair.pendingId});
        }
        else if (voice.id != 0)
        {
            m_claims.push_back({index, false, voice.loudness, voice.id});
        }
        return;
    }

    // The step's drive, over the window (none: the step's own).
    pair.target = Saturate(rule.scrapeWindow > 0.0f
                               ? WindowMean(pair.window, pair.newestBucket,
                                            static_cast<double>(rule.scrapeWindow) / kWindowBuckets,
                                            m_stepStart, m_time, pair.drive)
                               : pair.drive);
    pair.drive = 0.0f; // each scrape event drives its own step
    const float continueAt = rule.scrapeStart * rule.scrapeContinueRatio;
    const bool loud = pair.scrapeId != 0 && pair.target >= continueAt;
    if (voice.id == 0)
    {
        if (pair.scrapeId != 0 && pair.target >= rule.scrapeStart && m_time - pair.lastStart >= rule.cooldown)
        {
            m_claims.push_back({index, false, pair.target, (1ull << 32) + pair.scrapeId});
        }
        return;
    }
    const auto age = static_cast<float>(m_time - voice.startTime);
    if (loud)
    {
        voice.releasing = false;
        voice.loudness = pair.target;
    }
    else if (!voice.releasing && age >= rule.minDuration)
    {
        voice.releasing = true;
        pair.releaseStart = m_time;
        pair.releaseFrom = voice.loudness;
    }
    if (voice.releasing)
    {
        const auto fading = static_cast<float>(m_time - pair.releaseStart);
        voice.loudness = fading < rule.release ? pair.releaseFrom * (1.0f - fading / rule.release) : 0.0f;
        if (voice.loudness <= 0.0f)
        {
            Stop(pair);
            return;
        }
    }
    voice.peak = std::max(voice.peak, voice.loudness);
    const bool young = !voice.releasing && age < rule.minDuration;
    m_claims.push_back({index, young, voice.loudness, voice.id});
}

void SoundVoices::Stop(Pair& pair)
{
    m_changes.push_back({VoiceChangeType::stopped, m_time, pair.voice});
    pair.voice.id = 0;
    pair.voice.loudness = 0.0f;
    pair.voice.releasing = false;
}

void SoundVoices::Start(Pair& pair, float loudness)
{
    SoundVoice& voice = pair.voice;
    voice.id = m_nextId++;
    voice.loudness = loudness;
    voice.peak = loudness;
    voice.startTime = m_time;
    voice.releasing = false;
    if (pair.kind != VoiceKind::scrape)
    {
        voice.approachSpeed = pair.pendingSpeed;
        voice.point = pair.pendingPoint;
    }
    pair.lastStart = m_time;
    pair.pending = 0.0f;
    ++(pair.kind == VoiceKind::scrape   ? m_stats.scrapeVoices
       : pair.kind == VoiceKind::impact ? m_stats.impactVoices
                                        : m_stats.particleHitVoices);
    m_changes.push_back({VoiceChangeType::started, m_time, voice});
}

// Keeps at most maxVoices claims: voices within their minimum duration first, then the loudest, ties to the
// older voice (lower id), new voices last among equals in event order. The rest stop or never start.
void SoundVoices::ApplyCap()
{
    std::sort(m_claims.begin(), m_claims.end(),
              [](const Claim& a, const Claim& b)
              {
                  if (a.isProtected != b.isProtected)
                  {
                      return a.isProtected;
                  }
                  if (a.loudness != b.loudness)
                  {
                      return a.loudness > b.loudness;
                  }
                  return a.order < b.order;
              });
    for (std::size_t i = 0; i < m_claims.size(); ++i)
    {
        const Claim& claim = m_claims[i];
        Pair& pair = m_pairs[claim.pair];
        const bool kept = i < m_maxVoices;
        const bool sounding = claim.order < (1ull << 32);
        if (sounding && !kept)
        {
            ++m_stats.voicesCut;
            Stop(pair);
        }
        else if (!sounding && kept)
        {
            Start(pair, claim.loudness);
        }
        else if (!sounding && pair.kind != VoiceKind::scrape)
        {
            ++(pair.kind == VoiceKind::impact ? m_stats.impactsOverCap : m_stats.particleHitsOverCap);
            pair.pending = 0.0f;
        }
    }
}

void SoundVoices::Step(std::span<const EffectEvent> events, float dt)
{
    detail::CheckStepTime(dt); // before anything changes: a NaN time would stay in every later voice
    m_stepStart = m_time;
    m_time += static_cast<double>(dt);
    m_changes.clear();
    m_claims.clear();
    m_hitsThisStep = 0;
    for (const EffectEvent& event : events)
    {
        OnEvent(event, dt);
        m_hitsThisStep += event.type == EffectEventType::particleHits ? 1u : 0u;
    }
    for (Pair& pair : m_pairs)
    {
        Advance(pair);
    }
    ApplyCap();

    // Idle pairs go once their cooldown and merge window are over (swap-remove: the order stays a function
    // of the events).
    const double window = m_mergeWindow;
    for (std::size_t i = 0; i < m_pairs.size();)
    {
        const Pair& pair = m_pairs[i];
        const double since = m_time - pair.lastStart;
        const bool idle = pair.voice.id == 0 && pair.scrapeId == 0 && pair.pending <= 0.0f &&
                          since >= SoundOf(pair).cooldown && since > window;
        if (idle)
        {
            m_pairs[i] = m_pairs.back();
            m_pairs.pop_back();
        }
        else
        {
            ++i;
        }
    }

    m_voices.clear();
    for (const Pair& pair : m_pairs)
    {
        if (pair.voice.id != 0)
        {
            m_voices.push_back(pair.voice);
        }
    }
    std::sort(m_voices.begin(), m_voices.end(),
              [](const SoundVoice& a, const SoundVoice& b) { return a.id < b.id; });
    std::sort(m_changes.begin(), m_changes.end(),
              [](const VoiceChange& a, const VoiceChange& b)
              {
                  if (a.type != b.type)
                  {
                      return a.type == VoiceChangeType::stopped;
                  }
                  return a.voice.id < b.voice.id;
              });
    m_stats.soundingMax = std::max(m_stats.soundingMax, static_cast<std::uint32_t>(m_voices.size()));
}

void SoundVoices::StopAll()
{
    m_changes.clear();
    for (const SoundVoice& voice : m_voices)
    {
        m_changes.push_back({VoiceChangeType::stopped, m_time, voice});
    }
    // Every pair is forgotten: the scrapes attached to them (a level's, whose scrapeEnded may never come: a
    // new Effects counts its ids from 1 again) and the particle hits still waiting for their merge time.
    for (const Pair& pair : m_pairs)
    {
        m_stats.particleHitVoicesNotStarted +=
            pair.kind == VoiceKind::particleHits && pair.pending > 0.0f ? 1 : 0;
    }
    m_pairs.clear();
    m_voices.clear();
}

} // namespace cfx
