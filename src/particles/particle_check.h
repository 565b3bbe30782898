// contactfx internal: an honest check of where pool particles ended a step, independent of the sweeps.
//
// It asks Box2D itself (its broad phase, b2Fixture::TestPoint, the fixtures' own edges), not the
// particle system's cached geometry, so a bug in the cache or the sweeps cannot hide from it. Two ways a
// particle can be wrong after a step:
// - inside: its centre is inside a solid fixture it collides with (circles and polygons; edges and chains
//   have no inside);
// - crossed: the straight path of its centre from the start of the step to its end crosses a static edge
//   or chain it collides with: a two-sided edge from either side, a one-sided edge or chain from its
//   front (the side its normal points to) to its back;
// - passed through: seen from a moving body (a solid circle or polygon of a dynamic or kinematic body),
//   its centre went from outside the body to outside it through the body, deeper than its radius: its
//   path from where it started in the body's frame at the start of the step (the body's pose then taken
//   as Box2D integrated it: centre less dt times velocity, angle less dt times angular velocity) to where
//   it ended in the body's frame now, the body turning at a constant rate (followed in pieces of 0.05 rad).
// Particles that do not collide, body-backed particles (Box2D moves those) and particles that died in the
// step (life 0) are not checked. Costs a world query per particle: for tests, benchmarks and debugging,
// never on by default (ParticleSystemOptions::checkParticles).
#pragma once

#include "particles/motion.h"

#include <cstdint>

class b2World;

namespace cfx
{
struct BodyFilter;
}

namespace cfx::particles
{

struct CheckCounts
{
    std::uint64_t inside = 0;        ///< particles whose centre ended inside a solid fixture
    std::uint64_t crossings = 0;     ///< particles whose path crossed an edge or chain
    std::uint64_t passedThrough = 0; ///< particles that went through a moving body
};

/// Checks live particles [0, count) of `pool` (its start arrays set) against `world`, skipping bodies
/// `ignore` ignores; adds to `counts`. A query per particle, each meeting the fixtures' children near its
/// path (a chain's segments near it, not all of them). Allocates nothing.
void CheckParticles(const b2World& world, const PoolArrays& pool, const TypeStep* types, std::uint32_t count,
                    const BodyFilter* ignore, float dt, CheckCounts& counts);

} // namespace cfx::particles
