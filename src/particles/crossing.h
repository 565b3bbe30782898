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
inline bool PathCrossesEdge(b2Vec2 p, b2Vec2 q, b2Vec2 v1, b2Vec2 v2, bool oneSided,
                            bool endOnEdgeCounts = false)
{
    const auto cross = [](b2Vec2 a, b2Vec2 b) { return a.x * b.y - a.y * b.x; };
    const b2Vec2 e = v2 - v1;
    const float sideP = cross(p - v1, e); // > 0: right of v1 -> v2, the front
    const float sideQ = cross(q - v1, e);
    const bool endsOn = endOnEdgeCounts && sideQ == 0.0f && (oneSided ? sideP > 0.0f : sideP != 0.0f);
    const bool opposite = endsOn || (oneSided ? (sideP > 0.0f && sideQ < 0.0f) : (sideP * sideQ < 0.0f));
    if (!opposite)
    {
        return false;
    }
    const b2Vec2 d = q - p;
    return cross(v1 - p, d) * cross(v2 - p, d) <= 0.0f;
}

} // namespace cfx::particles
