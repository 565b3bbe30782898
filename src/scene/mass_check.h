// Checks that Box2D's mass updates will not assert.
//
// b2Body::ResetMassData and b2Body::SetMassData subtract mass * |center|^2 from the rotational inertia about
// the body origin and assert that the result (the inertia about the centre of mass) stays positive. Tiny
// fixtures far from the body origin, or a saved inertia that does not match its mass and centre, break that
// in float arithmetic. These functions redo Box2D's computation first.
#pragma once

#include <box2d/box2d.h>
#include <optional>
#include <string>

namespace cfx::scene_detail
{

/// What would go wrong in body.ResetMassData() with the fixtures and densities the body has now.
std::optional<std::string> CheckResetMassData(const b2Body& body);

/// What would go wrong in body.SetMassData(&massData).
std::optional<std::string> CheckSetMassData(const b2Body& body, const b2MassData& massData);

} // namespace cfx::scene_detail
