// The disc sweeps and the grid, piece by piece.
#include "particles/grid.h"
#include "particles/sweep.h"

#include <box2d/b2_polygon_shape.h>
#include <gtest/gtest.h>
#include <set>

namespace cfx::particles
{

namespace
{

constexpr float kR = 0.1f;

SweepInput Move(b2Vec2 p, b2Vec2 d)
{
    return SweepInput{p, d, kR};
}

} // namespace

TEST(Sweep, SegmentFaceIsTouchedAtTheRadius)
{
    const Segment ground = MakeSegment(b2Vec2(5.0f, 0.0f), b2Vec2(-5.0f, 0.0f), true); // normal up
    EXPECT_NEAR(ground.normal.y, 1.0f, 1e-6f);
    Touch touch;
    ASSERT_TRUE(SweepSegment(Move(b2Vec2(0.0f, 1.0f), b2Vec2(0.0f, -2.0f)), ground, touch));
    EXPECT_NEAR(touch.t, 0.45f, 1e-6f);
    EXPECT_NEAR(touch.position.y, kR, 1e-6f);
    EXPECT_NEAR(touch.normal.y, 1.0f, 1e-6f);
}

TEST(Sweep, OneSidedSegmentLetsThroughFromBehind)
{
    const Segment ground = MakeSegment(b2Vec2(5.0f, 0.0f), b2Vec2(-5.0f, 0.0f), true);
    Touch touch;
    EXPECT_FALSE(SweepSegment(Move(b2Vec2(0.0f, -1.0f), b2Vec2(0.0f, 2.0f)), ground, touch));
    const Segment twoSided = MakeSegment(b2Vec2(5.0f, 0.0f), b2Vec2(-5.0f, 0.0f), false);
    ASSERT_TRUE(SweepSegment(Move(b2Vec2(0.0f, -1.0f), b2Vec2(0.0f, 2.0f)), twoSided, touch));
    EXPECT_NEAR(touch.position.y, -kR, 1e-6f);
    EXPECT_NEAR(touch.normal.y, -1.0f, 1e-6f);
}

TEST(Sweep, SegmentEndIsRound)
{
    const Segment wall = MakeSegment(b2Vec2(0.0f, 0.0f), b2Vec2(0.0f, -5.0f), false);
    Touch touch;
    // Passing just above the top end, within the radius: touches the end's circle.
    ASSERT_TRUE(SweepSegment(Move(b2Vec2(-1.0f, 0.05f), b2Vec2(2.0f, 0.0f)), wall, touch));
    EXPECT_NEAR((touch.position - b2Vec2(0.0f, 0.0f)).Length(), kR, 1e-5f);
    EXPECT_LT(touch.normal.x, 0.0f);
    EXPECT_GT(touch.normal.y, 0.0f);
    // Passing above the radius: nothing.
    Touch none;
    EXPECT_FALSE(SweepSegment(Move(b2Vec2(-1.0f, 0.2f), b2Vec2(2.0f, 0.0f)), wall, none));
}

TEST(Sweep, OverlapPushesOutAlongTheShortestWay)
{
    const Segment ground = MakeSegment(b2Vec2(5.0f, 0.0f), b2Vec2(-5.0f, 0.0f), true);
    Touch touch;
    ASSERT_TRUE(SweepSegment(Move(b2Vec2(1.0f, 0.04f), b2Vec2(0.0f, 0.0f)), ground, touch));
    EXPECT_EQ(touch.t, 0.0f);
    EXPECT_NEAR(touch.depth, kR - 0.04f, 1e-6f);
    EXPECT_NEAR(touch.position.y, kR, 1e-6f);
    EXPECT_NEAR(touch.position.x, 1.0f, 1e-6f);
}

TEST(Sweep, RestingDiscSlidesWithoutTouching)
{
    const Segment ground = MakeSegment(b2Vec2(5.0f, 0.0f), b2Vec2(-5.0f, 0.0f), true);
    Touch touch;
    EXPECT_FALSE(SweepSegment(Move(b2Vec2(0.0f, kR), b2Vec2(0.3f, 0.0f)), ground, touch));
    EXPECT_TRUE(SweepSegment(Move(b2Vec2(0.0f, kR), b2Vec2(0.3f, -0.01f)), ground, touch));
    EXPECT_EQ(touch.t, 0.0f);
}

TEST(Sweep, CircleIsTouchedOnItsGrownRadius)
{
    Touch touch;
    ASSERT_TRUE(SweepCircle(Move(b2Vec2(-3.0f, 0.0f), b2Vec2(4.0f, 0.0f)), b2Vec2(0.0f, 0.0f), 1.0f, touch));
    EXPECT_NEAR(touch.position.x, -1.0f - kR, 1e-5f);
    EXPECT_NEAR(touch.normal.x, -1.0f, 1e-5f);
    Touch inside;
    ASSERT_TRUE(SweepCircle(Move(b2Vec2(0.5f, 0.0f), b2Vec2(0.0f, 0.0f)), b2Vec2(0.0f, 0.0f), 1.0f, inside));
    EXPECT_NEAR(inside.position.x, 1.0f + kR, 1e-5f);
}

TEST(Sweep, PolygonFacesCornersAndInside)
{
    b2PolygonShape box;
    box.SetAsBox(1.0f, 1.0f);
    const auto sweep = [&](b2Vec2 p, b2Vec2 d, Touch& touch)
    { return SweepPolygon(Move(p, d), box.m_vertices, box.m_normals, box.m_count, touch); };

    Touch face;
    ASSERT_TRUE(sweep(b2Vec2(0.3f, 3.0f), b2Vec2(0.0f, -3.0f), face));
    EXPECT_NEAR(face.position.y, 1.0f + kR, 1e-5f);
    EXPECT_NEAR(face.normal.y, 1.0f, 1e-5f);

    // Diagonally at the corner: touches the corner's circle, not the square grown box.
    Touch corner;
    ASSERT_TRUE(sweep(b2Vec2(3.0f, 3.0f), b2Vec2(-3.0f, -3.0f), corner));
    EXPECT_NEAR((corner.position - b2Vec2(1.0f, 1.0f)).Length(), kR, 1e-4f);
    EXPECT_NEAR(corner.normal.x, corner.normal.y, 1e-4f);

    // Grazing past the corner within the square grown box but outside the round one: no touch.
    Touch miss;
    EXPECT_FALSE(sweep(b2Vec2(1.59f, 0.59f), b2Vec2(-1.0f, 1.0f), miss)); // 0.127 m from the corner

    Touch inside;
    ASSERT_TRUE(sweep(b2Vec2(0.2f, 0.7f), b2Vec2(0.0f, 0.0f), inside));
    EXPECT_EQ(inside.t, 0.0f);
    EXPECT_NEAR(inside.position.y, 1.0f + kR, 1e-5f);
}

TEST(Sweep, EarlierTouchWins)
{
    const Segment near = MakeSegment(b2Vec2(5.0f, 1.0f), b2Vec2(-5.0f, 1.0f), true);
    const Segment far = MakeSegment(b2Vec2(5.0f, 0.0f), b2Vec2(-5.0f, 0.0f), true);
    Touch touch;
    EXPECT_TRUE(SweepSegment(Move(b2Vec2(0.0f, 3.0f), b2Vec2(0.0f, -4.0f)), far, touch));
    EXPECT_TRUE(SweepSegment(Move(b2Vec2(0.0f, 3.0f), b2Vec2(0.0f, -4.0f)), near, touch));
    EXPECT_FALSE(SweepSegment(Move(b2Vec2(0.0f, 3.0f), b2Vec2(0.0f, -4.0f)), far, touch));
    EXPECT_NEAR(touch.position.y, 1.0f + kR, 1e-5f);
}

TEST(Sweep, RespondBouncesRestsAndRubs)
{
    SurfaceResponse surface;
    surface.restitution = 0.5f;
    surface.friction = 0.0f;
    surface.restSpeed = 0.5f;
    const b2Vec2 up(0.0f, 1.0f);
    EXPECT_NEAR(Respond(b2Vec2(2.0f, -4.0f), up, surface).y, 2.0f, 1e-6f);
    EXPECT_NEAR(Respond(b2Vec2(2.0f, -4.0f), up, surface).x, 2.0f, 1e-6f);
    EXPECT_EQ(Respond(b2Vec2(2.0f, -0.3f), up, surface).y, 0.0f) << "below the rest speed";
    surface.friction = 10.0f;
    EXPECT_EQ(Respond(b2Vec2(2.0f, -4.0f), up, surface).x, 0.0f) << "friction stops, never reverses";
    surface.velocity = b2Vec2(3.0f, 0.0f);
    EXPECT_NEAR(Respond(b2Vec2(0.0f, -4.0f), up, surface).x, 3.0f, 1e-6f) << "carried by the surface";
    EXPECT_EQ(Respond(b2Vec2(0.0f, 4.0f), up, surface).y, 4.0f) << "leaving: kept";
}

TEST(Grid, ListsEveryBoxInTheCellsItOverlaps)
{
    std::vector<b2AABB> boxes;
    for (int i = 0; i < 100; ++i)
    {
        b2AABB box;
        box.lowerBound = b2Vec2(static_cast<float>(i), 0.0f);
        box.upperBound = b2Vec2(static_cast<float>(i) + 1.5f, 1.0f);
        boxes.push_back(box);
    }
    Grid grid;
    grid.Build(boxes);
    ASSERT_FALSE(grid.Empty());
    for (int probe = 0; probe < 100; ++probe)
    {
        b2AABB query;
        query.lowerBound = b2Vec2(static_cast<float>(probe) + 0.25f, 0.5f);
        query.upperBound = query.lowerBound + b2Vec2(0.1f, 0.1f);
        std::set<std::uint32_t> found;
        grid.Query(query, [&](std::uint32_t item) { found.insert(item); });
        for (std::uint32_t i = 0; i < boxes.size(); ++i)
        {
            if (b2TestOverlap(boxes[i], query))
            {
                EXPECT_TRUE(found.count(i)) << "box " << i << " at probe " << probe;
            }
        }
    }
    b2AABB outside;
    outside.lowerBound = b2Vec2(0.0f, 50.0f);
    outside.upperBound = b2Vec2(1.0f, 51.0f);
    int visits = 0;
    grid.Query(outside, [&](std::uint32_t) { ++visits; });
    EXPECT_EQ(visits, 0);
}

} // namespace cfx::particles
