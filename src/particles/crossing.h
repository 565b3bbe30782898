// contactfx internal: whether a straight path crosses an edge, shared by the particle check and the static
// sweeps' crush test.
#pragma once

#include <box2d/b2_math.h>

namespace cfx::particles
{

/// Whether the path p -> q crosses the edge v1 -> v2: a two-sided edge from either side, a one-sided one only
/// from its front (right of v1 -> v2, Box2D's normal) to its back. Through a vertex counts (a path between
/// two segments of a chain crosses the chain); touching the edge's line or starting on it does not, nor
/// does ending on it unless `endOnEdgeCounts`: a particle's centre is never on a surface, so the particle
/// check counts it (far from the origin, where a float's spacing is millimetres, a particle could cross in
/// two steps, onto the line and off it, neither of them strictly across).
/// Computed in doubles: in floats, the side of a point 1 mm from the middle of a 200 km edge came out wrong.
inline bool PathCrossesEdge(b2Vec2 p, b2Vec2 q, b2Vec2 v1, b2Vec2 v2, bool oneSided,
                            bool endOnEdgeCounts = false)
{
    struct Point
    {
        double x, y;
    };
    const auto minus = [](b2Vec2 a, b2Vec2 b) {
        return Point{static_cast<double>(a.x) - b.x, static_cast<double>(a.y) - b.y};
    };
    const auto cross = [](Point a, Point b) { return a.x * b.y - a.y * b.x; };
    const Point e = minus(v2, v1);
    const double sideP = cross(minus(p, v1), e); // > 0: right of v1 -> v2, the front
    const double sideQ = cross(minus(q, v1), e);
    const bool endsOn = endOnEdgeCounts && sideQ == 0.0 && (oneSided ? sideP > 0.0 : sideP != 0.0);
    const bool opposite = endsOn || (oneSided ? (sideP > 0.0 && sideQ < 0.0) : (sideP * sideQ < 0.0));
    if (!opposite)
    {
        return false;
    }
    const Point d = minus(q, p);
    return cross(minus(v1, p), d) * cross(minus(v2, p), d) <= 0.0;
}

} // namespace cfx::particles
