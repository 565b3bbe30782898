#include "particles/particle_check.h"

#include "child_edge.h"
#include "particles/crossing.h"
#include "spawn_point.h"
#include "world_query.h"

#include <box2d/b2_body.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>

namespace cfx::particles
{

namespace
{

bool Accepts(const b2Fixture& fixture, const ParticleSide& side)
{
    const b2Filter& filter = fixture.GetFilterData();
    return !fixture.IsSensor() && side.Accepts(filter.categoryBits, filter.maskBits);
}

// Whether the path p -> q crosses child `child` of an edge or chain fixture, or ends on it (false for other
// shapes).
bool PathCrosses(const b2Fixture& fixture, int child, b2Vec2 p, b2Vec2 q)
{
    const b2Transform& xf = fixture.GetBody()->GetTransform();
    b2EdgeShape edge;
    return detail::ChildEdge(*fixture.GetShape(), child, edge) &&
           PathCrossesEdge(p, q, b2Mul(xf, edge.m_vertex1), b2Mul(xf, edge.m_vertex2), edge.m_oneSided, true);
}

} // namespace

void CheckParticles(const b2World& world, const PoolArrays& pool, const TypeStep* types, std::uint32_t count,
                    const BodyFilter* ignore, CheckCounts& counts)
{
    for (std::uint32_t i = 0; i < count; ++i)
    {
        const std::uint32_t slot = pool.Slot(i);
        const TypeStep& type = types[pool.type[slot]];
        if (!type.sweeps || !(pool.life[slot] > 0.0f))
        {
            continue;
        }
        const b2Vec2 start(pool.startX[slot], pool.startY[slot]);
        const b2Vec2 end(pool.positionX[slot], pool.positionY[slot]);
        // The path the step took: from the start to where a moving body's push took it from (the start
        // itself when nothing pushed it), then to the end. Its chord can cut an edge the particle went
        // around (flown past the edge's end, then pushed down beyond it).
        const b2Vec2 via(pool.viaX[slot], pool.viaY[slot]);
        b2AABB box;
        box.lowerBound = b2Min(b2Min(start, via), end);
        box.upperBound = b2Max(b2Max(start, via), end);
        bool inside = false;
        bool crossed = false;
        // Each child once: a fixture of one child (polygon, circle, edge) is met once, a chain once per
        // segment near the path.
        detail::QueryChildren(world, box,
                              [&](const b2Fixture* fixture, int child)
                              {
                                  if (Accepts(*fixture, type.side) &&
                                      (ignore == nullptr || !ignore->Ignore(fixture->GetBody())))
                                  {
                                      inside = inside || fixture->TestPoint(end);
                                      crossed = crossed || (fixture->GetBody()->GetType() == b2_staticBody &&
                                                            (PathCrosses(*fixture, child, start, via) ||
                                                             PathCrosses(*fixture, child, via, end)));
                                  }
                                  return !(inside && crossed);
                              });
        counts.inside += inside ? 1u : 0u;
        counts.crossings += crossed ? 1u : 0u;
    }
}

} // namespace cfx::particles
