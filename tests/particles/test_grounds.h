// Static grounds of every shape type for the pool particle tests: a two-sided edge, a one-sided chain, a
// thick box and a row of split boxes, and finely split versions of the last two (2 cm pieces, smaller than a
// wheel's push in a step), all with their top at y = 0 in the ground body's frame.
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
    fineChain,  // one-sided, 2 cm segments
    fineBoxes,  // 2 cm wide polygons side by side
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
    case Ground::fineChain:
        return "FineChain";
    case Ground::fineBoxes:
        return "FineBoxes";
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
    case Ground::fineChain:
    {
        // Right to left: the normal points up. Counted in integers, so that the last vertex is at the end.
        const int segments = ground == Ground::chain ? 120 : 3000;
        std::vector<b2Vec2> vertices;
        for (int i = 0; i <= segments; ++i)
        {
            vertices.emplace_back(
                kHalfWidth - 2.0f * kHalfWidth * static_cast<float>(i) / static_cast<float>(segments), 0.0f);
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
    case Ground::fineBoxes:
    {
        const int boxes = ground == Ground::splitBoxes ? 240 : 3000;
        const float halfBox = kHalfWidth / static_cast<float>(boxes);
        for (int i = 0; i < boxes; ++i)
        {
            b2PolygonShape box;
            box.SetAsBox(halfBox, 0.5f, b2Vec2(-kHalfWidth + halfBox * static_cast<float>(2 * i + 1), -0.5f),
                         0.0f);
            fixture.shape = &box;
            fixtures.push_back(body->CreateFixture(&fixture));
        }
        break;
    }
    }
    return fixtures;
}

} // namespace cfx::test
