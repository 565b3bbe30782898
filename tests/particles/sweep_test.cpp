// The disc sweeps and the grid, piece by piece.
#include "particles/crossing.h"
#include "particles/grid.h"
#include "particles/sweep.h"
#include "particles/world_geometry.h"

#include <algorithm>
#include <box2d/b2_body.h>
#include <box2d/b2_chain_shape.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_world.h>
#include <cmath>
#include <gtest/gtest.h>
#include <iterator>
#include <new>
#include <random>
#include <set>
#include <span>

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

// A long path past a circle: the touch is found from the path's closest point, not the quadratic's
// discriminant, whose terms cancel to their rounding when the path is hundreds of radii long. A trial's disc
// of 1 cm falling 8.3 m in a step (500 m/s at 60 Hz) 1.3 mm beside a flat ground's shared vertex touched the
// vertex's cap first and bounced off 14 degrees from the vertical; the face under it is touched first.
TEST(Sweep, ALongPathPastAVertexTouchesTheFaceUnderIt)
{
    const Segment left = MakeSegment(b2Vec2(-0.5f, 0.0f), b2Vec2(0.0f, 0.0f), false);
    const Segment right = MakeSegment(b2Vec2(0.0f, 0.0f), b2Vec2(0.5f, 0.0f), false);
    for (const float fall : {0.5f, 8.3f, 80.0f})
    {
        for (const float beside : {-0.0013f, 0.0013f, 0.005f})
        {
            const SweepInput in{b2Vec2(beside, 0.9f * fall), b2Vec2(0.0f, -fall), 0.01f};
            Touch touch;
            SweepSegment(in, left, touch);
            SweepSegment(in, right, touch);
            ASSERT_TRUE(touch.Found()) << fall << " " << beside;
            EXPECT_EQ(touch.normal.x, 0.0f) << fall << " " << beside;
            EXPECT_NEAR(touch.position.y, 0.01f, 1e-5f) << fall << " " << beside;
            EXPECT_EQ(touch.position.x, beside);
        }
        // The cap itself, missed and touched, on the same long path.
        const SweepInput past{b2Vec2(0.02001f, 0.9f * fall), b2Vec2(0.0f, -fall), 0.01f};
        Touch none;
        EXPECT_FALSE(SweepCircle(past, b2Vec2(0.0f, 0.0f), 0.01f, none)) << fall;
        const SweepInput grazing{b2Vec2(0.0199f, 0.9f * fall), b2Vec2(0.0f, -fall), 0.01f};
        Touch cap;
        ASSERT_TRUE(SweepCircle(grazing, b2Vec2(0.0f, 0.0f), 0.01f, cap)) << fall;
        EXPECT_NEAR(cap.position.y, std::sqrt(0.02f * 0.02f - 0.0199f * 0.0199f), 1e-4f) << fall;
    }
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

namespace
{

// Restitution 0.5, nothing bounces below 0.5 m/s.
SurfaceResponse HalfBouncing(float friction)
{
    SurfaceResponse surface;
    surface.restitution = 0.5f;
    surface.friction = friction;
    surface.restSpeed = 0.5f;
    return surface;
}

} // namespace

TEST(Sweep, RespondBouncesRestsAndRubs)
{
    SurfaceResponse surface = HalfBouncing(0.0f);
    const b2Vec2 up(0.0f, 1.0f);
    EXPECT_NEAR(Respond(b2Vec2(2.0f, -4.0f), 4.0f, up, surface).y, 2.0f, 1e-6f);
    EXPECT_NEAR(Respond(b2Vec2(2.0f, -4.0f), 4.0f, up, surface).x, 2.0f, 1e-6f);
    EXPECT_EQ(Respond(b2Vec2(2.0f, -0.3f), 0.3f, up, surface).y, 0.0f) << "below the rest speed";
    surface.friction = 10.0f;
    EXPECT_EQ(Respond(b2Vec2(2.0f, -4.0f), 4.0f, up, surface).x, 0.0f) << "friction stops, never reverses";
    surface.velocity = b2Vec2(3.0f, 0.0f);
    EXPECT_NEAR(Respond(b2Vec2(0.0f, -4.0f), 4.0f, up, surface).x, 3.0f, 1e-6f) << "carried by the surface";
    EXPECT_EQ(Respond(b2Vec2(0.0f, 4.0f), -4.0f, up, surface).y, 4.0f) << "leaving: kept";
}

TEST(Sweep, RespondBouncesWithTheSpeedAtTheTouch)
{
    const SurfaceResponse surface = HalfBouncing(0.25f);
    const b2Vec2 up(0.0f, 1.0f);
    // A long step's gravity (2.5 m/s) on a particle that touched at its start: no bounce, and the
    // friction of the whole normal change (2.5 m/s, 0.625 m/s of slide) still acts.
    const b2Vec2 rested = Respond(b2Vec2(2.0f, -2.5f), 0.0f, up, surface);
    EXPECT_EQ(rested.y, 0.0f);
    EXPECT_NEAR(rested.x, 2.0f - 0.25f * 2.5f, 1e-6f);
    // Touched at 3 m/s, 1 m/s more gravity after it: the bounce is half of 3 m/s, not of 4 m/s.
    const b2Vec2 bounced = Respond(b2Vec2(2.0f, -4.0f), 3.0f, up, surface);
    EXPECT_NEAR(bounced.y, 1.5f, 1e-6f);
    EXPECT_NEAR(bounced.x, 2.0f - 0.25f * 5.5f, 1e-6f);
    // A particle rising into a ceiling approached it faster at the touch than at the step's end.
    const b2Vec2 down(0.0f, -1.0f);
    EXPECT_NEAR(Respond(b2Vec2(0.0f, 3.0f), 4.0f, down, surface).y, -2.0f, 1e-6f);
}

constexpr Grid::Listing kListings[] = {Grid::Listing::overlapped, Grid::Listing::neighbourhood};
namespace
{

constexpr Grid::Storage kStorages[] = {Grid::Storage::dense, Grid::Storage::hashed};

const char* StorageName(Grid::Storage storage)
{
    return storage == Grid::Storage::dense ? "dense" : "hashed";
}

std::vector<std::pair<Grid::Listing, Grid::Storage>> Combinations()
{
    std::vector<std::pair<Grid::Listing, Grid::Storage>> all;
    for (const Grid::Listing listing : kListings)
    {
        for (const Grid::Storage storage : kStorages)
        {
            all.emplace_back(listing, storage);
        }
    }
    return all;
}

} // namespace

TEST(Grid, VisitsEveryBoxTheQueryOverlaps)
{
    std::vector<b2AABB> boxes;
    for (int i = 0; i < 100; ++i)
    {
        b2AABB box;
        box.lowerBound = b2Vec2(static_cast<float>(i), 0.0f);
        box.upperBound = b2Vec2(static_cast<float>(i) + 1.5f, 1.0f);
        boxes.push_back(box);
    }
    for (const auto& [listing, storage] : Combinations())
    {
        SCOPED_TRACE(listing == Grid::Listing::overlapped ? "overlapped" : "neighbourhood");
        SCOPED_TRACE(StorageName(storage));
        Grid grid;
        grid.Build(boxes, listing, 0, nullptr, nullptr, storage);
        ASSERT_FALSE(grid.Empty());
        for (int probe = 0; probe < 100; ++probe)
        {
            b2AABB query;
            // From a tenth of a cell to several cells wide.
            query.lowerBound = b2Vec2(static_cast<float>(probe) + 0.25f, 0.5f);
            query.upperBound = query.lowerBound + b2Vec2(0.1f + 0.08f * static_cast<float>(probe), 0.1f);
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
    for (const auto& [listing, storage] : Combinations())
    {
        SCOPED_TRACE(listing == Grid::Listing::overlapped ? "overlapped" : "neighbourhood");
        SCOPED_TRACE(StorageName(storage));
        Grid grid;
        grid.Build(boxes, listing, 0, nullptr, nullptr, storage);
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
            EXPECT_TRUE(
                covered.lowerBound.x <= query.lowerBound.x && covered.lowerBound.y <= query.lowerBound.y &&
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
}

// A neighbourhood grid answers "what lies within a cell of this point" from the point's cell alone, also
// for points outside the grid's bounds (the nearest cell's list).
TEST(Grid, ANeighbourhoodCellListsEverythingWithinACellOfItsPoints)
{
    std::mt19937 random(11);
    std::uniform_real_distribution<float> where(0.0f, 20.0f);
    std::uniform_real_distribution<float> size(0.05f, 1.2f);
    std::vector<b2AABB> boxes;
    for (int i = 0; i < 60; ++i)
    {
        b2AABB box;
        box.lowerBound = b2Vec2(where(random), 0.5f * where(random));
        box.upperBound = box.lowerBound + b2Vec2(size(random), size(random));
        boxes.push_back(box);
    }
    auto distance = [](const b2AABB& box, b2Vec2 point)
    {
        const b2Vec2 nearest(std::clamp(point.x, box.lowerBound.x, box.upperBound.x),
                             std::clamp(point.y, box.lowerBound.y, box.upperBound.y));
        return b2Distance(point, nearest);
    };
    std::uniform_real_distribution<float> probe(-3.0f, 23.0f);
    for (const auto& [listing, storage] : Combinations())
    {
        SCOPED_TRACE(StorageName(storage));
        Grid grid;
        grid.Build(boxes, listing, 0, nullptr, nullptr, storage);
        const float cell = grid.CellSize();
        int missed = 0;
        std::size_t listed = 0;
        for (int i = 0; i < 3000; ++i)
        {
            const b2Vec2 point(probe(random), 0.6f * probe(random));
            const std::span<const std::uint32_t> around = grid.Around(point);
            const std::set<std::uint32_t> items(around.begin(), around.end());
            EXPECT_EQ(items.size(), around.size()) << "each item once";
            listed += around.size();
            for (std::uint32_t k = 0; k < boxes.size(); ++k)
            {
                missed += distance(boxes[k], point) <= cell && items.count(k) == 0 ? 1 : 0;
            }
        }
        if (listing == Grid::Listing::neighbourhood)
        {
            EXPECT_EQ(missed, 0) << "every box within a cell of the point is listed";
            EXPECT_LT(listed, 3000u * boxes.size() / 4) << "and the lists are not everything";
        }
        else
        {
            EXPECT_GT(missed, 0) << "a cell's own boxes do not say what lies next to it";
        }
    }
}

namespace
{

// Long diagonal segments (ramps) whose boxes are mostly empty: listed by their boxes, every cell of those
// boxes would list them.
struct Diagonals
{
    std::vector<std::pair<b2Vec2, b2Vec2>> segments;
    std::vector<b2AABB> boxes;

    Diagonals()
    {
        for (int i = 0; i < 6; ++i)
        {
            const float x = 8.0f * static_cast<float>(i);
            const b2Vec2 a(x, i % 2 == 0 ? 0.0f : 6.0f);
            const b2Vec2 b(x + 8.0f, i % 2 == 0 ? 6.0f : 0.0f);
            segments.emplace_back(a, b);
            b2AABB box;
            box.lowerBound = b2Min(a, b);
            box.upperBound = b2Max(a, b);
            boxes.push_back(box);
        }
    }

    static float Distance(b2Vec2 a, b2Vec2 b, b2Vec2 point)
    {
        const b2Vec2 e = b - a;
        const float u = std::clamp(b2Dot(point - a, e) / b2Dot(e, e), 0.0f, 1.0f);
        return b2Distance(point, a + u * e);
    }

    // Grid::Touches: whether the segment comes into the region (separating axis: its normal).
    static bool Touches(const void* context, std::uint32_t item, const b2AABB& region)
    {
        const auto& [a, b] = static_cast<const Diagonals*>(context)->segments[item];
        b2Vec2 normal(b.y - a.y, a.x - b.x);
        normal.Normalize();
        const b2Vec2 half = region.GetExtents();
        return std::abs(b2Dot(normal, region.GetCenter() - a)) <=
               std::abs(normal.x) * half.x + std::abs(normal.y) * half.y;
    }
};

} // namespace

// With the shapes' own test, a neighbourhood grid keeps its promise (everything within a cell of a point
// is in the point's list) with finer cells that list a long diagonal only where it passes.
TEST(Grid, ExactListingKeepsTheNeighbourhoodAndListsLess)
{
    const Diagonals diagonals;
    Grid byBoxes;
    byBoxes.Build(diagonals.boxes, Grid::Listing::neighbourhood);
    Grid exact;
    exact.Build(diagonals.boxes, Grid::Listing::neighbourhood, 0, &Diagonals::Touches, &diagonals);
    EXPECT_LT(exact.CellSize(), byBoxes.CellSize()) << "finer cells than the boxes' median extent";
    std::mt19937 random(5);
    std::uniform_real_distribution<float> x(-2.0f, 50.0f);
    std::uniform_real_distribution<float> y(-2.0f, 8.0f);
    int missed = 0;
    std::size_t listedExact = 0;
    std::size_t listedByBoxes = 0;
    std::size_t far = 0;
    for (int i = 0; i < 5000; ++i)
    {
        const b2Vec2 point(x(random), y(random));
        const std::span<const std::uint32_t> around = exact.Around(point);
        const std::set<std::uint32_t> items(around.begin(), around.end());
        listedExact += around.size();
        listedByBoxes += byBoxes.Around(point).size();
        for (std::uint32_t k = 0; k < diagonals.segments.size(); ++k)
        {
            const auto& [a, b] = diagonals.segments[k];
            const float distance = Diagonals::Distance(a, b, point);
            missed += distance <= exact.CellSize() && items.count(k) == 0 ? 1 : 0;
            // (A point outside the grid's bounds gets the nearest cell's list.)
            const bool inBounds = point.x >= 0.0f && point.x <= 48.0f && point.y >= 0.0f && point.y <= 6.0f;
            far += inBounds && distance > 3.0f * exact.CellSize() && items.count(k) > 0 ? 1 : 0;
        }
    }
    EXPECT_EQ(missed, 0) << "every segment within a cell of the point is listed";
    EXPECT_EQ(far, 0u) << "no segment more than three cells away is listed";
    EXPECT_LT(4 * listedExact, listedByBoxes) << "a quarter of the entries a point's list has by boxes";
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
    const float reach = 0.05f; // the least a sweep looks around (4 times this motion's 1 cm is less)
    SweepResult result;
    float clearance = 0.0f;
    const SweepInput in{b2Vec2(0.25f, 2.0f), b2Vec2(0.0f, -0.01f), scene.side.radius};
    ASSERT_FALSE(scene.geometry.SweepStatic(in, scene.side, result, &clearance));
    EXPECT_GT(clearance, 2.0f * reach) << "more than the reach: nothing lies in the cells the query visited";
    EXPECT_LE(clearance, TwoChains::Distance(in.p + in.d) - scene.side.radius);

    std::mt19937 random(3);
    std::uniform_real_distribution<float> x(-12.0f, 12.0f);
    std::uniform_real_distribution<float> y(-2.0f, 6.0f);
    for (int probe = 0; probe < 2000; ++probe)
    {
        const SweepInput at{b2Vec2(x(random), y(random)), b2Vec2(0.0f, 0.0f), scene.side.radius};
        SweepResult hit;
        if (!scene.geometry.SweepStatic(at, scene.side, hit, &clearance))
        {
            // Within the radius of a chain, from behind (one-sided), the clearance is 0.
            EXPECT_LE(clearance, std::max(0.0f, TwoChains::Distance(at.p) - scene.side.radius))
                << "a lower bound at (" << at.p.x << ", " << at.p.y << ")";
        }
    }
}

namespace
{

// Every kind of static shape: a one-sided chain along a wave, a two-sided edge, a circle, polygons on a
// moved and turned body, and a box the particle's filter rejects.
struct EveryShape
{
    b2World world{b2Vec2(0.0f, -10.0f)};
    WorldGeometry geometry;
    ParticleSide side{0.1f, 0.0f, 0.0f, 0.0f, 0x0002, 0x0001};

    /// `farAway` > 0: also a static box that far up and to the right (a level's far corner). `waveSegments`:
    /// how finely the chain is split.
    explicit EveryShape(float farAway = 0.0f, int waveSegments = 24)
    {
        b2BodyDef def;
        b2Body* ground = world.CreateBody(&def);
        if (farAway > 0.0f)
        {
            b2PolygonShape far;
            far.SetAsBox(1.0f, 1.0f, b2Vec2(farAway, farAway), 0.0f);
            ground->CreateFixture(&far, 0.0f);
        }
        std::vector<b2Vec2> wave;
        for (int i = 0; i <= waveSegments; ++i)
        {
            // Right to left, so that the normals point up.
            const float x = 6.0f - 12.0f * static_cast<float>(i) / static_cast<float>(waveSegments);
            wave.emplace_back(x, 0.4f * std::sin(0.8f * x));
        }
        b2ChainShape chain;
        chain.CreateChain(wave.data(), static_cast<int>(wave.size()), wave.front(), wave.back());
        ground->CreateFixture(&chain, 0.0f);
        b2EdgeShape edge;
        edge.SetTwoSided(b2Vec2(-3.0f, 2.0f), b2Vec2(-1.0f, 2.6f));
        ground->CreateFixture(&edge, 0.0f);
        b2CircleShape circle;
        circle.m_p.Set(2.0f, 2.0f);
        circle.m_radius = 0.4f;
        ground->CreateFixture(&circle, 0.0f);
        b2PolygonShape rejected;
        rejected.SetAsBox(0.5f, 0.5f, b2Vec2(-4.5f, 3.0f), 0.0f);
        b2FixtureDef rejectedDef;
        rejectedDef.shape = &rejected;
        rejectedDef.filter.categoryBits = 0x0004;
        ground->CreateFixture(&rejectedDef);

        def.position.Set(0.5f, 3.5f);
        def.angle = 0.4f;
        b2Body* turned = world.CreateBody(&def);
        b2PolygonShape box;
        box.SetAsBox(0.6f, 0.2f);
        turned->CreateFixture(&box, 0.0f);
        const b2Vec2 triangle[3] = {b2Vec2(2.0f, 0.0f), b2Vec2(3.0f, 0.2f), b2Vec2(2.4f, 0.9f)};
        b2PolygonShape wedge;
        wedge.Set(triangle, 3);
        turned->CreateFixture(&wedge, 0.0f);
        geometry.Scan(world, nullptr, 1.0f / 60.0f);
    }

    // The earliest touch of every static shape the filter accepts, each swept on its own.
    bool SweepEach(const SweepInput& in, Touch& best) const
    {
        bool found = false;
        for (const b2Body* body = world.GetBodyList(); body != nullptr; body = body->GetNext())
        {
            const b2Transform& xf = body->GetTransform();
            for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr;
                 fixture = fixture->GetNext())
            {
                const b2Filter& filter = fixture->GetFilterData();
                if ((filter.maskBits & side.categoryBits) == 0 || (filter.categoryBits & side.maskBits) == 0)
                {
                    continue;
                }
                const b2Shape* shape = fixture->GetShape();
                if (shape->GetType() == b2Shape::e_circle)
                {
                    const auto* circle = static_cast<const b2CircleShape*>(shape);
                    found = SweepCircle(in, b2Mul(xf, circle->m_p), circle->m_radius, best) || found;
                }
                else if (shape->GetType() == b2Shape::e_polygon)
                {
                    const auto* polygon = static_cast<const b2PolygonShape*>(shape);
                    std::vector<b2Vec2> vertices, normals;
                    for (int i = 0; i < polygon->m_count; ++i)
                    {
                        vertices.push_back(b2Mul(xf, polygon->m_vertices[i]));
                        normals.push_back(b2Mul(xf.q, polygon->m_normals[i]));
                    }
                    found =
                        SweepPolygon(in, vertices.data(), normals.data(), polygon->m_count, best) || found;
                }
                else
                {
                    for (int child = 0; child < shape->GetChildCount(); ++child)
                    {
                        b2EdgeShape edge;
                        if (shape->GetType() == b2Shape::e_edge)
                        {
                            edge = *static_cast<const b2EdgeShape*>(shape);
                        }
                        else
                        {
                            static_cast<const b2ChainShape*>(shape)->GetChildEdge(&edge, child);
                        }
                        const Segment segment = MakeSegment(b2Mul(xf, edge.m_vertex1),
                                                            b2Mul(xf, edge.m_vertex2), edge.m_oneSided);
                        found = SweepSegment(in, segment, best) || found;
                    }
                }
            }
        }
        return found;
    }
};

// A path through the vertex two segments of a chain share crosses the chain (a trial's particle pushed
// down through a chain at a vertex was not counted: the test wanted the path strictly between the ends).
TEST(PathCrossesEdge, ThroughAVertexAcrossNotAlongNorFromBehind)
{
    const b2Vec2 down0(0.0f, 0.02f), down1(0.0f, -0.02f);
    // Segments right to left, front up (one-sided), meeting at (0, 0).
    EXPECT_TRUE(particles::PathCrossesEdge(down0, down1, b2Vec2(0.5f, 0.0f), b2Vec2(0.0f, 0.0f), true));
    EXPECT_TRUE(particles::PathCrossesEdge(down0, down1, b2Vec2(0.0f, 0.0f), b2Vec2(-0.5f, 0.0f), true));
    EXPECT_TRUE(particles::PathCrossesEdge(down0, down1, b2Vec2(0.0f, 0.0f), b2Vec2(-0.5f, 0.0f), false));
    // From behind a one-sided segment, along its line, beside it, or ending on it: not a crossing.
    EXPECT_FALSE(particles::PathCrossesEdge(down1, down0, b2Vec2(0.5f, 0.0f), b2Vec2(0.0f, 0.0f), true));
    EXPECT_FALSE(particles::PathCrossesEdge(b2Vec2(-0.2f, 0.0f), b2Vec2(0.2f, 0.0f), b2Vec2(0.5f, 0.0f),
                                            b2Vec2(-0.5f, 0.0f), false));
    EXPECT_FALSE(particles::PathCrossesEdge(b2Vec2(0.6f, 0.02f), b2Vec2(0.6f, -0.02f), b2Vec2(0.5f, 0.0f),
                                            b2Vec2(0.0f, 0.0f), false));
    EXPECT_FALSE(particles::PathCrossesEdge(down0, b2Vec2(0.0f, 0.0f), b2Vec2(0.5f, 0.0f),
                                            b2Vec2(-0.5f, 0.0f), false));
    // The particle check counts ending on it (a centre on a surface; far from the origin a particle crossed
    // in two steps, onto the line and off it), from the front of a one-sided segment only; starting on it
    // never counts.
    const b2Vec2 on(0.1f, 0.0f);
    EXPECT_TRUE(particles::PathCrossesEdge(down0, on, b2Vec2(0.5f, 0.0f), b2Vec2(-0.5f, 0.0f), false, true));
    EXPECT_TRUE(particles::PathCrossesEdge(down0, on, b2Vec2(0.5f, 0.0f), b2Vec2(-0.5f, 0.0f), true, true));
    EXPECT_TRUE(particles::PathCrossesEdge(down1, on, b2Vec2(0.5f, 0.0f), b2Vec2(-0.5f, 0.0f), false, true));
    EXPECT_FALSE(particles::PathCrossesEdge(down1, on, b2Vec2(0.5f, 0.0f), b2Vec2(-0.5f, 0.0f), true, true));
    EXPECT_FALSE(particles::PathCrossesEdge(on, down1, b2Vec2(0.5f, 0.0f), b2Vec2(-0.5f, 0.0f), false, true));
    EXPECT_FALSE(particles::PathCrossesEdge(down0, b2Vec2(0.6f, 0.0f), b2Vec2(0.5f, 0.0f),
                                            b2Vec2(-0.5f, 0.0f), false, true))
        << "on the line beyond the segment";
}

// The cache answers from one cell's list for short motions and from a query of cells for long ones, and
// skips primitives out of the disc's reach: the touches must be those of sweeping every shape, and the
// clearance a distance the disc can really move in any direction without touching anything.
void ExpectSweepsAsSweepingEveryShape(const EveryShape& scene, int probes = 20000)
{
    ASSERT_GE(scene.geometry.StaticPrimitives(), 28u);
    std::mt19937 random(5);
    std::uniform_real_distribution<float> x(-7.5f, 7.5f);
    std::uniform_real_distribution<float> y(-1.5f, 5.5f);
    std::uniform_real_distribution<float> turn(0.0f, 2.0f * b2_pi);
    std::uniform_real_distribution<float> length(0.0f, 1.5f);
    int touches = 0;
    int overlaps = 0;
    int clearancesChecked = 0;
    for (int probe = 0; probe < probes; ++probe)
    {
        const float angle = turn(random);
        const SweepInput in{b2Vec2(x(random), y(random)),
                            length(random) * b2Vec2(std::cos(angle), std::sin(angle)), scene.side.radius};
        SweepResult result;
        float clearance = -1.0f;
        const bool found = scene.geometry.SweepStatic(in, scene.side, result, &clearance);
        Touch expected;
        ASSERT_EQ(found, scene.SweepEach(in, expected)) << "probe " << probe;
        if (found)
        {
            ++touches;
            overlaps += expected.t == 0.0f ? 1 : 0;
            ASSERT_EQ(result.touch.t, expected.t) << "probe " << probe;
            EXPECT_NEAR(result.touch.position.x, expected.position.x, 1e-5f) << "probe " << probe;
            EXPECT_NEAR(result.touch.position.y, expected.position.y, 1e-5f) << "probe " << probe;
            EXPECT_EQ(clearance, 0.0f);
            continue;
        }
        // Moving on from the end by the clearance, in any direction, touches nothing.
        ASSERT_GE(clearance, 0.0f);
        for (int k = 0; k < 16 && clearance > 0.0f; ++k)
        {
            const float direction = static_cast<float>(k) * b2_pi / 8.0f;
            const SweepInput on{in.p + in.d, clearance * b2Vec2(std::cos(direction), std::sin(direction)),
                                scene.side.radius};
            Touch none;
            EXPECT_FALSE(scene.SweepEach(on, none)) << "probe " << probe << ", direction " << k;
        }
        clearancesChecked += clearance > 0.0f ? 1 : 0;
    }
    EXPECT_GT(touches, probes / 20);
    EXPECT_GT(overlaps, probes / 200);
    EXPECT_GT(clearancesChecked, probes / 2);
}

} // namespace

TEST(WorldGeometry, SweepsFindWhatSweepingEveryShapeFinds)
{
    ExpectSweepsAsSweepingEveryShape(EveryShape());
}

// One static fixture far away (a level's far corner, a kill zone) made the static grid's cells grow with the
// bounds, until each listed many primitives and every particle step near the ground cost more: 5,000
// particles raining on a 100 m chain of 5 cm segments took 0.12 ms a step alone, 1.3 ms with a box 1 km away
// and 6.3 ms with it 10 km away (contactfx_bench's FarFixture). The static grid then keeps only the cells
// that list something: its cells are no coarser than without the box, and its answers exact. (A chain of 5
// cm segments: the primitives' median extent sets the cells.)
TEST(WorldGeometry, AFarFixtureLeavesTheStaticCellsAsFineAndTheSweepsExact)
{
    constexpr int kWaveSegments = 240;
    const EveryShape alone(0.0f, kWaveSegments);
    for (const float farAway : {1.0e3f, 1.0e4f, 1.0e5f})
    {
        SCOPED_TRACE(testing::Message() << "a box " << farAway << " m away");
        const EveryShape scene(farAway, kWaveSegments);
        EXPECT_EQ(scene.geometry.StaticPrimitives(), alone.geometry.StaticPrimitives() + 1);
        EXPECT_LE(scene.geometry.StaticCellSize(), alone.geometry.StaticCellSize());
        ExpectSweepsAsSweepingEveryShape(scene, 5000);
    }
}

// With the box far to the lower left, the hashed grid's fine cells lie kilometres from its lower side, where
// floats placed the cells' lines off by a good part of a cell: a fuzz found primitives near the origin left
// out of cells their index put them in, and discs overlapping a segment there swept through it (2,002 of
// 4,004), paths across it not counted as crossings. Cells are now placed in doubles.
TEST(WorldGeometry, AFarFixtureToTheLowerLeftLeavesTheSweepsNearTheOriginExact)
{
    b2World world(b2Vec2(0.0f, -10.0f));
    b2BodyDef def;
    b2Body* ground = world.CreateBody(&def);
    const b2Vec2 a(-0.49280566f, 16.4696617f), b(-0.48643294f, 16.4606953f);
    b2EdgeShape edge;
    edge.SetTwoSided(a, b);
    ground->CreateFixture(&edge, 0.0f);
    for (int i = 0; i < 20; ++i) // they make the cells 0.079 m
    {
        b2EdgeShape filler;
        filler.SetTwoSided(b2Vec2(static_cast<float>(i), 0.0f),
                           b2Vec2(static_cast<float>(i) + 0.0791015625f, 0.0f));
        ground->CreateFixture(&filler, 0.0f);
    }
    b2PolygonShape far;
    far.SetAsBox(0.05f, 0.05f, b2Vec2(-84619.2547f, -44065.6453f), 0.0f);
    ground->CreateFixture(&far, 0.0f);
    WorldGeometry geometry;
    geometry.Scan(world, nullptr, 1.0f / 60.0f);
    ASSERT_LT(geometry.StaticCellSize(), 0.1f);
    const ParticleSide side{0.00208882196f, 0.0f, 0.0f, 0.0f, 0x0001, 0xffff};
    const Segment segment = MakeSegment(a, b, false);
    int missed = 0;
    int uncrossed = 0;
    for (int i = 0; i <= 1000; ++i)
    {
        const float u = static_cast<float>(i) / 1000.0f;
        const b2Vec2 on = (1.0f - u) * segment.v1 + u * segment.v2;
        for (const float length : {0.0f, 0.05f, 0.5f, 2.0f})
        {
            SweepResult result;
            missed += geometry.SweepStatic(
                          SweepInput{on + 0.001f * segment.normal, -length * segment.normal, side.radius},
                          side, result)
                          ? 0
                          : 1;
        }
        uncrossed +=
            geometry.CrossesStaticSegment(on + 0.01f * segment.normal, on - 0.01f * segment.normal, side) ? 0
                                                                                                          : 1;
    }
    EXPECT_EQ(missed, 0) << "discs overlapping the segment";
    EXPECT_EQ(uncrossed, 0) << "paths across it";
}

// A tile map: 20,000 boxes of 0.5 m in one row at round coordinates. The duplicate search's hash spreads
// them over its table (a trial found every tile of a row probing the same slots: a 100,000-tile level took
// 3 to 4.6 s to build, 85 % of it in that search).
TEST(WorldGeometry, ARowOfTilesIsBuiltWithoutCrowdingTheDuplicateSearch)
{
    b2World world(b2Vec2(0.0f, -10.0f));
    b2BodyDef def;
    b2Body* ground = world.CreateBody(&def);
    constexpr int kTiles = 20000;
    for (int i = 0; i < kTiles; ++i)
    {
        b2PolygonShape tile;
        tile.SetAsBox(0.25f, 0.25f, b2Vec2(-5000.0f + 0.5f * static_cast<float>(i), -0.25f), 0.0f);
        ground->CreateFixture(&tile, 0.0f);
    }
    b2PolygonShape again; // one tile twice: still met once
    again.SetAsBox(0.25f, 0.25f, b2Vec2(-5000.0f, -0.25f), 0.0f);
    ground->CreateFixture(&again, 0.0f);
    WorldGeometry geometry;
    geometry.Scan(world, nullptr, 1.0f / 60.0f);
    EXPECT_EQ(geometry.StaticPrimitives(), static_cast<std::size_t>(kTiles));
    // Linear probing in a table at most half full: under one extra slot a primitive on average.
    EXPECT_LT(geometry.DedupProbes(), static_cast<std::uint64_t>(kTiles));
}

TEST(WorldGeometry, StaticCacheSeesAChangeInAnyChildOfAChain)
{
    b2World world(b2Vec2(0.0f, -10.0f));
    b2BodyDef def;
    b2Body* ground = world.CreateBody(&def);
    std::vector<b2Vec2> points;
    for (int i = 0; i <= 10; ++i)
    {
        points.emplace_back(10.0f - 2.0f * static_cast<float>(i), 0.0f);
    }
    auto replaceChain = [&]()
    {
        if (ground->GetFixtureList() != nullptr)
        {
            ground->DestroyFixture(ground->GetFixtureList());
        }
        b2ChainShape chain;
        chain.CreateChain(points.data(), static_cast<int>(points.size()), points.front(), points.back());
        ground->CreateFixture(&chain, 0.0f);
    };
    replaceChain();
    WorldGeometry geometry;
    geometry.Scan(world, nullptr, 1.0f / 60.0f);
    std::uint64_t builds = geometry.StaticBuilds();
    for (const int moved : {0, 4, 9, 10}) // the first child, middle ones, the last (after the fourth lanes)
    {
        points[static_cast<std::size_t>(moved)].y += 0.01f;
        replaceChain();
        geometry.Scan(world, nullptr, 1.0f / 60.0f);
        EXPECT_EQ(geometry.StaticBuilds(), builds + 1) << "vertex " << moved << " moved";
        builds = geometry.StaticBuilds();
        geometry.Scan(world, nullptr, 1.0f / 60.0f);
        EXPECT_EQ(geometry.StaticBuilds(), builds) << "nothing changed since";
    }
}

// A static shape replaced by another with the same bounding box (a mirrored triangle, an edge or chain
// reversed, a ghost vertex moved), or edited in place, at the same addresses: the shape's own geometry
// tells it apart, not its box.
TEST(WorldGeometry, StaticCacheSeesAReplacedShapeWithTheSameBox)
{
    b2World world(b2Vec2(0.0f, -10.0f));
    b2BodyDef def;
    b2Body* ground = world.CreateBody(&def);
    WorldGeometry geometry;
    std::uint64_t builds = 0;
    auto replace = [&](const b2Shape& shape, const char* what)
    {
        if (ground->GetFixtureList() != nullptr)
        {
            ground->DestroyFixture(ground->GetFixtureList());
        }
        const b2Fixture* fixture = ground->CreateFixture(&shape, 0.0f);
        geometry.Scan(world, nullptr, 1.0f / 60.0f);
        EXPECT_EQ(geometry.StaticBuilds(), builds + 1) << what;
        builds = geometry.StaticBuilds();
        geometry.Scan(world, nullptr, 1.0f / 60.0f);
        EXPECT_EQ(geometry.StaticBuilds(), builds) << what << ": nothing changed since";
        return fixture;
    };
    b2PolygonShape triangle;
    const b2Vec2 rising[3] = {b2Vec2(0.0f, 0.0f), b2Vec2(4.0f, 0.0f), b2Vec2(0.0f, 4.0f)};
    triangle.Set(rising, 3);
    replace(triangle, "a triangle");
    const b2Vec2 mirrored[3] = {b2Vec2(0.0f, 0.0f), b2Vec2(4.0f, 0.0f), b2Vec2(4.0f, 4.0f)};
    triangle.Set(mirrored, 3);
    const b2Fixture* fixture = replace(triangle, "the triangle mirrored, same box");

    // Edited in place (Box2D's broad phase does not see it either).
    auto* inPlace = static_cast<b2PolygonShape*>(const_cast<b2Fixture*>(fixture)->GetShape());
    inPlace->m_vertices[2] = b2Vec2(3.0f, 4.0f);
    geometry.Scan(world, nullptr, 1.0f / 60.0f);
    EXPECT_EQ(geometry.StaticBuilds(), builds + 1) << "a vertex moved in place";
    builds = geometry.StaticBuilds();

    b2EdgeShape edge;
    edge.SetOneSided(b2Vec2(-1.0f, 0.0f), b2Vec2(0.0f, 0.0f), b2Vec2(4.0f, 0.0f), b2Vec2(5.0f, 0.0f));
    replace(edge, "a one-sided edge");
    edge.SetOneSided(b2Vec2(5.0f, 0.0f), b2Vec2(4.0f, 0.0f), b2Vec2(0.0f, 0.0f), b2Vec2(-1.0f, 0.0f));
    replace(edge, "the edge reversed");
    edge.SetOneSided(b2Vec2(5.0f, 0.0f), b2Vec2(4.0f, 0.0f), b2Vec2(0.0f, 0.0f), b2Vec2(-1.0f, 1.0f));
    replace(edge, "a ghost vertex moved");
    edge.SetTwoSided(b2Vec2(4.0f, 0.0f), b2Vec2(0.0f, 0.0f));
    replace(edge, "made two-sided");

    const b2Vec2 points[3] = {b2Vec2(0.0f, 0.0f), b2Vec2(2.0f, 0.0f), b2Vec2(4.0f, 0.0f)};
    const b2Vec2 reversed[3] = {points[2], points[1], points[0]};
    b2ChainShape forward;
    forward.CreateChain(points, 3, b2Vec2(-1.0f, 0.0f), b2Vec2(5.0f, 0.0f));
    replace(forward, "a chain");
    b2ChainShape backward;
    backward.CreateChain(reversed, 3, b2Vec2(5.0f, 0.0f), b2Vec2(-1.0f, 0.0f));
    replace(backward, "the chain reversed");
    b2ChainShape ghost;
    ghost.CreateChain(reversed, 3, b2Vec2(5.0f, 1.0f), b2Vec2(-1.0f, 0.0f));
    replace(ghost, "the chain's first ghost vertex moved");
}

} // namespace cfx::particles
