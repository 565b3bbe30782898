// contactfx internal: the edge of an edge fixture, or of one child of a chain.
#pragma once

#include <box2d/b2_chain_shape.h>
#include <box2d/b2_edge_shape.h>

namespace cfx::detail
{

/// For an edge shape, the edge itself; for a chain, its child `child` (one-sided, as Box2D makes it);
/// false for any other shape (then `edge` is left as it was). In the shape's own frame.
inline bool ChildEdge(const b2Shape& shape, int child, b2EdgeShape& edge)
{
    if (shape.GetType() == b2Shape::e_edge)
    {
        edge = static_cast<const b2EdgeShape&>(shape);
        return true;
    }
    if (shape.GetType() == b2Shape::e_chain)
    {
        static_cast<const b2ChainShape&>(shape).GetChildEdge(&edge, child);
        return true;
    }
    return false;
}

} // namespace cfx::detail
