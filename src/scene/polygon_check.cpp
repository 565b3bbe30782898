#include "scene/polygon_check.h"

#include <box2d/b2_common.h>
#include <box2d/b2_settings.h>
#include <cmath>
#include <cstdio>

namespace cfx::scene_detail
{

namespace
{

// Margin over Box2D's chain and edge thresholds, so that rounding can never turn an accepted shape into an
// assert. Polygons need none: CheckPolygon computes what Set computes.
constexpr float kDistanceMargin = 1.001f;
// Set welds a vertex closer than this (squared) to a vertex kept before it.
constexpr float kWeldDistanceSquared = (0.5f * b2_linearSlop) * (0.5f * b2_linearSlop);

std::string Index(int i)
{
    return std::to_string(i);
}

std::string Number(float value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(value));
    return buffer;
}

/// The convex hull walk of b2PolygonShape::Set over `points`: start at the right-most point (lowest of
/// equals), then repeatedly take the point with every other point on its left (the farthest of exactly
/// collinear ones). Box2D asserts when a walk reaches b2_maxPolygonVertices points without coming back to
/// the start; so does this (-1). Otherwise the number of hull points, their indices in `hull`.
int WrapHull(std::span<const b2Vec2> points, int (&hull)[b2_maxPolygonVertices])
{
    const int count = static_cast<int>(points.size());
    auto at = [&](int i) { return points[static_cast<std::size_t>(i)]; };
    int start = 0;
    for (int i = 1; i < count; ++i)
    {
        if (at(i).x > at(start).x || (at(i).x == at(start).x && at(i).y < at(start).y))
        {
            start = i;
        }
    }
    int size = 0;
    int current = start;
    while (true)
    {
        if (size >= b2_maxPolygonVertices)
        {
            return -1;
        }
        hull[size] = current;
        int next = 0;
        for (int candidate = 1; candidate < count; ++candidate)
        {
            if (next == current)
            {
                next = candidate;
                continue;
            }
            const b2Vec2 toNext = at(next) - at(current);
            const b2Vec2 toCandidate = at(candidate) - at(current);
            const float turn = b2Cross(toNext, toCandidate);
            if (turn < 0.0f || (turn == 0.0f && toCandidate.LengthSquared() > toNext.LengthSquared()))
            {
                next = candidate;
            }
        }
        ++size;
        current = next;
        if (current == start)
        {
            return size;
        }
    }
}

/// The area as ComputeCentroid sums it (triangles fanned from the first vertex).
float FanArea(std::span<const b2Vec2> polygon)
{
    const std::size_t count = polygon.size();
    const b2Vec2 origin = polygon[0];
    float area = 0.0f;
    for (std::size_t i = 0; i < count; ++i)
    {
        const b2Vec2 first = polygon[0] - origin;
        const b2Vec2 second = polygon[i] - origin;
        const b2Vec2 third = (i + 1 < count ? polygon[i + 1] : polygon[0]) - origin;
        area += 0.5f * b2Cross(second - first, third - first);
    }
    return area;
}

} // namespace

