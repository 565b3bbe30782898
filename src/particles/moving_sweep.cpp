// contactfx internal: particles against moving bodies, in each body's own frame (see world_geometry.h).
#include "particles/world_geometry.h"

#include <algorithm>
#include <box2d/b2_chain_shape.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_polygon_shape.h>
#include <cmath>

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

b2Vec2 WorldGeometry::MovingBody::CenterAt(float f) const
{
    return f >= 1.0f ? center : f <= 0.0f ? centerBefore : centerBefore + f * (center - centerBefore);
}

int WorldGeometry::MovingBody::PiecesFrom(float from) const
{
    const float left = 1.0f - from;
    return from <= 0.0f  ? pieces
           : left > 0.0f ? std::max(1, static_cast<int>(std::ceil(left * static_cast<float>(pieces))))
                         : 1;
}

b2Transform WorldGeometry::MovingBody::At(float f) const
{
    if (f >= 1.0f)
    {
        return after;
    }
    if (f <= 0.0f)
    {
        return before;
    }
    b2Transform xf;
    xf.q.Set(angleBefore + f * turn);
    xf.p = CenterAt(f) - b2Mul(xf.q, localCenter);
    return xf;
}

// Seen from the body's centre, which moves in a straight line, the disc's path is a segment, and the shape
// stays within `reach` of the centre in every pose: the disc can meet it only if the segment passes within
// reach + r of the centre. A few flops, where the sweep costs two transforms per piece and a shape test.
bool WorldGeometry::MayMeet(const MovingBody& body, b2Vec2 centreAtStart, float reach, b2Vec2 start,
                            b2Vec2 end, float r)
{
    const b2Vec2 from = start - centreAtStart;
    const b2Vec2 along = (end - body.center) - from;
    const float lengthSq = b2Dot(along, along);
    const float u = lengthSq > 0.0f ? std::clamp(-b2Dot(from, along) / lengthSq, 0.0f, 1.0f) : 0.0f;
    const b2Vec2 nearest = from + u * along;
    const float magnitude = std::max(std::max(std::abs(start.x), std::abs(start.y)),
                                     std::max(std::abs(body.center.x), std::abs(body.center.y)));
    const float within = reach + r + MovingSlop(magnitude + std::abs(end.x) + std::abs(end.y));
    return b2Dot(nearest, nearest) <= within * within;
}

bool WorldGeometry::SweepMoving(b2Vec2 start, b2Vec2 end, const ParticleSide& side, float from,
                                SweepResult& result, const b2Body* except, LeavingTouch leaving) const
{
    const float r = side.radius;
    const b2AABB query = PathBox(start, end, r);
    const float left = 1.0f - from; // of the step, from `from`
    bool found = false;
    m_movingGrid.Query(
        query,
        [&](std::uint32_t index)
        {
            const MovingShape& moving = m_movingShapes[index];
            if (!side.Accepts(moving.categoryBits, moving.maskBits) ||
                (except != nullptr && m_movingMaterials[moving.material].body == except))
            {
                return;
            }
            if (!BoxesOverlap(query, m_movingBoxes[index]))
            {
                return;
            }
            const MovingBody& body = m_movingBodies[moving.body];
            if (!MayMeet(body, body.CenterAt(from), moving.reach, start, end, r))
            {
                return;
            }

            // The disc's path in the body's frame, piece by piece: from where it was in the frame at the
            // piece's start to where it is in the frame at the piece's end (one piece, in the end pose,
            // from the end of the step). A piece is a fraction `perPiece` of the path and of the time left.
            const int pieces = body.PiecesFrom(from);
            const float perPiece = 1.0f / static_cast<float>(pieces);
            b2Transform frame = body.At(from);
            b2Vec2 pieceStart = b2MulT(frame, start);
            Touch local;
            float t = 2.0f;
            for (int piece = 0; piece < pieces; ++piece)
            {
                const float f = piece + 1 == pieces ? 1.0f : static_cast<float>(piece + 1) * perPiece;
                frame = body.At(from + f * left);
                const b2Vec2 to = b2MulT(frame, start + f * (end - start));
                if (SweepShape(SweepInput{pieceStart, to - pieceStart, r}, *moving.shape, moving.child,
                               local))
                {
                    t = (static_cast<float>(piece) + local.t) * perPiece;
                    break;
                }
                pieceStart = to;
            }
            if (t > 1.0f || t > result.touch.t || (t == result.touch.t && local.depth <= result.touch.depth))
            {
                return; // no touch, or not earlier (or, at the start, not deeper) than the best one
            }
            // Then the disc slides: the rest of its motion relative to the body, less its part into the
            // surface, ends in the body's frame at the end of the step; out of the shape if a curve or a
            // corner still puts it inside. The slide loses Coulomb friction times the part into the
            // surface, never reversing (as the velocity does, Respond): a particle resting on a sloped
            // body holds where the friction holds it, instead of creeping down by the step's gravity.
            b2Vec2 normal = local.normal;
            b2Vec2 rest = b2MulT(body.after, end) - local.position;
            const float into = b2Dot(rest, normal);
            if (into < 0.0f)
            {
                rest -= into * normal;
                rest *= SlideLeft(rest.Length(),
                                  b2MixFriction(side.friction, m_movingMaterials[moving.material].friction) *
                                      -into);
            }
            else if (t > 0.0f)
            {
                // Came onto the surface, yet the rest leaves it: only a turning body's arc does that (the
                // chord to its end pose cuts across the turn, where the arc went on into the body). The
                // body carries the disc: it ends on the surface.
                rest -= into * normal;
            }
            b2Vec2 final = local.position + rest;
            Touch out;
            const bool endsOn =
                SweepShape(SweepInput{final, b2Vec2(0.0f, 0.0f), r}, *moving.shape, moving.child, out);
            // It starts on (or in) the shape and leaves it or slides along it, or it grazes the surface later
            // and stays on it (a rounding brought it a hair closer): the body moves it nowhere (a grain a
            // box pushes along the ground, swept again after the ground's touch). Within the touch slop, a
            // disc is on the surface, not into it.
            const bool movesNothing = (t == 0.0f ? into >= -kTouchSlop : std::abs(into) <= kTouchSlop) &&
                                      (!endsOn || out.depth <= kTouchSlop);
            if (movesNothing && leaving == LeavingTouch::ignored)
            {
                return;
            }
            if (endsOn)
            {
                final = out.position;
                normal = out.normal;
            }
            result.firstTouch = start + t * (end - start);
            result.movingBody = moving.body;
            result.touchTime = from + t * left;
            result.carryFrom = local.position;
            result.carryTo = final;
            result.touch.t = t;
            result.touch.depth = local.depth;
            result.touch.position = b2Mul(body.after, final);
            result.touch.normal = b2Mul(body.after.q, normal);
            result.surfaceVelocity =
                body.velocity + b2Cross(body.angularVelocity, result.touch.position - body.center);
            result.material = &m_movingMaterials[moving.material];
            found = true;
        });
    return found;
}

