// contactfx internal: the box around all of a body's fixtures.
#pragma once

#include <box2d/b2_body.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_fixture.h>
#include <limits>

namespace cfx::detail
{

/// The box around every child of every fixture of `body`, where the body is now (m, world). Empty (lower
/// above upper) for a body without fixtures. Costs a box per child.
inline b2AABB BodyBox(const b2Body& body)
{
    const float most = std::numeric_limits<float>::max();
    b2AABB box{b2Vec2(most, most), b2Vec2(-most, -most)};
    for (const b2Fixture* fixture = body.GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext())
    {
        const b2Shape& shape = *fixture->GetShape();
        for (int32 child = 0; child < shape.GetChildCount(); ++child)
        {
            b2AABB part;
            shape.ComputeAABB(&part, body.GetTransform(), child);
            box.lowerBound = b2Min(box.lowerBound, part.lowerBound);
            box.upperBound = b2Max(box.upperBound, part.upperBound);
        }
    }
    return box;
}

} // namespace cfx::detail
