#include "harness/car.h"

#include "contactfx/scene/rube.h"

#include <array>
#include <box2d/b2_body.h>
#include <box2d/b2_wheel_joint.h>

namespace cfx
{

std::optional<Car> Car::Find(const Scene& scene)
{
    const SceneBody* car = scene.FindBody("car");
    if (car == nullptr)
    {
        return std::nullopt;
    }
    Car result;
    result.m_body = car->body;
    for (const SceneJoint& entry : scene.joints)
    {
        if (entry.joint->GetType() != e_wheelJoint || entry.joint->GetBodyA() != car->body)
        {
            continue;
        }
        auto* wheel = static_cast<b2WheelJoint*>(entry.joint);
        if (result.m_rear == nullptr || wheel->GetLocalAnchorA().x < result.m_rear->GetLocalAnchorA().x)
        {
            result.m_front = result.m_rear;
            result.m_rear = wheel;
        }
        else
        {
            result.m_front = wheel;
        }
    }
    if (result.m_rear == nullptr)
    {
        return std::nullopt;
    }
    return result;
}

void Car::Apply(const DriveInput& input) const
{
    auto set = [](b2WheelJoint* joint, bool on, float speed)
    {
        if (joint != nullptr)
        {
            joint->EnableMotor(on);
            joint->SetMotorSpeed(speed);
        }
    };
    if (input.brake)
    {
        set(m_rear, true, 0.0f);
        set(m_front, true, 0.0f);
        return;
    }
    // Driving right turns the wheels clockwise: a negative speed.
    const float speed = -static_cast<float>(input.direction) * kCarMotorSpeed;
    const bool driving = input.direction != 0;
    set(m_rear, driving, speed);
    set(m_front, driving && input.fourWheelDrive, speed);
    m_body->SetAwake(true);
}

DriveInput InputAt(std::span<const DriveSegment> script, float time)
{
    for (const DriveSegment& segment : script)
    {
        if (time < segment.until)
        {
            return segment.input;
        }
    }
    return DriveInput{};
}

std::span<const DriveSegment> TutorialDrive()
{
    // Found by searching drives made of the tutorial's keys for one that shows all three effects; the
    // world is deterministic, so the same drive always does the same thing.
    static const std::array kDrive{
        DriveSegment{4.07f, DriveInput{+1, false, true}},   // launch with wheelspin (smoke), 4WD
        DriveSegment{7.16f, DriveInput{-1, false, false}},  // full reverse at speed: tyres skid (smoke)
        DriveSegment{11.26f, DriveInput{+1, false, false}}, // forward over the bump: the car tips onto
                                                            // its body and grinds on concrete (sparks)
        DriveSegment{15.59f, DriveInput{-1, false, false}}, // rocking on the dirt hills (dirt)
        DriveSegment{17.12f, DriveInput{+1, false, false}},
        DriveSegment{18.33f, DriveInput{+1, false, true}},
    };
    return kDrive;
}

} // namespace cfx
