// Shape checks that keep Box2D's asserts from firing, and the vertices Box2D drops.
#include "scene/polygon_check.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <vector>

namespace cfx::scene_detail
{
namespace
{

bool Accepted(const std::vector<b2Vec2>& vertices)
{
    const PolygonCheck check = CheckPolygon(vertices);
    return !check.error && check.dropped.empty() && check.kept == static_cast<int>(vertices.size());
}

std::string Error(const std::vector<b2Vec2>& vertices)
{
    return CheckPolygon(vertices).error.value_or("(accepted)");
}

TEST(CheckPolygon, AcceptsConvexPolygonsInAnyOrder)
{
    EXPECT_TRUE(Accepted({{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
    EXPECT_TRUE(Accepted({{0, 0}, {0, 1}, {1, 1}, {1, 0}}));
    EXPECT_TRUE(Accepted({{0, 0}, {1, 1}, {1, 0}, {0, 1}})); // Box2D wraps the hull itself
    std::vector<b2Vec2> octagon;
    for (int i = 0; i < 8; ++i)
    {
        const float angle = static_cast<float>(i) * b2_pi / 4.0f;
        octagon.emplace_back(std::cos(angle), std::sin(angle));
    }
    EXPECT_TRUE(Accepted(octagon));
    EXPECT_TRUE(Accepted({{0, 0}, {0.003f, 0}, {0, 0.003f}})); // small but fine for Box2D
}

TEST(CheckPolygon, RejectsWrongVertexCounts)
{
    EXPECT_NE(Error({{0, 0}}).find("found 1"), std::string::npos);
    std::vector<b2Vec2> nine;
    for (int i = 0; i < 9; ++i)
    {
        const float angle = static_cast<float>(i) * 2.0f * b2_pi / 9.0f;
        nine.emplace_back(std::cos(angle), std::sin(angle));
    }
    EXPECT_NE(Error(nine).find("found 9"), std::string::npos);
}

TEST(CheckPolygon, RejectsWhatBox2DAssertsOn)
{
    EXPECT_NE(Error({{0, 0}, {1, 0}, {2, 0}}).find("collinear"), std::string::npos);
    EXPECT_NE(Error({{0, 0}, {1, 0}, {2, 0}, {3, 0}}).find("collinear"), std::string::npos);
    // Two vertices left after welding.
    EXPECT_NE(Error({{0, 0}, {1, 0}, {1.001f, 0.001f}}).find("only 2 vertices are left"), std::string::npos);
    // Distinct and not exactly collinear, but the area is not above b2_epsilon.
    EXPECT_NE(Error({{0, 0}, {0.01f, 0}, {0.005f, 1e-6f}}).find("area"), std::string::npos);
}

TEST(CheckPolygon, AcceptsWhatBox2DAcceptsAndNamesDroppedVertices)
{
    // Box2D drops the midpoint of an edge (exactly collinear) and keeps a triangle.
    PolygonCheck midpoint = CheckPolygon(std::vector<b2Vec2>{{0, 0}, {1, 0}, {2, 0}, {1, 1}});
    EXPECT_FALSE(midpoint.error);
    EXPECT_EQ(midpoint.kept, 3);
    ASSERT_EQ(midpoint.dropped.size(), 1U);
    EXPECT_NE(midpoint.dropped[0].find("vertex 1 is not a corner"), std::string::npos);

    // A vertex within b2_linearSlop/2 of an earlier one is welded to it.
    PolygonCheck welded = CheckPolygon(std::vector<b2Vec2>{{0, 0}, {1, 0}, {1, 1}, {1.001f, 1.0f}});
    EXPECT_FALSE(welded.error);
    EXPECT_EQ(welded.kept, 3);
    ASSERT_EQ(welded.dropped.size(), 1U);
    EXPECT_NE(welded.dropped[0].find("vertex 3 is closer than b2_linearSlop/2 (0.0025) to vertex 2"),
              std::string::npos);

    // A non-convex outline becomes its hull: the inner vertex is dropped.
    PolygonCheck arrow = CheckPolygon(std::vector<b2Vec2>{{0, 0}, {2, 1}, {0, 2}, {0.5f, 1}});
    EXPECT_FALSE(arrow.error);
    ASSERT_EQ(arrow.dropped.size(), 1U);
    EXPECT_NE(arrow.dropped[0].find("vertex 3 is not a corner"), std::string::npos);

    // Thin but with an area above b2_epsilon: Box2D builds it.
    EXPECT_TRUE(Accepted({{0, 0}, {1, 0}, {0.5f, 1e-6f}}));
}

// netonjm/RubeLoader's tank.json, body[24] fixtures 5 and 8: three vertices nearly on a line, which an
// earlier check refused as collinear; Box2D 2.4.1 builds 4-vertex hulls from both.
TEST(CheckPolygon, AcceptsTheNearlyCollinearPolygonsOfARealTank)
{
    const char* kPolygons[] = {
        R"({"x": [-2.010097503662109, -2.158888339996338, -2.594896554946899, -2.669627189636231],
            "y": [1.390945672988892, 1.390349745750427, 1.388603448867798, 1.257031798362732]})",
        R"({"x": [1.401737928390503, 1.297484159469605, 1.115253567695618, -0.5285210609436035],
            "y": [1.228543758392334, 1.404193162918091, 1.403463363647461, 1.39687967300415]})",
    };
    for (const char* text : kPolygons)
    {
        const nlohmann::json polygon = nlohmann::json::parse(text);
        std::vector<b2Vec2> vertices;
        for (std::size_t i = 0; i < polygon["x"].size(); ++i)
        {
            // As the reader converts them: double, then float.
            vertices.emplace_back(static_cast<float>(polygon["x"][i].get<double>()),
                                  static_cast<float>(polygon["y"][i].get<double>()));
        }
        const PolygonCheck check = CheckPolygon(vertices);
        EXPECT_FALSE(check.error) << *check.error;
        EXPECT_EQ(check.kept, 4);
        EXPECT_TRUE(check.dropped.empty());
    }
}

TEST(CheckEdgeAndChain, RequireDistinctVertices)
{
    EXPECT_FALSE(CheckEdge(b2Vec2(0, 0), b2Vec2(1, 0)));
    EXPECT_TRUE(CheckEdge(b2Vec2(0, 0), b2Vec2(0.001f, 0)));

    const std::vector<b2Vec2> chain = {{0, 0}, {1, 0}, {2, 1}};
    EXPECT_FALSE(CheckChain(chain, false));
    EXPECT_FALSE(CheckChain(chain, true));
    const std::vector<b2Vec2> single = {{0, 0}};
    EXPECT_TRUE(CheckChain(single, false));
    const std::vector<b2Vec2> two = {{0, 0}, {1, 0}};
    EXPECT_TRUE(CheckChain(two, true));
    const std::vector<b2Vec2> repeated = {{0, 0}, {1, 0}, {1, 0}, {2, 0}};
    ASSERT_TRUE(CheckChain(repeated, false));
    EXPECT_NE(CheckChain(repeated, false)->find("vertices 1 and 2"), std::string::npos);
    const std::vector<b2Vec2> closed = {{0, 0}, {1, 0}, {1, 1}, {0, 0.001f}};
    EXPECT_FALSE(CheckChain(closed, false));
    EXPECT_TRUE(CheckChain(closed, true));
}

} // namespace
} // namespace cfx::scene_detail
