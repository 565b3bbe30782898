#include "particles/particle_check.h"

#include "child_edge.h"
#include "particles/crossing.h"
#include "spawn_point.h"
#include "world_query.h"

#include <algorithm>
#include <box2d/b2_body.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_world.h>
#include <cmath>

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

// How deep (m) a point is inside the convex polygon: the least of its distances behind the edges' lines
// (negative outside).
float PolygonDepth(const b2PolygonShape& polygon, b2Vec2 point)
{
    float depth = b2_maxFloat;
    for (int i = 0; i < polygon.m_count; ++i)
    {
        depth = std::min(depth, -b2Dot(polygon.m_normals[i], point - polygon.m_vertices[i]));
    }
    return depth;
}

// The most a moving body turns (rad) between two points of a particle's path in its frame.
constexpr float kCheckTurn = 0.05f;
constexpr int kCheckPieces = 128;

// How deep (m) the path a -> b (in the shape's frame) goes into the shape at most, and where (0..1 along
// it). A polygon's depth along it is the least of one linear function per edge, so its largest is at an end
// or where two of those functions meet: each is tried.
struct Deepest
{
    float depth;
    float t;
};
Deepest DeepestOnSegment(const b2Shape& shape, b2Vec2 a, b2Vec2 b)
{
    if (shape.GetType() == b2Shape::e_circle)
    {
        const auto& circle = static_cast<const b2CircleShape&>(shape);
        const b2Vec2 d = b - a;
        const float lengthSq = b2Dot(d, d);
        const float u = lengthSq > 0.0f ? std::clamp(b2Dot(circle.m_p - a, d) / lengthSq, 0.0f, 1.0f) : 0.0f;
        return {circle.m_radius - b2Distance(a + u * d, circle.m_p), u};
    }
    const auto& polygon = static_cast<const b2PolygonShape&>(shape);
    const float atA = PolygonDepth(polygon, a);
    const float atB = PolygonDepth(polygon, b);
    Deepest deepest = atA >= atB ? Deepest{atA, 0.0f} : Deepest{atB, 1.0f};
    auto edgeDepth = [&](int i, b2Vec2 point)
    { return -b2Dot(polygon.m_normals[i], point - polygon.m_vertices[i]); };
    for (int i = 0; i < polygon.m_count; ++i)
    {
        for (int j = i + 1; j < polygon.m_count; ++j)
        {
            // Where edges i and j are equally deep: c + slopeI t = e + slopeJ t.
            const float c = edgeDepth(i, a), slopeI = edgeDepth(i, b) - c;
            const float e = edgeDepth(j, a), slopeJ = edgeDepth(j, b) - e;
            if (slopeI != slopeJ)
            {
                const float t = (e - c) / (slopeI - slopeJ);
                const float depth =
                    t > 0.0f && t < 1.0f ? PolygonDepth(polygon, a + t * (b - a)) : -b2_maxFloat;
                deepest = depth > deepest.depth ? Deepest{depth, t} : deepest;
            }
        }
    }
    return deepest;
}

// The outward normal of the shape's surface nearest a point outside it or on it: for a polygon, of the
// edge whose line the point is farthest in front of.
b2Vec2 OutwardNormal(const b2Shape& shape, b2Vec2 point)
{
    if (shape.GetType() == b2Shape::e_circle)
    {
        b2Vec2 away = point - static_cast<const b2CircleShape&>(shape).m_p;
        away.Normalize();
        return away;
    }
    const auto& polygon = static_cast<const b2PolygonShape&>(shape);
    int best = 0;
    for (int i = 1; i < polygon.m_count; ++i)
    {
        if (b2Dot(polygon.m_normals[i], point - polygon.m_vertices[i]) >
            b2Dot(polygon.m_normals[best], point - polygon.m_vertices[best]))
        {
            best = i;
        }
    }
    return polygon.m_normals[best];
}

// Where the path a -> b, `a` outside the shape, first comes onto it, when it does (else `b`). Its depth is
// concave along the path, so it crosses zero once before its deepest point: found by halving.
b2Vec2 Entry(const b2Shape& shape, b2Vec2 a, b2Vec2 b, const Deepest& deepest)
{
    float outside = 0.0f;
    float inside = deepest.t;
    for (int i = 0; i < 24; ++i)
    {
        const float t = 0.5f * (outside + inside);
        const b2Vec2 point = a + t * (b - a);
        (DeepestOnSegment(shape, point, point).depth >= 0.0f ? inside : outside) = t;
    }
    return a + outside * (b - a);
}