PolygonCheck CheckPolygon(std::span<const b2Vec2> vertices)
{
    PolygonCheck result;
    const int n = static_cast<int>(vertices.size());
    if (n < 3)
    {
        result.error = "a polygon needs 3 to " + Index(b2_maxPolygonVertices) +
                       " vertices (2 make an edge), found " + Index(n);
        return result;
    }
    if (n > b2_maxPolygonVertices)
    {
        result.error = "a polygon has at most " + Index(b2_maxPolygonVertices) +
                       " vertices (b2_maxPolygonVertices), found " + Index(n);
        return result;
    }

    // Welding: a vertex within b2_linearSlop/2 of one kept before it is dropped.
    std::vector<std::string> dropped(static_cast<std::size_t>(n));
    b2Vec2 kept[b2_maxPolygonVertices];
    int keptIndex[b2_maxPolygonVertices] = {};
    int keptCount = 0;
    for (int i = 0; i < n; ++i)
    {
        const b2Vec2 vertex = vertices[static_cast<std::size_t>(i)];
        int weldedTo = -1;
        for (int k = 0; k < keptCount && weldedTo < 0; ++k)
        {
            if (b2DistanceSquared(vertex, kept[k]) < kWeldDistanceSquared)
            {
                weldedTo = keptIndex[k];
            }
        }
        if (weldedTo >= 0)
        {
            dropped[static_cast<std::size_t>(i)] =
                "vertex " + Index(i) + " is closer than b2_linearSlop/2 (0.0025) to vertex " +
                Index(weldedTo) + ": Box2D welds them and drops vertex " + Index(i);
            continue;
        }
        kept[keptCount] = vertex;
        keptIndex[keptCount] = i;
        ++keptCount;
    }
    if (keptCount < 3)
    {
        result.error = "only " + Index(keptCount) +
                       " vertices are left after welding those closer than b2_linearSlop/2 (0.0025): "
                       "degenerate polygon (Box2D asserts)";
        return result;
    }

    int hull[b2_maxPolygonVertices] = {};
    const std::span<const b2Vec2> points(kept, static_cast<std::size_t>(keptCount));
    const int hullCount = WrapHull(points, hull);
    if (hullCount < 0)
    {
        result.error = "the convex hull of the vertices does not close (degenerate polygon, Box2D asserts)";
        return result;
    }
    if (hullCount < 3)
    {
        result.error = "the vertices are collinear: the convex hull has " + Index(hullCount) +
                       " corners (degenerate polygon, Box2D asserts)";
        return result;
    }
    b2Vec2 polygon[b2_maxPolygonVertices];
    for (int i = 0; i < hullCount; ++i)
    {
        polygon[i] = kept[hull[i]];
    }
    const std::span<const b2Vec2> corners(polygon, static_cast<std::size_t>(hullCount));
    for (int i = 0; i < hullCount; ++i)
    {
        const int next = i + 1 < hullCount ? i + 1 : 0;
        if (!((polygon[next] - polygon[i]).LengthSquared() > b2_epsilon * b2_epsilon))
        {
            result.error = "the hull edge from vertex " + Index(keptIndex[hull[i]]) + " to vertex " +
                           Index(keptIndex[hull[next]]) +
                           " has zero length (degenerate polygon, Box2D asserts)";
            return result;
        }
    }
    const float area = FanArea(corners);
    if (!(area > b2_epsilon))
    {
        result.error = "area " + Number(area) + " m^2 is not above b2_epsilon (" + Number(b2_epsilon) +
                       "): degenerate polygon (Box2D asserts)";
        return result;
    }
    // b2PolygonShape::Validate: every corner on the inner side of every edge it is not on.
    for (int i = 0; i < hullCount; ++i)
    {
        const int next = i + 1 < hullCount ? i + 1 : 0;
        const b2Vec2 edge = polygon[next] - polygon[i];
        for (int j = 0; j < hullCount; ++j)
        {
            if (j != i && j != next && b2Cross(edge, polygon[j] - polygon[i]) < 0.0f)
            {
                result.error = "vertex " + Index(keptIndex[hull[j]]) +
                               " lies outside the hull edge from vertex " + Index(keptIndex[hull[i]]) +
                               " to vertex " + Index(keptIndex[hull[next]]) +
                               " in float arithmetic (b2PolygonShape::Validate fails: degenerate polygon)";
                return result;
            }
        }
    }

    bool onHull[b2_maxPolygonVertices] = {};
    for (int i = 0; i < hullCount; ++i)
    {
        onHull[hull[i]] = true;
    }
    for (int k = 0; k < keptCount; ++k)
    {
        if (!onHull[k])
        {
            const int i = keptIndex[k];
            dropped[static_cast<std::size_t>(i)] =
                "vertex " + Index(i) +
                " is not a corner of the convex hull (inside it, or on an edge between two corners): Box2D "
                "drops it";
        }
    }
    for (std::string& message : dropped)
    {
        if (!message.empty())
        {
            result.dropped.push_back(std::move(message));
        }
    }
    result.kept = hullCount;
    return result;
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
