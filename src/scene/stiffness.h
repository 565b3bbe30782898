// RUBE's spring frequency and damping ratio <-> Box2D 2.4's stiffness and damping.
//
// Box2D 2.4.1 converts with b2LinearStiffness (mass of the two bodies) and b2AngularStiffness (their
// rotational inertia about their origins); the inverse here uses the same effective mass or inertia.
#pragma once

#include <box2d/box2d.h>

namespace cfx::scene_detail
{

struct Spring
{
    float frequency = 0.0f; ///< Hz
    float dampingRatio = 0.0f;
};

/// The effective mass b2LinearStiffness uses.
float LinearSpringMass(const b2Body& bodyA, const b2Body& bodyB);
/// The effective inertia b2AngularStiffness uses.
float AngularSpringInertia(const b2Body& bodyA, const b2Body& bodyB);

/// Frequency and damping ratio that b2LinearStiffness / b2AngularStiffness turn back into `stiffness` and
/// `damping` for this effective mass (or inertia). Zero when there is no stiffness or no mass.
Spring SpringFromStiffness(float stiffness, float damping, float massOrInertia);

} // namespace cfx::scene_detail
