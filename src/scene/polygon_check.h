// Shape checks done before Box2D sees the vertices.
//
// Box2D 2.4.1 asserts (or silently replaces the shape with a 1x1 box) on degenerate input:
// b2PolygonShape::Set welds vertices closer than b2_linearSlop/2, wraps the rest in a convex hull and asserts
// when fewer than 3 remain or the area is tiny; b2ChainShape asserts on consecutive vertices closer than
// b2_linearSlop. These checks run the same computations first (with a small safety margin) and say what is
// wrong in words, so that a polygon Box2D accepts is exactly the polygon of the file.
#pragma once

#include <box2d/b2_math.h>
#include <optional>
#include <span>
#include <string>

namespace cfx::scene_detail
{

/// Nothing when b2PolygonShape::Set keeps every vertex (3..8 vertices in convex position, no two closer
/// than b2_linearSlop/2, no three collinear, positive area); otherwise what is wrong.
std::optional<std::string> CheckPolygon(std::span<const b2Vec2> vertices);

/// Nothing when the two vertices of an edge are farther apart than b2_linearSlop.
std::optional<std::string> CheckEdge(b2Vec2 vertex1, b2Vec2 vertex2);

/// Nothing when b2ChainShape::CreateChain (or CreateLoop when `loop`) accepts the vertices: at least 2
/// (3 for a loop) and consecutive vertices (the closing pair too for a loop) farther apart than
/// b2_linearSlop.
std::optional<std::string> CheckChain(std::span<const b2Vec2> vertices, bool loop);

} // namespace cfx::scene_detail
