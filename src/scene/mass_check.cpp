#include "scene/mass_check.h"

#include "scene/json_reader.h"

#include <cmath>

namespace cfx::scene_detail
{

namespace
{

// Box2D computes the inertia about the centre of mass as I - m * (x * x + y * y) and asserts that it is
// positive. A compiler may fuse any of those products with the sum or the difference that follows
// (contracted multiply-adds: GCC's default on targets that have them), each rounding differently: the body
// is accepted only when every way of computing it is positive, so that no build of Box2D asserts.
bool PositiveInEveryRounding(float inertiaAboutOrigin, float mass, b2Vec2 center)
{
    const float x = center.x;
    const float y = center.y;
    const float squares[] = {x * x + y * y, std::fma(x, x, y * y), std::fma(y, y, x * x)};
    for (const float square : squares)
    {
        if (!(inertiaAboutOrigin - mass * square > 0.0f) ||
            !(std::fma(-mass, square, inertiaAboutOrigin) > 0.0f))
        {
            return false;
        }
    }
    return true;
}

bool Finite(b2Vec2 v)
{
    return std::isfinite(v.x) && std::isfinite(v.y);
}

std::optional<std::string> CheckCentralInertia(float inertiaAboutOrigin, float mass, b2Vec2 center)
{
    if (!PositiveInEveryRounding(inertiaAboutOrigin, mass, center))
    {
        return "rotational inertia about the centre of mass would not be positive (inertia about the body "
               "origin " +
               FormatFloat(inertiaAboutOrigin) + ", mass " + FormatFloat(mass) + ", centre (" +
               FormatFloat(center.x) + ", " + FormatFloat(center.y) +
               ")): the mass lies too far from the body origin for its size";
    }
    return std::nullopt;
}

} // namespace

std::optional<std::string> CheckResetMassData(const b2Body& body)
{
    if (body.GetType() != b2_dynamicBody)
    {
        return std::nullopt;
    }
    // Same order and arithmetic as b2Body::ResetMassData.
    float mass = 0.0f;
    float inertia = 0.0f;
    b2Vec2 localCenter(0.0f, 0.0f);
    for (const b2Fixture* fixture = body.GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext())
    {
        if (fixture->GetDensity() == 0.0f)
        {
            continue;
        }
        b2MassData massData;
        fixture->GetMassData(&massData);
        mass += massData.mass;
        localCenter += massData.mass * massData.center;
        inertia += massData.I;
    }
    if (!std::isfinite(mass) || !std::isfinite(inertia) || !Finite(localCenter))
    {
        return std::string("the mass of the fixtures overflows (density times area too large)");
    }
    if (mass > 0.0f)
    {
        const float invMass = 1.0f / mass;
        localCenter *= invMass;
        if (!Finite(localCenter))
        {
            return std::string("the mass of the fixtures is too small to locate its centre");
        }
    }
    if (inertia > 0.0f && !body.IsFixedRotation())
    {
        return CheckCentralInertia(inertia, mass, localCenter);
    }
    return std::nullopt;
}

std::optional<std::string> CheckSetMassData(const b2Body& body, const b2MassData& massData)
{
    if (body.GetType() != b2_dynamicBody)
    {
        return std::nullopt;
    }
    float mass = massData.mass;
    if (mass <= 0.0f)
    {
        mass = 1.0f;
    }
    if (massData.I > 0.0f && !body.IsFixedRotation())
    {
        return CheckCentralInertia(massData.I, mass, massData.center);
    }
    return std::nullopt;
}

} // namespace cfx::scene_detail
