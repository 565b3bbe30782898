// contactfx internal: particles against moving bodies, in each body's own frame (see world_geometry.h).
#include "particles/world_geometry.h"

#include <box2d/b2_chain_shape.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_polygon_shape.h>

namespace cfx::particles
{

namespace
{

bool SweepShape(const SweepInput& in, const b2Shape& shape, int child, Touch& touch)
{
    switch (shape.GetType())
    {
    case b2Shape::e_circle:
    {
        const auto& circle = static_cast<const b2CircleShape&>(shape);
        return SweepCircle(in, circle.m_p, circle.m_radius, touch);
    }
    case b2Shape::e_polygon:
    {
        const auto& polygon = static_cast<const b2PolygonShape&>(shape);
        return SweepPolygon(in, polygon.m_vertices, polygon.m_normals, polygon.m_count, touch);
    }
    case b2Shape::e_edge:
    {
        const auto& edge = static_cast<const b2EdgeShape&>(shape);
        return edge.m_vertex1 != edge.m_vertex2 &&
               SweepSegment(in, MakeSegment(edge.m_vertex1, edge.m_vertex2, edge.m_oneSided), touch);
    }
    case b2Shape::e_chain:
    {
        b2EdgeShape edge;
        static_cast<const b2ChainShape&>(shape).GetChildEdge(&edge, child);
        return edge.m_vertex1 != edge.m_vertex2 &&
               SweepSegment(in, MakeSegment(edge.m_vertex1, edge.m_vertex2, true), touch);
    }
    default:
        return false;
    }
}

} // namespace

bool WorldGeometry::SweepMoving(b2Vec2 start, b2Vec2 end, const ParticleSide& side, SweepResult& result) const
{
    const float r = side.radius;
    const b2AABB query = PathBox(start, end, r);
    bool found = false;
    m_movingGrid.Query(
        query,
        [&](std::uint32_t index)
        {
            const MovingShape& moving = m_movingShapes[index];
            if ((moving.maskBits & side.categoryBits) == 0 || (moving.categoryBits & side.maskBits) == 0)
            {
                return;
            }
            if (!BoxesOverlap(query, m_movingBoxes[index]))
            {
                return;
            }
            const MovingBody& body = m_movingBodies[moving.body];
            SweepInput in;
            in.p = b2MulT(body.before, start);
            in.d = b2MulT(body.after, end) - in.p;
            in.radius = r;
            Touch local = result.touch;
            if (!SweepShape(in, *moving.shape, moving.child, local))
            {
                return;
            }
            result.touch.t = local.t;
            result.touch.depth = local.depth;
            result.touch.position = b2Mul(body.after, local.position);
            result.touch.normal = b2Mul(body.after.q, local.normal);
            result.surfaceVelocity =
                body.velocity + b2Cross(body.angularVelocity, result.touch.position - body.center);
            result.material = &m_movingMaterials[moving.material];
            found = true;
        });
    return found;
}

} // namespace cfx::particles
