// The disc sweeps and the grid, piece by piece.
#include "particles/grid.h"
#include "particles/sweep.h"
#include "particles/world_geometry.h"

#include <algorithm>
#include <box2d/b2_body.h>
#include <box2d/b2_chain_shape.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_world.h>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
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

TEST(Grid, ReturnsTheBoxItsVisitedCellsCover)
{
    std::vector<b2AABB> boxes;
    for (int i = 0; i < 40; ++i)
    {
        b2AABB box;
        box.lowerBound = b2Vec2(static_cast<float>(i), static_cast<float>(i % 7));
        box.upperBound = box.lowerBound + b2Vec2(0.5f, 0.5f);
        boxes.push_back(box);
    }
    Grid grid;
    grid.Build(boxes);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> x(-5.0f, 45.0f);
    std::uniform_real_distribution<float> y(-5.0f, 12.0f);
    std::uniform_real_distribution<float> size(0.0f, 1.5f);
    bool largerThanAsked = false;
    for (int probe = 0; probe < 500; ++probe)
    {
        b2AABB query;
        query.lowerBound = b2Vec2(x(random), y(random));
        query.upperBound = query.lowerBound + b2Vec2(size(random), size(random));
        std::set<std::uint32_t> visited;
        const b2AABB covered = grid.Query(query, [&](std::uint32_t item) { visited.insert(item); });
        EXPECT_TRUE(covered.lowerBound.x <= query.lowerBound.x &&
                    covered.lowerBound.y <= query.lowerBound.y &&
                    covered.upperBound.x >= query.upperBound.x && covered.upperBound.y >= query.upperBound.y)
            << "the covered box holds the query, probe " << probe;
        for (std::uint32_t i = 0; i < boxes.size(); ++i)
        {
            if (!visited.count(i))
            {
                // Touching a side is fine: a point inside is still as far from the box as from the side.
                const b2AABB& box = boxes[i];
                const bool inside =
                    box.upperBound.x > covered.lowerBound.x && box.upperBound.y > covered.lowerBound.y &&
                    box.lowerBound.x < covered.upperBound.x && box.lowerBound.y < covered.upperBound.y;
                EXPECT_FALSE(inside) << "box " << i << " not visited, probe " << probe;
            }
        }
        largerThanAsked = largerThanAsked || covered.upperBound.x - covered.lowerBound.x >
                                                 query.upperBound.x - query.lowerBound.x + 0.01f;
    }
    EXPECT_TRUE(largerThanAsked) << "the covered box reaches to the visited cells' sides";
}

namespace
{

// Two static chains of 0.5 m segments, along y = 0 and y = 4, from x = -10 to 10.
struct TwoChains
{
    b2World world{b2Vec2(0.0f, -10.0f)};
    WorldGeometry geometry;
    ParticleSide side{0.05f, 0.0f, 0.0f, 0.0f, 0xffff, 0xffff};

    TwoChains()
    {
        b2BodyDef def;
        b2Body* ground = world.CreateBody(&def);
        for (float height : {0.0f, 4.0f})
        {
            std::vector<b2Vec2> points;
            for (int i = 0; i <= 40; ++i)
            {
                points.emplace_back(-10.0f + 0.5f * static_cast<float>(i), height);
            }
            b2ChainShape chain;
            chain.CreateChain(points.data(), static_cast<int>(points.size()), points.front(), points.back());
            ground->CreateFixture(&chain, 0.0f);
        }
        geometry.Scan(world, nullptr, 1.0f / 60.0f);
    }

    // Distance from `point` to the nearest segment.
    static float Distance(b2Vec2 point)
    {
        const float x = std::clamp(point.x, -10.0f, 10.0f);
        return std::min(b2Distance(point, b2Vec2(x, 0.0f)), b2Distance(point, b2Vec2(x, 4.0f)));
    }
};

} // namespace

TEST(WorldGeometry, ClearanceReachesAsFarAsTheCellsItLookedAt)
{
    TwoChains scene;
    const float reach = 0.05f;
    SweepResult result;
    float clearance = 0.0f;
    const SweepInput in{b2Vec2(0.25f, 2.0f), b2Vec2(0.0f, -0.01f), scene.side.radius};
    ASSERT_FALSE(scene.geometry.SweepStatic(in, scene.side, result, reach, &clearance));
    EXPECT_GT(clearance, 2.0f * reach) << "more than the reach: nothing lies in the cells the query visited";
    EXPECT_LE(clearance, TwoChains::Distance(in.p + in.d) - scene.side.radius);

    std::mt19937 random(3);
    std::uniform_real_distribution<float> x(-12.0f, 12.0f);
    std::uniform_real_distribution<float> y(-2.0f, 6.0f);
    for (int probe = 0; probe < 2000; ++probe)
    {
        const SweepInput at{b2Vec2(x(random), y(random)), b2Vec2(0.0f, 0.0f), scene.side.radius};
        SweepResult hit;
        if (!scene.geometry.SweepStatic(at, scene.side, hit, reach, &clearance))
        {
            // Within the radius of a chain, from behind (one-sided), the clearance is 0.
            EXPECT_LE(clearance, std::max(0.0f, TwoChains::Distance(at.p) - scene.side.radius))
                << "a lower bound at (" << at.p.x << ", " << at.p.y << ")";
        }
    }
}

} // namespace cfx::particles
