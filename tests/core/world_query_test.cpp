// The children of fixtures a box meets (src/world_query.h): a trial's terrain of one 20,000-vertex chain
// made every spawn loop over all its children for each proxy Box2D reported (45 ms an Effects::Step
// against 0.4 ms now, bench ChainGround).
#include "world_query.h"

#include <algorithm>
#include <box2d/box2d.h>
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace cfx::test
{

TEST(WorldQuery, ASmallBoxMeetsOnlyTheChainSegmentsNearItEachOnce)
{
    b2World world(b2Vec2(0.0f, -10.0f));
    constexpr int kVertices = 20000;
    std::vector<b2Vec2> points;
    for (int i = 0; i < kVertices; ++i)
    {
        points.emplace_back(0.2f * static_cast<float>(i), 0.0f);
    }
    b2ChainShape chain;
    chain.CreateChain(points.data(), kVertices, points.front(), points.back());
    b2BodyDef groundDef;
    b2Fixture* terrain = world.CreateBody(&groundDef)->CreateFixture(&chain, 0.0f);
    b2BodyDef boxDef;
    boxDef.type = b2_dynamicBody;
    boxDef.position.Set(1000.1f, 0.5f);
    b2PolygonShape square;
    square.SetAsBox(0.5f, 0.5f);
    b2Fixture* box = world.CreateBody(&boxDef)->CreateFixture(&square, 1.0f);

    b2AABB query;
    query.lowerBound.Set(1000.05f, -0.05f); // within segment 5000 (x 1000.0 .. 1000.2) and the box
    query.upperBound.Set(1000.15f, 0.05f);
    std::vector<int> segments;
    int boxVisits = 0;
    detail::QueryChildren(world, query,
                          [&](const b2Fixture* fixture, int child)
                          {
                              if (fixture == terrain)
                              {
                                  segments.push_back(child);
                              }
                              boxVisits += fixture == box ? 1 : 0;
                              return true;
                          });
    // Box2D fattens each proxy by 0.1 m: the segment under the box and its neighbours, no more.
    ASSERT_FALSE(segments.empty());
    EXPECT_LE(segments.size(), 3u);
    EXPECT_NE(std::find(segments.begin(), segments.end(), 5000), segments.end());
    for (const int child : segments)
    {
        EXPECT_EQ(std::count(segments.begin(), segments.end(), child), 1) << child;
        EXPECT_TRUE(b2TestOverlap(terrain->GetAABB(child), query) || std::abs(child - 5000) <= 1) << child;
    }
    EXPECT_EQ(boxVisits, 1);

    // The visit can stop the query.
    int visits = 0;
    detail::QueryChildren(world, query,
                          [&](const b2Fixture*, int)
                          {
                              ++visits;
                              return false;
                          });
    EXPECT_EQ(visits, 1);
}

} // namespace cfx::test
