// contactfx internal: which fixture has which material, a side table keyed by fixture address.
#pragma once

#include "contactfx/materials.h"
#include "pointer_map.h"

#include <cstddef>
#include <cstdint>

class b2Fixture;

namespace cfx
{

/// Which fixture has which material: a side table keyed by fixture address. The fixture's user data is
/// not used. Entries must be removed when a fixture is destroyed: Effects does it for fixtures destroyed
/// with their body (b2DestructionListener); call Effects::ForgetFixture before b2Body::DestroyFixture,
/// which Box2D 2.4 reports to nobody.
///
/// When that call is missing, Box2D's block allocator gives the next fixture of the same size the freed
/// address, and it would inherit the material. So each entry also records who the fixture was: its body,
/// its shape's address, type, child count and geometry (48 bits of a hash). A lookup for a fixture that is
/// not the one recorded (another body, another shape, different geometry) finds no material, drops the
/// stale entry and counts it (Stale). What cannot be told apart: a fixture destroyed and re-created on the
/// same body with the same shape at the same addresses, which is the same fixture in every way Box2D
/// shows. The other side of it: a shape edited in place looks like another fixture (SetMaterial again).
class FixtureMaterials
{
public:
    /// Assigns `material` (an invalid id removes the entry). `fixture` must be alive.
    void Set(const b2Fixture* fixture, MaterialId material);
    /// The fixture's material, or an invalid id (also when the entry was recorded for another fixture at
    /// the same address, see above). `fixture` must be alive: it is read.
    MaterialId Get(const b2Fixture* fixture) const;
    /// The material recorded for the address, without checking who the fixture is: for a fixture that may
    /// have been destroyed since (an event naming the fixture last reported). Never reads `fixture`.
    MaterialId Recorded(const b2Fixture* fixture) const
    {
        const std::uint64_t* value = m_map.Find(fixture);
        return value != nullptr ? MaterialId{static_cast<std::uint16_t>(*value & 0xFFFFu)} : MaterialId{};
    }
    void Erase(const b2Fixture* fixture) { m_map.Erase(fixture); }
    std::size_t Size() const { return m_map.Size(); }
    /// Entries found to belong to a destroyed fixture (another fixture now at its address) and dropped.
    std::uint64_t Stale() const { return m_stale; }

private:
    // A lookup drops the stale entry it finds; it changes what a later lookup answers only in that the
    // answer is already known (no material).
    mutable detail::PointerMap m_map;
    mutable std::uint64_t m_stale = 0;
};

} // namespace cfx
