// contactfx internal: which fixtures a particle collides with, one rule for the sweeps, the particle check
// and the spawn placement.
#pragma once

#include <cstdint>

namespace cfx::particles
{

/// Whether a particle of collision filter (categoryBits, maskBits) (ParticleTypeDef's) meets a fixture whose
/// b2Filter has (fixtureCategoryBits, fixtureMaskBits): Box2D's rule for two fixtures of group 0 (particles
/// have no group).
inline bool FilterAccepts(std::uint16_t categoryBits, std::uint16_t maskBits,
                          std::uint16_t fixtureCategoryBits, std::uint16_t fixtureMaskBits)
{
    return (fixtureMaskBits & categoryBits) != 0 && (fixtureCategoryBits & maskBits) != 0;
}

} // namespace cfx::particles
