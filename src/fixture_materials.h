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
