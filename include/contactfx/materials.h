// contactfx: materials.
//
// A material is a name ("steel", "rubber") with a small index. Fixtures get a material through the
// Effects object's side table (cfx::Effects::SetMaterial), never through the fixture's user data, which
// stays the application's. A fixture without a material takes part in no rule and makes no effects.
// This header holds the small ids that name materials, rules and particle types.
#pragma once

#include <cstdint>

namespace cfx
{

/// Index of a material in an effects configuration (`EffectsConfig::materials`). A small value that is
/// cheap to copy and compare; `MaterialId{}` is "no material".
struct MaterialId
{
    static constexpr std::uint16_t kNone = 0xFFFF;
    std::uint16_t index = kNone;

    constexpr bool IsValid() const { return index != kNone; }
    constexpr bool operator==(const MaterialId&) const = default;
};

/// Index of a pair rule in `EffectsConfig::rules`; `RuleId{}` is "no rule".
struct RuleId
{
    static constexpr std::uint16_t kNone = 0xFFFF;
    std::uint16_t index = kNone;

    constexpr bool IsValid() const { return index != kNone; }
    constexpr bool operator==(const RuleId&) const = default;
};

/// Index of a particle type in `EffectsConfig::particleTypes`.
struct ParticleTypeId
{
    static constexpr std::uint16_t kNone = 0xFFFF;
    std::uint16_t index = kNone;

    constexpr bool IsValid() const { return index != kNone; }
    constexpr bool operator==(const ParticleTypeId&) const = default;
};

} // namespace cfx
