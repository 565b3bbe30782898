// Static grounds of every shape type for the pool particle tests: a two-sided edge, a one-sided chain, a
// thick box and a row of split boxes, all with their top at y = 0 in the ground body's frame.
#pragma once

#include <box2d/box2d.h>
#include <vector>

namespace cfx::test
{

enum class Ground
{
    twoSidedEdge,
    chain,      // one-sided, 0.5 m segments, solid from above
    thickBox,   // 1 m thick
    splitBoxes, // 0.25 m wide polygons side by side
};

inline const char* GroundName(Ground ground)
{
    switch (ground)
    {
    case Ground::twoSidedEdge:
        return "Edge";
    case Ground::chain:
        return "Chain";
    case Ground::thickBox:
        return "Box";
    case Ground::splitBoxes:
        return "SplitBoxes";
    }
    return "";
}

constexpr float kHalfWidth = 30.0f;

// Static ground whose top is y = 0 over x in [-kHalfWidth, kHalfWidth], in the frame of a ground body placed
// at `origin` (so its top is at origin.y over origin.x +- kHalfWidth in the world).
inline std::vector<b2Fixture*> CreateGround(b2World& world, Ground ground, float friction,
                                            b2Vec2 origin = b2Vec2(0.0f, 0.0f))
{
    b2BodyDef def;
    def.position = origin;
    b2Body* body = world.CreateBody(&def);
    std::vector<b2Fixture*> fixtures;
    b2FixtureDef fixture;
    fixture.friction = friction;
    switch (ground)
    {
    case Ground::twoSidedEdge:
    {
        b2EdgeShape edge;
        edge.SetTwoSided(b2Vec2(-kHalfWidth, 0.0f), b2Vec2(kHalfWidth, 0.0f));
        fixture.shape = &edge;
        fixtures.push_back(body->CreateFixture(&fixture));
        break;
    }
    case Ground::chain:
    {
        std::vector<b2Vec2> vertices;
        for (float x = kHalfWidth; x >= -kHalfWidth; x -= 0.5f) // right to left: the normal points up
        {
            vertices.emplace_back(x, 0.0f);
        }
        b2ChainShape chain;
        chain.CreateChain(vertices.data(), static_cast<int>(vertices.size()), vertices.front() + b2Vec2(1, 0),
                          vertices.back() - b2Vec2(1, 0));
        fixture.shape = &chain;
        fixtures.push_back(body->CreateFixture(&fixture));
        break;
    }
    case Ground::thickBox:
    {
        b2PolygonShape box;
        box.SetAsBox(kHalfWidth, 0.5f, b2Vec2(0.0f, -0.5f), 0.0f);
        fixture.shape = &box;
        fixtures.push_back(body->CreateFixture(&fixture));
        break;
    }
    case Ground::splitBoxes:
    {
        for (float x = -kHalfWidth; x < kHalfWidth; x += 0.25f)
        {
            b2PolygonShape box;
            box.SetAsBox(0.125f, 0.5f, b2Vec2(x + 0.125f, -0.5f), 0.0f);
            fixture.shape = &box;
            fixtures.push_back(body->CreateFixture(&fixture));
        }
        break;
    }
    }
    return fixtures;
}

} // namespace cfx::test
