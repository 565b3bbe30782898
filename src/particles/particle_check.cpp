#include "particles/particle_check.h"

#include "child_edge.h"
#include "spawn_point.h"
#include "world_query.h"

#include <box2d/b2_body.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>

namespace cfx::particles
{

namespace
{

float Cross(b2Vec2 a, b2Vec2 b)
{
    return a.x * b.y - a.y * b.x;
}

// Whether the path p -> q crosses the edge v1 -> v2: two-sided from either side, one-sided only from the
// front (right of v1 -> v2, Box2D's normal) to the back. Touching or ending on the line is not crossing.
bool Crosses(b2Vec2 p, b2Vec2 q, b2Vec2 v1, b2Vec2 v2, bool oneSided)
{
    const b2Vec2 e = v2 - v1;
    const float sideP = Cross(p - v1, e); // > 0: right of v1 -> v2, the front
    const float sideQ = Cross(q - v1, e);
    const bool opposite = oneSided ? (sideP > 0.0f && sideQ < 0.0f) : (sideP * sideQ < 0.0f);
    if (!opposite)
    {
        return false;
    }
    const b2Vec2 d = q - p;
    const float side1 = Cross(v1 - p, d);
    const float side2 = Cross(v2 - p, d);
    return side1 * side2 < 0.0f;
}

bool Accepts(const b2Fixture& fixture, const ParticleSide& side)
{
    const b2Filter& filter = fixture.GetFilterData();
    return !fixture.IsSensor() && (filter.maskBits & side.categoryBits) != 0 &&
           (filter.categoryBits & side.maskBits) != 0;
}

// Whether the path p -> q crosses child `child` of an edge or chain fixture (false for other shapes).
bool PathCrosses(const b2Fixture& fixture, int child, b2Vec2 p, b2Vec2 q)
{
    const b2Transform& xf = fixture.GetBody()->GetTransform();
    b2EdgeShape edge;
    return detail::ChildEdge(*fixture.GetShape(), child, edge) &&
           Crosses(p, q, b2Mul(xf, edge.m_vertex1), b2Mul(xf, edge.m_vertex2), edge.m_oneSided);
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
        b2AABB box;
        box.lowerBound = b2Min(start, end);
        box.upperBound = b2Max(start, end);
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
                                                            PathCrosses(*fixture, child, start, end));
                                  }
                                  return !(inside && crossed);
                              });
        counts.inside += inside ? 1u : 0u;
        counts.crossings += crossed ? 1u : 0u;
    }
}

} // namespace cfx::particles
