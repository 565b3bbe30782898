// contactfx: materials.
//
// A material is a name ("steel", "rubber") with a small index. Fixtures get a material through the
// Effects object's side table (cfx::Effects::SetMaterial), never through the fixture's user data, which
// stays the application's. A fixture without a material takes part in no rule and makes no effects.
#pragma once

#include "contactfx/detail/pointer_map.h"

#include <cstdint>

class b2Fixture;

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

/// Which fixture has which material: a side table keyed by fixture address. The fixture's user data is
/// not used. Entries must be removed when a fixture is destroyed: Effects does it for fixtures destroyed
/// with their body (b2DestructionListener); call Effects::ForgetFixture before b2Body::DestroyFixture,
/// which Box2D 2.4 reports to nobody.
class FixtureMaterials
{
public:
    /// Assigns `material` (an invalid id removes the entry).
    void Set(const b2Fixture* fixture, MaterialId material);
    /// The fixture's material, or an invalid id.
    MaterialId Get(const b2Fixture* fixture) const
    {
        const std::uint64_t* value = m_map.Find(fixture);
        return value != nullptr ? MaterialId{static_cast<std::uint16_t>(*value)} : MaterialId{};
    }
    void Erase(const b2Fixture* fixture) { m_map.Erase(fixture); }
    std::size_t Size() const { return m_map.Size(); }

private:
    detail::PointerMap m_map;
};

} // namespace cfx
