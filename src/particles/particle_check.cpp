#include "particles/particle_check.h"

#include "spawn_point.h"

#include <algorithm>
#include <box2d/b2_body.h>
#include <box2d/b2_chain_shape.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>

namespace cfx::particles
{

namespace
{

// Collects each fixture a query meets once (Box2D reports a chain once per child proxy).
class Collect final : public b2QueryCallback
{
public:
    explicit Collect(std::vector<const b2Fixture*>& fixtures) : m_fixtures(fixtures) { m_fixtures.clear(); }

    bool ReportFixture(b2Fixture* fixture) override
    {
        if (std::find(m_fixtures.begin(), m_fixtures.end(), fixture) == m_fixtures.end())
        {
            m_fixtures.push_back(fixture);
        }
        return true;
    }

private:
    std::vector<const b2Fixture*>& m_fixtures;
};

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

bool PathCrosses(const b2Fixture& fixture, b2Vec2 p, b2Vec2 q)
{
    const b2Transform& xf = fixture.GetBody()->GetTransform();
    const b2Shape& shape = *fixture.GetShape();
    if (shape.GetType() == b2Shape::e_edge)
    {
        const auto& edge = static_cast<const b2EdgeShape&>(shape);
        return Crosses(p, q, b2Mul(xf, edge.m_vertex1), b2Mul(xf, edge.m_vertex2), edge.m_oneSided);
    }
    if (shape.GetType() == b2Shape::e_chain)
    {
        const auto& chain = static_cast<const b2ChainShape&>(shape);
        for (int child = 0; child < chain.GetChildCount(); ++child)
        {
            b2EdgeShape edge;
            chain.GetChildEdge(&edge, child);
            if (Crosses(p, q, b2Mul(xf, edge.m_vertex1), b2Mul(xf, edge.m_vertex2), true))
            {
                return true;
            }
        }
    }
    return false;
}

} // namespace

void ParticleCheck::Check(const b2World& world, const PoolArrays& pool, const TypeStep* types,
                          std::uint32_t count, const BodyFilter* ignore, CheckCounts& counts)
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
        Collect collect(m_fixtures);
        world.QueryAABB(&collect, box);
        bool inside = false;
        bool crossed = false;
        for (const b2Fixture* fixture : m_fixtures)
        {
            if (!Accepts(*fixture, type.side) || (ignore != nullptr && ignore->Ignore(fixture->GetBody())))
            {
                continue;
            }
            inside = inside || fixture->TestPoint(end);
            crossed = crossed ||
                      (fixture->GetBody()->GetType() == b2_staticBody && PathCrosses(*fixture, start, end));
        }
        counts.inside += inside ? 1u : 0u;
        counts.crossings += crossed ? 1u : 0u;
    }
}

} // namespace cfx::particles
