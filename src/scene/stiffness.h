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

/// Frequency and damping ratio of a joint's spring between `bodyA` and `bodyB` that b2LinearStiffness
/// (`angular`: b2AngularStiffness) turns back into exactly `stiffness` and `damping` when such floats lie
/// within a few steps of the computed inverse (so a saved scene loads with the springs it was saved with, and
/// saving it again writes the same numbers); otherwise the computed inverse. Zero when there is no stiffness
/// or no mass (inertia).
Spring SpringFromStiffness(float stiffness, float damping, const b2Body& bodyA, const b2Body& bodyB,
                           bool angular);

} // namespace cfx::scene_detail
