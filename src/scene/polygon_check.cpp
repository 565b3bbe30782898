#include "scene/polygon_check.h"

#include <box2d/b2_common.h>
#include <box2d/b2_settings.h>
#include <cmath>

namespace cfx::scene_detail
{

namespace
{

// Margins over Box2D's own thresholds, so that rounding can never turn an accepted shape into an assert.
constexpr float kDistanceMargin = 1.001f;
constexpr float kCollinearTolerance = 1.0e-5f; // |sin| of the angle between two edges from one vertex
constexpr float kMinArea = 4.0f * b2_epsilon;  // Box2D asserts area > b2_epsilon

std::string Index(int i)
{
    return std::to_string(i);
}

/// Box2D's gift wrapping (b2PolygonShape::Set) on vertices that need no welding, bounded so that it stops
/// instead of overrunning. The number of hull vertices, or -1 when the walk does not close.
int GiftWrap(std::span<const b2Vec2> ps, int* hull)
{
    const int n = static_cast<int>(ps.size());
    int i0 = 0;
    float x0 = ps[0].x;
    for (int i = 1; i < n; ++i)
    {
        const float x = ps[static_cast<std::size_t>(i)].x;
        if (x > x0 || (x == x0 && ps[static_cast<std::size_t>(i)].y < ps[static_cast<std::size_t>(i0)].y))
        {
            i0 = i;
            x0 = x;
        }
    }
    int m = 0;
    int ih = i0;
    for (;;)
    {
        if (m >= n)
        {
            return -1;
        }
        hull[m] = ih;
        const b2Vec2 current = ps[static_cast<std::size_t>(ih)];
        int ie = 0;
        for (int j = 1; j < n; ++j)
        {
            if (ie == ih)
            {
                ie = j;
                continue;
            }
            const b2Vec2 r = ps[static_cast<std::size_t>(ie)] - current;
            const b2Vec2 v = ps[static_cast<std::size_t>(j)] - current;
            const float c = b2Cross(r, v);
            if (c < 0.0f)
            {
                ie = j;
            }
            if (c == 0.0f && v.LengthSquared() > r.LengthSquared())
            {
                ie = j;
            }
        }
        ++m;
        ih = ie;
        if (ie == i0)
        {
            break;
        }
    }
    return m;
}

} // namespace

std::optional<std::string> CheckPolygon(std::span<const b2Vec2> vertices)
{
    const int n = static_cast<int>(vertices.size());
    if (n < 3)
    {
        return "a polygon needs 3 to " + Index(b2_maxPolygonVertices) + " vertices (2 make an edge), found " +
               Index(n);
    }
    if (n > b2_maxPolygonVertices)
    {
        return "a polygon has at most " + Index(b2_maxPolygonVertices) +
               " vertices (b2_maxPolygonVertices), found " + Index(n);
    }
    const float weld = (0.5f * b2_linearSlop) * (0.5f * b2_linearSlop) * kDistanceMargin;
    for (int i = 0; i < n; ++i)
    {
        for (int j = i + 1; j < n; ++j)
        {
            if (b2DistanceSquared(vertices[static_cast<std::size_t>(i)],
                                  vertices[static_cast<std::size_t>(j)]) < weld)
            {
                return "vertices " + Index(i) + " and " + Index(j) +
                       " are closer than b2_linearSlop/2 (0.0025): Box2D would merge them";
            }
        }
    }
    for (int i = 0; i < n; ++i)
    {
        for (int j = i + 1; j < n; ++j)
        {
            for (int k = j + 1; k < n; ++k)
            {
                const b2Vec2 a = vertices[static_cast<std::size_t>(i)];
                const b2Vec2 e1 = vertices[static_cast<std::size_t>(j)] - a;
                const b2Vec2 e2 = vertices[static_cast<std::size_t>(k)] - a;
                if (std::fabs(b2Cross(e1, e2)) <= kCollinearTolerance * e1.Length() * e2.Length())
                {
                    return "vertices " + Index(i) + ", " + Index(j) + " and " + Index(k) +
                           " are collinear (degenerate polygon)";
                }
            }
        }
    }
    int hull[b2_maxPolygonVertices] = {};
    const int hullCount = GiftWrap(vertices, hull);
    if (hullCount < 0)
    {
        return "not convex";
    }
    if (hullCount != n)
    {
        bool onHull[b2_maxPolygonVertices] = {};
        for (int i = 0; i < hullCount; ++i)
        {
            onHull[hull[i]] = true;
        }
        for (int i = 0; i < n; ++i)
        {
            if (!onHull[i])
            {
                return "not convex: vertex " + Index(i) + " lies inside the convex hull of the others";
            }
        }
        return "not convex";
    }
    // Area as b2PolygonShape computes it for the centroid and the mass, on the hull in Box2D's order.
    float area = 0.0f;
    const b2Vec2 s = vertices[static_cast<std::size_t>(hull[0])];
    for (int i = 0; i < n; ++i)
    {
        const b2Vec2 e1 = vertices[static_cast<std::size_t>(hull[i])] - s;
        const b2Vec2 e2 = vertices[static_cast<std::size_t>(hull[i + 1 < n ? i + 1 : 0])] - s;
        area += 0.5f * b2Cross(e1, e2);
    }
    if (!(area > kMinArea))
    {
        return "area " + std::to_string(area) + " is too small (degenerate polygon)";
    }
    return std::nullopt;
}

std::optional<std::string> CheckEdge(b2Vec2 vertex1, b2Vec2 vertex2)
{
    if (b2DistanceSquared(vertex1, vertex2) <= b2_linearSlop * b2_linearSlop * kDistanceMargin)
    {
        return "the two vertices are closer than b2_linearSlop (0.005): degenerate edge";
    }
    return std::nullopt;
}

std::optional<std::string> CheckChain(std::span<const b2Vec2> vertices, bool loop)
{
    const int n = static_cast<int>(vertices.size());
    const int minimum = loop ? 3 : 2;
    if (n < minimum)
    {
        return std::string(loop ? "a loop" : "a chain") + " needs at least " + Index(minimum) +
               " vertices, found " + Index(n);
    }
    const float limit = b2_linearSlop * b2_linearSlop * kDistanceMargin;
    for (int i = 1; i < n; ++i)
    {
        if (b2DistanceSquared(vertices[static_cast<std::size_t>(i - 1)],
                              vertices[static_cast<std::size_t>(i)]) <= limit)
        {
            return "vertices " + Index(i - 1) + " and " + Index(i) +
                   " are closer than b2_linearSlop (0.005): Box2D needs distinct consecutive vertices";
        }
    }
    if (loop && b2DistanceSquared(vertices[static_cast<std::size_t>(n - 1)], vertices[0]) <= limit)
    {
        return "the last and first vertices of the loop are closer than b2_linearSlop (0.005)";
    }
    return std::nullopt;
}

} // namespace cfx::scene_detail
