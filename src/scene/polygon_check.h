// Shape checks done before Box2D sees the vertices.
//
// Box2D 2.4.1 asserts (or silently replaces the shape with a 1x1 box) on degenerate input, and its library
// is built with asserts on. b2PolygonShape::Set welds vertices closer than b2_linearSlop/2 to one kept
// before them, wraps the rest in a convex hull (gift wrapping, dropping points inside the hull or on its
// edges) and asserts when fewer than 3 vertices remain, when the walk does not close within
// b2_maxPolygonVertices, on an edge of (nearly) zero length or when the area is not above b2_epsilon.
// CheckPolygon runs the same rules with the same float operations, so that it accepts exactly the polygons
// Box2D accepts (tests/scene/polygon_parity_test.cpp compares the two on every polygon we have), says what
// is wrong in words where Box2D would assert, and names each vertex Box2D drops (a warning: the shape is
// still valid, but not the one of the file). b2ChainShape asserts on consecutive vertices closer than
// b2_linearSlop; CheckEdge and CheckChain check that (with a small safety margin).
#pragma once

#include <box2d/b2_math.h>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace cfx::scene_detail
{

/// What b2PolygonShape::Set makes of a vertex list.
struct PolygonCheck
{
    /// Why Box2D would assert or build a degenerate shape (not 3..8 vertices, fewer than 3 left after
    /// welding, all on a line, an area not above b2_epsilon, a hull that fails b2PolygonShape::Validate);
    /// nothing when Set accepts the vertices.
    std::optional<std::string> error;
    /// One message per vertex Box2D drops (welded to an earlier vertex, or not a corner of the convex hull),
    /// in vertex order. Only filled when there is no error.
    std::vector<std::string> dropped;
    /// How many vertices the Box2D polygon keeps (0 on an error).
    int kept = 0;
};

PolygonCheck CheckPolygon(std::span<const b2Vec2> vertices);

/// Nothing when the two vertices of an edge are farther apart than b2_linearSlop.
std::optional<std::string> CheckEdge(b2Vec2 vertex1, b2Vec2 vertex2);

/// Nothing when b2ChainShape::CreateChain (or CreateLoop when `loop`) accepts the vertices: at least 2
/// (3 for a loop) and consecutive vertices (the closing pair too for a loop) farther apart than
/// b2_linearSlop.
std::optional<std::string> CheckChain(std::span<const b2Vec2> vertices, bool loop);

} // namespace cfx::scene_detail
