// contactfx-testbed: dragging bodies with the mouse, as in Box2D's testbed.
//
// A press on a dynamic body of the scene attaches a b2MouseJoint (soft spring, force limit in
// proportion to the body's mass) between a static body and the grabbed point; moving the mouse moves
// the joint's target; releasing destroys the joint. Particles that are Box2D bodies are not grabbed.
//
// Lifetime: the joint belongs to the simulation's world. Call Release() before that world goes, or
// Forget() once it is gone.
#pragma once

#include <box2d/b2_math.h>

class b2Body;
class b2MouseJoint;
class b2World;

namespace cfx
{
class Scene;
}

namespace cfx::testbed
{

class MouseDrag
{
public:
    /// Grabs the scene's dynamic body under `point` (m, world); false when there is none.
    bool Grab(Scene& scene, b2Vec2 point);
    /// Moves the grabbed point's target (m, world).
    void MoveTo(b2Vec2 point);
    /// Lets go (destroys the joint); nothing when nothing is held.
    void Release();
    /// Drops the joint pointer without touching the world (the world was destroyed).
    void Forget()
    {
        m_joint = nullptr;
        m_world = nullptr;
    }
    bool Active() const { return m_joint != nullptr; }

private:
    b2MouseJoint* m_joint = nullptr;
    b2World* m_world = nullptr;
    b2Body* m_anchor = nullptr; // a static body of the world, the joint's body A
};

} // namespace cfx::testbed
