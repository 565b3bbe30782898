// Shape checks that keep Box2D's asserts from firing.
#include "scene/polygon_check.h"

#include <gtest/gtest.h>
#include <vector>

namespace cfx::scene_detail
{
namespace
{

TEST(CheckPolygon, AcceptsConvexPolygonsInAnyOrder)
{
    const std::vector<b2Vec2> box = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    EXPECT_FALSE(CheckPolygon(box));
    const std::vector<b2Vec2> clockwise = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    EXPECT_FALSE(CheckPolygon(clockwise));
    const std::vector<b2Vec2> scrambled = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
    EXPECT_FALSE(CheckPolygon(scrambled)); // Box2D wraps the hull itself
    std::vector<b2Vec2> octagon;
    for (int i = 0; i < 8; ++i)
    {
        const float angle = static_cast<float>(i) * b2_pi / 4.0f;
        octagon.emplace_back(std::cos(angle), std::sin(angle));
    }
    EXPECT_FALSE(CheckPolygon(octagon));
}

TEST(CheckPolygon, RejectsWrongVertexCounts)
{
    const std::vector<b2Vec2> one = {{0, 0}};
    ASSERT_TRUE(CheckPolygon(one));
    EXPECT_NE(CheckPolygon(one)->find("found 1"), std::string::npos);
    std::vector<b2Vec2> nine;
    for (int i = 0; i < 9; ++i)
    {
        const float angle = static_cast<float>(i) * 2.0f * b2_pi / 9.0f;
        nine.emplace_back(std::cos(angle), std::sin(angle));
    }
    ASSERT_TRUE(CheckPolygon(nine));
    EXPECT_NE(CheckPolygon(nine)->find("found 9"), std::string::npos);
}

TEST(CheckPolygon, RejectsDegenerateAndNonConvexPolygons)
{
    const std::vector<b2Vec2> collinear = {{0, 0}, {1, 0}, {2, 0}};
    ASSERT_TRUE(CheckPolygon(collinear));
    EXPECT_NE(CheckPolygon(collinear)->find("collinear"), std::string::npos);

    const std::vector<b2Vec2> midpoint = {{0, 0}, {1, 0}, {2, 0}, {1, 1}};
    ASSERT_TRUE(CheckPolygon(midpoint));

    const std::vector<b2Vec2> coincident = {{0, 0}, {1, 0}, {1, 1}, {1.001f, 1.0f}};
    ASSERT_TRUE(CheckPolygon(coincident));
    EXPECT_NE(CheckPolygon(coincident)->find("closer"), std::string::npos);

    const std::vector<b2Vec2> arrow = {{0, 0}, {2, 1}, {0, 2}, {0.5f, 1}};
    ASSERT_TRUE(CheckPolygon(arrow));
    EXPECT_NE(CheckPolygon(arrow)->find("not convex: vertex 3"), std::string::npos);

    const std::vector<b2Vec2> sliver = {{0, 0}, {1, 0}, {0.5f, 1e-6f}};
    ASSERT_TRUE(CheckPolygon(sliver));
    EXPECT_NE(CheckPolygon(sliver)->find("collinear"), std::string::npos);

    const std::vector<b2Vec2> small = {{0, 0}, {0.003f, 0}, {0, 0.003f}};
    EXPECT_FALSE(CheckPolygon(small)); // small but fine for Box2D
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
