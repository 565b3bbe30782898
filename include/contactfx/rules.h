// contactfx: pair rules.
//
// A rule says what happens when two materials rub: which particle type, from what intensity, at what
// rate, measured how. Rules are symmetric: the rule for (steel, concrete) is also the rule for
// (concrete, steel). RuleTable answers "which rule for these two materials" in O(1): from a dense
// material x material matrix for up to kDenseMaterials materials (2 MB at most), else from a hash table
// of the pairs that have a rule (memory grows with the rules, not with the square of the materials); it
// is a pure function of the two ids.
#pragma once

#include "contactfx/intensity.h"
#include "contactfx/materials.h"

#include <cstdint>
#include <string>
#include <vector>

namespace cfx
{

/// How intensity above the threshold becomes particles.
enum class EmissionMode : std::uint8_t
{
    /// Per body pair (all contacts of the rule between the same two bodies, with all their manifold
    /// points, are one sliding contact): rate = ratePerIntensity * (intensity - threshold) particles per
    /// second, capped at maxRate, from the pair's intensity (its points' intensities weighted by normal
    /// impulse, each pressed by the pair's whole normal force), accumulated across steps per pair and
    /// shared out over the points by normal impulse. The count emitted for the same motion depends
    /// neither on the step rate nor on how many fixtures, chain segments or manifold points it spans.
    rate,
    /// One particle per sample per contact per step while the sample's intensity > threshold (the
    /// tutorial). Depends on the step rate and on the number of contacts and points by design.
    perStep,
};

/// The window over which RuleDef::maxRate holds (s): a pair saves at most this long's worth of its cap.
inline constexpr float kMaxRateWindow = 1.0f / 30.0f;

/// Where particles start.
enum class SpawnPlacement : std::uint8_t
{
    /// Outside both surfaces of the contact, found by ray casts against the two fixtures near the
    /// contact point (polygons, circles, edges and chains, one-sided included). Never inside a solid:
    /// when no start near the contact is free, the particle is not spawned (EffectsStats::spawnRejected).
    surface,
    /// The tutorial's: x of the contact point, y of the highest static fixture under it plus 0.05 m;
    /// when that start is inside a fixture the particle collides with (the other body of the contact is
    /// not one when the particle's collision filter passes through it, as the tutorial's car and wheels),
    /// the same drop at x moved along the ground, trailing side first, up to 1 m each way, else not spawned.
    tutorialDrop,
};

/// One rule. Materials and particle type are named; names are resolved and checked when an Effects
/// object is created (an unknown name is an error naming the field).
struct RuleDef
{
    /// The two materials (names of EffectsConfig::materials; the same name twice: a material on itself).
    /// Their order only names the two sides (the particle type's inheritA and inheritB, the events'
    /// materialA and fixtureA); the rule is symmetric.
    std::string materialA;
    std::string materialB;
    /// What the pair's scrapes emit (a name of EffectsConfig::particleTypes).
    std::string particleType;
    /// How a contact point's intensity is measured (intensity.h).
    IntensityModel intensity;
    /// Intensities <= threshold emit nothing (rate: the body pair's; perStep: each sample's). [0, 1e6].
    float threshold = 1.0f;
    EmissionMode emission = EmissionMode::rate;
    /// Particles per second per unit of intensity above the threshold (rate mode). [0, 1e6].
    float ratePerIntensity = 50.0f;
    /// Cap on one body pair's rate, particles per second (rate mode). [0, 1e5]. It holds over time, not
    /// per step: each step allows maxRate * dt, and what a pair leaves unused it saves, up to maxRate *
    /// kMaxRateWindow, for a later step to spend on top of its own. So over any T seconds a pair emits at
    /// most maxRate * (T + kMaxRateWindow) and the fraction of a particle it carries; a pair below its cap
    /// emits all its rate asks for; one held above it from its start emits its savings once, then
    /// maxRate, at any step rate; and a one-step spike (a landing's pressure) is not cut while it is
    /// within the savings plus the step's allowance (beyond that it gets those, which grow with dt).
    float maxRate = 1000.0f;
    /// Where particles start (see SpawnPlacement).
    SpawnPlacement placement = SpawnPlacement::surface;

