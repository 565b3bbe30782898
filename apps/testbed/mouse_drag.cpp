#include "mouse_drag.h"

#include "contactfx/scene/rube.h"

#include <box2d/b2_body.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_mouse_joint.h>
#include <box2d/b2_world.h>

namespace cfx::testbed
{

namespace
{

// The first dynamic body of the scene with a fixture containing the point.
class PointQuery final : public b2QueryCallback
{
public:
    PointQuery(const Scene& scene, b2Vec2 point) : m_scene(scene), m_point(point) {}

    bool ReportFixture(b2Fixture* fixture) override
    {
        b2Body* body = fixture->GetBody();
        if (body->GetType() == b2_dynamicBody && m_scene.FindBody(body) != nullptr &&
            fixture->TestPoint(m_point))
        {
            found = body;
            return false;
        }
        return true;
    }

    b2Body* found = nullptr;

private:
    const Scene& m_scene;
    b2Vec2 m_point;
};

} // namespace

bool MouseDrag::Grab(Scene& scene, b2Vec2 point)
{
    Release();
    b2World& world = *scene.world;
    constexpr float kReach = 0.001f; // m
    PointQuery query(scene, point);
    b2AABB box;
    box.lowerBound = point - b2Vec2(kReach, kReach);
    box.upperBound = point + b2Vec2(kReach, kReach);
    world.QueryAABB(&query, box);
    if (query.found == nullptr)
    {
        return false;
    }
    if (m_world != &world)
    {
        m_anchor = nullptr;
        m_world = &world;
    }
    for (b2Body* body = world.GetBodyList(); body != nullptr && m_anchor == nullptr; body = body->GetNext())
    {
        if (body->GetType() == b2_staticBody)
        {
            m_anchor = body;
        }
    }
    if (m_anchor == nullptr)
    {
        b2BodyDef anchor; // a scene without static bodies: one empty static body holds the joint
        m_anchor = world.CreateBody(&anchor);
    }
    constexpr float kFrequency = 5.0f;     // Hz
    constexpr float kDamping = 0.7f;       // ratio
    constexpr float kForcePerKg = 1000.0f; // N/kg: a hundred times gravity, a firm grip
    b2MouseJointDef def;
    def.bodyA = m_anchor;
    def.bodyB = query.found;
    def.target = point;
    def.maxForce = kForcePerKg * query.found->GetMass();
    b2LinearStiffness(def.stiffness, def.damping, kFrequency, kDamping, def.bodyA, def.bodyB);
    m_joint = static_cast<b2MouseJoint*>(world.CreateJoint(&def));
    query.found->SetAwake(true);
    return true;
}

void MouseDrag::MoveTo(b2Vec2 point)
{
    if (m_joint != nullptr)
    {
        m_joint->SetTarget(point);
    }
}

void MouseDrag::Release()
{
    if (m_joint != nullptr)
    {
        m_world->DestroyJoint(m_joint);
        m_joint = nullptr;
    }
}

} // namespace cfx::testbed
