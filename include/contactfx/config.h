// contactfx: an effects configuration is plain data.
//
// Materials, particle types, pair rules, the particle budget, material assignment rules and sound, all by
// name, with defaults in place. The same struct is built in code, read from an effects config JSON file
// (contactfx_scene), edited in the testbed and written back. Validate() lists every problem with the field
// path, e.g. `rules[2].threshold`; Effects refuses an invalid configuration with the same list.
#pragma once

#include "contactfx/assignments.h"
#include "contactfx/error.h"
#include "contactfx/particle_types.h"
#include "contactfx/rules.h"
#include "contactfx/sound_config.h"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace cfx
{

/// Which particle makes room when the pool is full.
enum class RecyclePolicy : std::uint8_t
{
    oldest,     ///< the particle spawned first
    lowestLife, ///< the particle with the least time left to live (ties: the oldest)
};

/// The most touching-contact entries a config's budget may make room for: rules * budget.contacts (each
/// rule has room for budget.contacts of its own, and the body pairs and a step's events as much room in
/// all: about 800 bytes an entry, measured, so this is about 3.4 GB).
inline constexpr std::uint64_t kMaxContactRoom = std::uint64_t{1} << 22;

/// The particle budget.
struct ParticleBudget
{
    std::uint32_t capacity = 4096; ///< hard cap on live particles, 1 .. 4,000,000
    RecyclePolicy recycle = RecyclePolicy::oldest;
    /// Touching contacts (and body pairs) Effects makes room for when it is created, for each rule (about
    /// 800 bytes a contact a rule; rules * contacts <= kMaxContactRoom), 0 .. 1,000,000:
    /// with no more touching one rule at once, neither the contact callbacks nor Effects::Step allocate
    /// for them (the particle system's own warm-up in its first steps aside: docs/particles.md).
    /// More allocate once, as they first happen.
    std::uint32_t contacts = 1024;
    /// Particle hit groups (per particle type and body) a step reports at most, 0 .. 4096: beyond it the
    /// groups with the most hits are kept (ties: the first to appear). 0 records no hits at all.
    std::uint32_t particleHits = 64;

    bool operator==(const ParticleBudget&) const = default;
};

/// A complete effects configuration.
struct EffectsConfig
{
    std::string name;                   ///< for display ("tutorial", "default"); no control characters
    std::vector<std::string> materials; ///< unique, non-empty names, no control characters; at most 65534
    std::vector<ParticleTypeDef> particleTypes; ///< unique names; at most 65534
    std::vector<RuleDef> rules;                 ///< at most one per unordered material pair; at most 65534
    ParticleBudget budget;
    /// Materials for fixtures without a `material` property, first match wins (assignments.h).
    std::vector<MaterialAssignment> assignments;
    /// How events become voices and how the built-in synthesizer sounds (sound_config.h, docs/sound.md).
    SoundConfig sound;

    bool operator==(const EffectsConfig&) const = default;

    /// Index of a material / particle type by name, or an invalid id.
    MaterialId FindMaterial(std::string_view wanted) const;
    ParticleTypeId FindParticleType(std::string_view wanted) const;
    /// Touching contacts of all rules together that Effects makes room for: rules * budget.contacts (at
    /// most kMaxContactRoom in a valid config). Body pairs and a step's events get as much room.
    std::size_t ContactRoom() const { return rules.size() * std::size_t{budget.contacts}; }
};

/// Every problem in `config`, each with `file` as given and the field path. Empty when valid.
std::vector<Diagnostic> Validate(const EffectsConfig& config, std::string_view file = "<api>");

/// What Validate checks of particle types and a budget (paths "particleTypes[i].FIELD", "budget.FIELD"),
/// but not the names, which a ParticleSystem used alone never reads.
std::vector<Diagnostic> ValidateParticles(std::span<const ParticleTypeDef> types,
                                          const ParticleBudget& budget, std::string_view file = "<api>");

} // namespace cfx