    // Events (events.h) and impact bursts.
    /// A scrape ends after its intensity has stayed at or below the threshold this long, s, [0, 3600].
    float scrapeEndDelay = 0.1f;
    /// Approach speed along the normal at a new touch (events.h) that makes an impact event, m/s, [0, 1e4].
    float impactThreshold = 2.0f;
    /// Particles of the rule's burst type (burstParticleType) burst per m/s of approach speed above
    /// impactThreshold (or above burstThreshold when that is higher), [0, 1e4].
    float burstPerSpeed = 0.0f;
    /// Approach speed (m/s, [0, 1e4]) an impact must pass to burst, when it is above impactThreshold: soft
    /// impacts then make events (and sound) without particles. At or below impactThreshold (0 by default)
    /// it changes nothing: a burst comes with an impact event.
    float burstThreshold = 0.0f;
    /// Most particles one impact bursts, [0, 1e5].
    float burstMax = 50.0f;
    /// The particle type impacts burst; empty: particleType. One pair can so scrape one type and burst
    /// another (wood on stone: dust while a crate slides, splinters when it lands hard).
    std::string burstParticleType;

    /// The approach speed (m/s) an impact's burst counts from: the higher of impactThreshold and
    /// burstThreshold. An impact bursts min(burstMax, burstPerSpeed * (approach speed - this)) particles.
    float BurstFrom() const { return impactThreshold > burstThreshold ? impactThreshold : burstThreshold; }
    /// The particles an impact at `approachSpeed` (m/s) bursts: the whole part of min(burstMax,
    /// burstPerSpeed * (approachSpeed - BurstFrom())), 0 below 1 (before the pool's capacity and the
    /// search for a free start, which may leave fewer).
    int BurstSize(float approachSpeed) const
    {
        const float burst = burstPerSpeed * (approachSpeed - BurstFrom());
        const float capped = burst >= burstMax ? burstMax : burst; // NaN stays NaN, and bursts nothing
        // Validated rules give at most 1e5; beyond 1e9 (a rule that skipped validation) it is held at 1e9.
        return !(capped >= 1.0f) ? 0 : capped >= 1.0e9f ? 1000000000 : static_cast<int>(capped);
    }

    bool operator==(const RuleDef&) const = default;
};

/// The rule's name: its two material names sorted, joined by '+' ("concrete+steel"); what the events, the
/// stats file, the CLI and the testbed call it, and unique among a valid config's rules.
std::string PairName(const RuleDef& rule);

/// Symmetric (material, material) -> rule lookup.
class RuleTable
{
public:
    /// Up to this many materials the table is a dense matrix (a load per lookup); above, a hash table.
    static constexpr int kDenseMaterials = 1024;

    RuleTable() = default;
    /// A table for `materialCount` materials (0 .. 65,535) with no rules; throws InputError otherwise.
    explicit RuleTable(int materialCount);

    /// Sets the rule for the unordered pair {a, b} (replacing any rule it had); `a` is remembered as the
    /// rule's first material. Throws InputError unless both ids are valid and < material count and the
    /// rule id is valid. Allocates (a build step, not a per-step one).
    void Set(MaterialId a, MaterialId b, RuleId rule);
    /// The rule for the unordered pair, or RuleId{} when either id is invalid or no rule is set.
    RuleId Find(MaterialId a, MaterialId b) const
    {
        if (!a.IsValid() || !b.IsValid() || a.index >= m_count || b.index >= m_count)
        {
            return RuleId{};
        }
        if (m_count > kDenseMaterials)
        {
            return FindHashed(a, b);
        }
        return m_cells[static_cast<std::size_t>(a.index) * static_cast<std::size_t>(m_count) + b.index];
    }
    int MaterialCount() const { return m_count; }
    /// Number of rules: one more than the largest rule id set.
    int RuleCount() const { return static_cast<int>(m_first.size()); }
    /// The material given first when `rule` was set (the rule's materialA).
    MaterialId FirstMaterial(RuleId rule) const { return m_first[rule.index]; }

private:
    RuleId FindHashed(MaterialId a, MaterialId b) const;
    /// The hashed table's slot for the pair's key: where it is, or the empty slot where it goes.
    std::size_t HashedSlot(std::uint32_t key) const;

    int m_count = 0;
    /// Dense: m_count * m_count, kept symmetric. Hashed: a power of two of slots, at most half full.
    std::vector<RuleId> m_cells;
    std::vector<std::uint32_t> m_keys; ///< hashed only: per slot, (smaller id << 16) | larger id, or empty
    std::size_t m_pairs = 0;           ///< hashed only: slots in use
    std::vector<MaterialId> m_first;   ///< per rule: its materialA
};

} // namespace cfx
