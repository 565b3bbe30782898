// contactfx internal: disc sweeps against segments, circles and convex polygons (see sweep.h).
//
// Every test first asks the cheapest question that can say "no" (does the disc ever come within r of
// the segment's line; is the ray moving away from the circle), because nearly all candidate shapes a
// particle meets in a grid cell are misses.
#include "particles/sweep.h"

#include <algorithm>
#include <cmath>

namespace cfx::particles
{

namespace
{

bool Earlier(float t, const Touch& best)
{
    return t < best.t;
}

bool Deeper(float depth, const Touch& best)
{
    return best.t > 0.0f || depth > best.depth;
}

bool Overlap(b2Vec2 position, b2Vec2 normal, float depth, Touch& best)
{
    if (!Deeper(depth, best))
    {
        return false;
    }
    best.t = 0.0f;
    best.depth = depth;
    best.normal = normal;
    best.position = position;
    return true;
}

bool Hit(float t, b2Vec2 position, b2Vec2 normal, Touch& best)
{
    if (!Earlier(t, best))
    {
        return false;
    }
    best.t = t;
    best.depth = 0.0f;
    best.normal = normal;
    best.position = position;
    return true;
}

} // namespace

Segment MakeSegment(b2Vec2 v1, b2Vec2 v2, bool oneSided)
{
    const b2Vec2 e = v2 - v1;
    const float lengthSq = b2Dot(e, e);
    const float length = std::sqrt(lengthSq);
    Segment segment;
    segment.v1 = v1;
    segment.v2 = v2;
    segment.normal = length > 0.0f ? b2Vec2(e.y / length, -e.x / length) : b2Vec2(0.0f, 1.0f);
    segment.invLengthSq = lengthSq > 0.0f ? 1.0f / lengthSq : 0.0f;
    segment.oneSided = oneSided;
    return segment;
}

bool SweepCircle(const SweepInput& in, b2Vec2 center, float radius, Touch& best)
{
    const float grown = radius + in.radius;
    const b2Vec2 m = in.p - center;
    const float mm = b2Dot(m, m);
    const float touching = grown - kTouchSlop;
    if (mm < touching * touching)
    {
        const float distance = std::sqrt(mm);
        const b2Vec2 normal = distance > b2_epsilon ? (1.0f / distance) * m : b2Vec2(0.0f, 1.0f);
        return Overlap(center + grown * normal, normal, grown - distance, best);
    }
    const float b = b2Dot(m, in.d);
    if (b >= 0.0f)
    {
        return false; // moving away or along
    }
    // From the point of the path closest to the centre, back by half the chord. Not the quadratic's
    // discriminant b^2 - |d|^2 (|m|^2 - grown^2): for a path much longer than the radius its two terms
    // cancel to their rounding (a disc falling at 500 m/s 1.3 mm beside a ground's vertex touched that
    // vertex's cap before the face under it, and bounced off 14 degrees from the vertical).
    const float dd = b2Dot(in.d, in.d);
    const float closestT = -b / dd;
    const b2Vec2 closest = m + closestT * in.d;
    const float missBy = grown * grown - b2Dot(closest, closest);
    if (missBy < 0.0f)
    {
        return false;
    }
    const float t = std::max(0.0f, closestT - std::sqrt(missBy / dd));
    if (t > 1.0f || !Earlier(t, best))
    {
        return false;
    }
    const b2Vec2 position = in.p + t * in.d;
    b2Vec2 normal = position - center;
    normal.Normalize();
    return Hit(t, position, normal, best);
}

bool SweepSegment(const SweepInput& in, const Segment& segment, Touch& best)
{
    b2Vec2 normal = segment.normal;
    const b2Vec2 fromV1 = in.p - segment.v1;
    float s = b2Dot(fromV1, normal);
    float ds = b2Dot(in.d, normal);
    if (s < 0.0f)
    {
        if (segment.oneSided)
        {
            return false; // behind a one-sided segment: not solid from here
        }
        normal = -normal;
        s = -s;
        ds = -ds;
    }
    const float r = in.radius;
    if (s >= r && s + ds >= r)
    {
        return false; // never comes within r of the line
    }
    const b2Vec2 e = segment.v2 - segment.v1;
    if (s < r - kTouchSlop)
    {
        const float u = b2Dot(fromV1, e) * segment.invLengthSq;
        if (u >= 0.0f && u <= 1.0f)
        {
            return Overlap(in.p + (r - s) * normal, normal, r - s, best);
        }
        return SweepCircle(in, u < 0.0f ? segment.v1 : segment.v2, 0.0f, best);
    }
    if (ds >= 0.0f)
    {
        return false; // touching (within the slop) and not moving closer
    }
    const float t = std::max(0.0f, (s - r) / -ds);
    if (!Earlier(t, best))
    {
        return false;
    }
    const b2Vec2 position = in.p + t * in.d;
    const float u = b2Dot(position - segment.v1, e) * segment.invLengthSq;
    if (u >= 0.0f && u <= 1.0f)
    {
        return Hit(t, position, normal, best);
    }
    return SweepCircle(in, u < 0.0f ? segment.v1 : segment.v2, 0.0f, best);
}

namespace
{

// The rounded polygon as the union of its edges' capsules: exact from outside, used where the fast
// clipping test cannot decide (corner regions).
bool SweepEdges(const SweepInput& in, const b2Vec2* vertices, int count, Touch& best)
{
    bool found = false;
    for (int i = 0; i < count; ++i)
    {
        const int next = i + 1 < count ? i + 1 : 0;
        found = SweepSegment(in, MakeSegment(vertices[i], vertices[next], true), best) || found;
    }
    return found;
}

} // namespace

bool SweepPolygon(const SweepInput& in, const b2Vec2* vertices, const b2Vec2* normals, int count, Touch& best)
{
    // Clip the ray against every edge's line moved out by r (Box2D's polygon ray cast, grown).
    const float r = in.radius;
    float lower = 0.0f;
    float upper = 1.0f;
    int entry = -1;
    float maxSeparation = -b2_maxFloat;
    int maxIndex = 0;
    for (int i = 0; i < count; ++i)
    {
        const float separation = b2Dot(normals[i], in.p - vertices[i]);
        if (separation > maxSeparation)
        {
            maxSeparation = separation;
            maxIndex = i;
        }
        const float numerator = r - separation;
        const float denominator = b2Dot(normals[i], in.d);
        if (denominator == 0.0f)
        {
            if (numerator < 0.0f)
            {
                return false;
            }
        }
        else if (denominator < 0.0f)
        {
            if (numerator < lower * denominator)
            {
                lower = numerator / denominator;
                entry = i;
            }
        }
        else if (numerator < upper * denominator)
        {
            upper = numerator / denominator;
        }
        if (upper < lower)
        {
            return false;
        }
    }
    if (entry < 0)
    {
        // Starts inside the grown polygon with square corners.
        const b2Vec2 normal = normals[maxIndex];
        if (maxSeparation <= 0.0f)
        {
            const float depth = r - maxSeparation;
            return Overlap(in.p + depth * normal, normal, depth, best);
        }
        if (maxSeparation >= r - kTouchSlop)
        {
            // Touching the line of edge maxIndex from outside: the convex polygon lies behind it, so a
            // disc not moving closer to that line stays clear of the whole polygon.
            if (b2Dot(normal, in.d) >= 0.0f)
            {
                return false;
            }
            const int next = maxIndex + 1 < count ? maxIndex + 1 : 0;
            const b2Vec2 e = vertices[next] - vertices[maxIndex];
            const float u = b2Dot(in.p - vertices[maxIndex], e);
            if (u >= 0.0f && u <= b2Dot(e, e))
            {
                return Earlier(0.0f, best) && Hit(0.0f, in.p, normal, best);
            }
        }
        return SweepEdges(in, vertices, count, best);
    }
    if (!Earlier(lower, best))
    {
        return false;
    }
    const b2Vec2 position = in.p + lower * in.d;
    const int next = entry + 1 < count ? entry + 1 : 0;
    const b2Vec2 e = vertices[next] - vertices[entry];
    const float u = b2Dot(position - vertices[entry], e);
    if (u >= 0.0f && u <= b2Dot(e, e))
    {
        return Hit(lower, position, normals[entry], best);
    }
    return SweepEdges(in, vertices, count, best);
}

b2Vec2 Respond(b2Vec2 velocity, float touchSpeed, b2Vec2 normal, const SurfaceResponse& surface)
{
    const b2Vec2 relative = velocity - surface.velocity;
    const float approach = b2Dot(relative, normal);
    if (approach >= 0.0f)
    {
        return velocity;
    }
    const b2Vec2 tangential = relative - approach * normal;
    const float bounce = touchSpeed > surface.restSpeed ? surface.restitution * touchSpeed : 0.0f;
    const float normalChange = bounce - approach; // > 0
    const float slide = tangential.Length();
    const b2Vec2 tangentialAfter =
        slide > 0.0f ? SlideLeft(slide, surface.friction * normalChange) * tangential : b2Vec2(0.0f, 0.0f);
    return surface.velocity + tangentialAfter + bounce * normal;
}

} // namespace cfx::particles