WorldGeometry::CarriedDisc WorldGeometry::Carried(const SweepResult& hit, float f) const
{
    const MovingBody& body = m_movingBodies[hit.movingBody];
    const float left = 1.0f - hit.touchTime;
    const float along = left > 0.0f ? (f - hit.touchTime) / left : 1.0f;
    const b2Transform frame = body.At(f);
    return CarriedDisc{b2Mul(frame, hit.carryFrom + along * (hit.carryTo - hit.carryFrom)),
                       b2Mul(frame.q, b2MulT(body.after.q, hit.touch.normal))};
}

int WorldGeometry::CarryPieces(const SweepResult& hit) const
{
    return m_movingBodies[hit.movingBody].PiecesFrom(hit.touchTime);
}

bool WorldGeometry::MovingPassesOver(b2Vec2 point, const ParticleSide& side, float from) const
{
    ParticleSide core = side;
    core.radius = 0.25f * side.radius;
    SweepResult passed;
    return SweepMoving(point, point, core, from, passed, nullptr, LeavingTouch::counts);
}

bool WorldGeometry::MovingOverlapsDeeper(b2Vec2 point, const ParticleSide& side, float depth) const
{
    const float r = side.radius;
    const b2AABB query = PathBox(point, point, r);
    // A polygon lies behind each of its edges' lines, so a disc whose centre is `separation` in front of
    // one overlaps it by at most r - separation. The margin keeps rounding in the measured depth (edge
    // capsules, corners) from ever deciding differently than the measure would.
    const float clearlyShallow = r - depth + 1.0e-4f * r;
    bool deeper = false;
    m_movingGrid.Query(query,
                       [&](std::uint32_t index)
                       {
                           const MovingShape& moving = m_movingShapes[index];
                           if (deeper || !side.Accepts(moving.categoryBits, moving.maskBits) ||
                               !BoxesOverlap(query, m_movingBoxes[index]))
                           {
                               return;
                           }
                           const MovingBody& body = m_movingBodies[moving.body];
                           // A disc resting at `point` for the whole step that never comes within reach of
                           // the body's centre overlaps nothing of it at the end either.
                           if (!MayMeet(body, body.centerBefore, moving.reach, point, point, r))
                           {
                               return;
                           }
                           const SweepInput in{b2MulT(body.after, point), b2Vec2(0.0f, 0.0f), r};
                           if (moving.shape->GetType() == b2Shape::e_polygon)
                           {
                               const auto& polygon = static_cast<const b2PolygonShape&>(*moving.shape);
                               for (int i = 0; i < polygon.m_count; ++i)
                               {
                                   if (b2Dot(polygon.m_normals[i], in.p - polygon.m_vertices[i]) >=
                                       clearlyShallow)
                                   {
                                       return;
                                   }
                               }
                           }
                           Touch touch;
                           deeper = SweepShape(in, *moving.shape, moving.child, touch) && touch.t == 0.0f &&
                                    touch.depth > depth;
                       });
    return deeper;
}

} // namespace cfx::particles