// Whether the particle went through the moving fixture deeper than `depth`, from outside it to outside it,
// seen from its body. The particle was at `start` when the step began, flew in a straight line at a
// constant speed towards `flown` (where its flight would have ended, when `pushed`, had no push begun at
// `fraction` of it; else `end`), and is at `end` now. The body's pose goes from the start of the step (as
// Box2D integrated it) to now as Box2D moves it (its centre along a line, its angle at a constant rate),
// followed in pieces of at most kCheckTurn.
// - Not pushed, its whole path in the body's frame is known: it must not go deeper than `depth`.
// - Pushed, the push's own path is not known. Where the flight came onto the body, the particle should
//   have stayed on that side of it: the path from there to where it ended (in the body's frame now) must
//   not cut deeper than `depth` through the body to a face turned away from that one (a slide around a
//   corner cuts the corner too, but comes out of a face beside the first). A push alone (no flight onto
//   this body: pushed by another) is tested from where it began.
bool PassedThrough(const b2Fixture& fixture, b2Vec2 start, b2Vec2 flown, b2Vec2 end, bool pushed,
                   float fraction, float depth, float dt)
{
    const b2Body& body = *fixture.GetBody();
    const b2Shape& shape = *fixture.GetShape();
    if (body.GetType() == b2_staticBody ||
        (shape.GetType() != b2Shape::e_circle && shape.GetType() != b2Shape::e_polygon))
    {
        return false; // edges and chains have no inside
    }
    const float turn = dt * body.GetAngularVelocity();
    const float angleBefore = body.GetAngle() - turn;
    const b2Vec2 centre = body.GetWorldCenter();
    const b2Vec2 centreBefore = centre - dt * body.GetLinearVelocity();
    auto frameAt = [&](float f)
    {
        b2Transform xf;
        xf.q.Set(angleBefore + f * turn);
        xf.p = centreBefore + f * (centre - centreBefore) - b2Mul(xf.q, body.GetLocalCenter());
        return xf;
    };
    const b2Vec2 last = b2MulT(body.GetTransform(), end);
    b2Vec2 from = b2MulT(frameAt(0.0f), start);
    if (DeepestOnSegment(shape, from, from).depth >= 0.0f ||
        DeepestOnSegment(shape, last, last).depth >= 0.0f)
    {
        return false; // started or ended inside: not a pass (an end inside counts as inside)
    }
    // Pushed, it flew only until the push began (`fraction` of the step and of the flight); no flight onto
    // the body before that: where the push began.
    const float until = pushed ? fraction : 1.0f;
    b2Vec2 entry = until >= 1.0f ? b2MulT(body.GetTransform(), flown)
                                 : b2MulT(frameAt(until), start + until * (flown - start));
    const int pieces =
        std::clamp(static_cast<int>(std::ceil(std::abs(until * turn) / kCheckTurn)), 1, kCheckPieces);
    for (int piece = 1; piece <= pieces; ++piece)
    {
        const float f = until * (static_cast<float>(piece) / static_cast<float>(pieces));
        const b2Vec2 to = piece == pieces ? entry : b2MulT(frameAt(f), start + f * (flown - start));
        const Deepest deepest = DeepestOnSegment(shape, from, to);
        if (!pushed && deepest.depth > depth)
        {
            return true; // its whole path is known: through the body
        }
        if (pushed && deepest.depth >= 0.0f)
        {
            entry = Entry(shape, from, to, deepest);
            break;
        }
        from = to;
    }
    if (!pushed)
    {
        return false;
    }
    // Across: out of a face turned away from the one it came onto (a plank's other side), by a path through
    // the body. A slide around a corner cuts the corner (a chord), but out of a face beside the first.
    constexpr float kAcross = -0.7f; // the faces' normals more than 134 degrees apart
    return b2Dot(OutwardNormal(shape, entry), OutwardNormal(shape, last)) < kAcross &&
           DeepestOnSegment(shape, entry, last).depth > depth;
}

} // namespace

void CheckParticles(const b2World& world, const PoolArrays& pool, const TypeStep* types, std::uint32_t count,
                    const BodyFilter* ignore, float dt, CheckCounts& counts)
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
        // Where its flight ended, when a moving body pushed it (its start, for a particle at rest), else the
        // end; and where along the flight the push began (where the flight met the body, or its end).
        const b2Vec2 via(pool.viaX[slot], pool.viaY[slot]);
        const bool pushed = (pool.stepFlags[slot] & kPushedFlag) != 0;
        const b2Vec2 flown = pushed ? via : end;
        const float fraction = pushed ? pool.pushFraction[slot] : 1.0f;
        // The path the step took: from the start to where the push began (the start itself when nothing
        // pushed it), then to the end. Its chord can cut an edge the particle went around (flown past the
        // edge's end, then pushed down beyond it).
        const b2Vec2 pushStart = fraction >= 1.0f ? via : start + fraction * (via - start);
        b2AABB box;
        box.lowerBound = b2Min(b2Min(start, via), end);
        box.upperBound = b2Max(b2Max(start, via), end);
        bool inside = false;
        bool crossed = false;
        bool passed = false;
        // Deeper than the radius, and than Box2D's linear slop: the body's pose at the start of the step
        // is taken from its velocity, and Box2D's position correction moves it by up to about that more.
        const float passDepth = type.side.radius + b2_linearSlop;
        // Spawned after the bodies moved, it was never where they passed: seen from the bodies as they are
        // now (a step of no time).
        const bool placedAfter = (pool.stepFlags[slot] & kPlacedAfterFlag) != 0;
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
                                                            (PathCrosses(*fixture, child, start, pushStart) ||
                                                             PathCrosses(*fixture, child, pushStart, end)));
                                      passed = passed ||
                                               PassedThrough(*fixture, start, flown, end, pushed, fraction,
                                                             passDepth, placedAfter ? 0.0f : dt);
                                  }
                                  return !(inside && crossed && passed);
                              });
        counts.inside += inside ? 1u : 0u;
        counts.crossings += crossed ? 1u : 0u;
        counts.passedThrough += passed ? 1u : 0u;
    }
}

} // namespace cfx::particles
