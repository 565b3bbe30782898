// Camera placement: following a body and fitting the world's fixtures into view.
#include "contactfx/draw/camera.h"

#include "body_box.h"

#include <algorithm>
#include <box2d/b2_body.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>
#include <cmath>
#include <limits>

namespace cfx
{

namespace
{

/// The bounding box of fixtures, grown one body at a time; empty until something is added.
struct Bounds
{
    b2Vec2 lower{std::numeric_limits<float>::max(), std::numeric_limits<float>::max()};
    b2Vec2 upper{-std::numeric_limits<float>::max(), -std::numeric_limits<float>::max()};

    bool Empty() const { return lower.x > upper.x; }

    void Add(const b2Body& body)
    {
        const b2AABB box = detail::BodyBox(body);
        lower = b2Min(lower, box.lowerBound);
        upper = b2Max(upper, box.upperBound);
    }
};

/// Where the camera following `body` looks: its origin's x, `lift` above its lowest point.
b2Vec2 FollowTarget(const b2Body& body, float lift)
{
    Bounds bounds;
    bounds.Add(body);
    const float bottom = bounds.Empty() ? body.GetPosition().y : bounds.lower.y;
    return b2Vec2(body.GetPosition().x, bottom + lift);
}

} // namespace

Camera MakeCamera(int width, int height, float viewWidth, b2Vec2 center)
{
    Camera camera;
    camera.width = width;
    camera.height = height;
    camera.center = center;
    camera.pixelsPerMetre = static_cast<float>(width) / viewWidth;
    return camera;
}

void Follow(Camera& camera, const b2Body& body, float lift)
{
    camera.center = FollowTarget(body, lift);
}

void FollowSmoothly(Camera& camera, const b2Body& body, float lift, float dt, float smoothing)
{
    const b2Vec2 target = FollowTarget(body, lift);
    camera.center.x = target.x;
    const float blend = smoothing > 0.0f ? 1.0f - std::exp(-dt / smoothing) : 1.0f;
    camera.center.y += (target.y - camera.center.y) * blend;
}

void FitWorld(Camera& camera, const b2World& world, float margin)
{
    Bounds bounds;
    for (const b2Body* body = world.GetBodyList(); body != nullptr; body = body->GetNext())
    {
        bounds.Add(*body);
    }
    if (bounds.Empty())
    {
        return;
    }
    const float usable = 1.0f - 2.0f * std::clamp(margin, 0.0f, 0.49f);
    const b2Vec2 size = bounds.upper - bounds.lower;
    const float fitX = usable * static_cast<float>(camera.width) / std::max(size.x, 1e-3f);
    const float fitY = usable * static_cast<float>(camera.height) / std::max(size.y, 1e-3f);
    camera.pixelsPerMetre = std::min(fitX, fitY);
    camera.center = 0.5f * (bounds.lower + bounds.upper);
}

} // namespace cfx
