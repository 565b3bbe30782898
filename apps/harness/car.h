// contactfx_harness (the demo harness, not installed): the tutorial's car and its controls.
//
// The tutorial scene has a body "car" with two wheel joints. Keys: a / d drive the rear wheel's motor
// at +/-1600 degrees per second (the front one too with four-wheel drive), s brakes (both motors on at
// speed 0), no key lets the wheels roll free. The same controls serve the testbed's keyboard and the
// scripted drives of the CLI, tests and benchmarks.
#pragma once

#include <optional>
#include <span>

class b2Body;
class b2WheelJoint;

namespace cfx
{

class Scene;

/// One moment of the driver's hands.
struct DriveInput
{
    int direction = 0;           ///< -1 left (key a), +1 right (key d), 0 no throttle
    bool brake = false;          ///< key s
    bool fourWheelDrive = false; ///< key 4 toggles it in the testbed
    bool operator==(const DriveInput&) const = default;
};

/// The wheel motor speed of the tutorial: 1600 degrees per second, in rad/s.
inline constexpr float kCarMotorSpeed = 1600.0f * 3.14159265358979f / 180.0f;

class Car
{
public:
    /// The car of a scene: the body named "car" and the wheel joints attached to it (the one with the
    /// smaller local anchor x is the rear). Nothing when the scene has no such car.
    static std::optional<Car> Find(const Scene& scene);

    /// Sets the motors for this input; call before each world step.
    void Apply(const DriveInput& input) const;

    b2Body* Body() const { return m_body; }

private:
    b2Body* m_body = nullptr;
    b2WheelJoint* m_rear = nullptr;
    b2WheelJoint* m_front = nullptr;
};

/// A drive as a list of inputs, each held until its end time.
struct DriveSegment
{
    float until = 0.0f; ///< s since the start; the segment covers [previous until, until)
    DriveInput input;
};

/// The input at `time`; no throttle after the last segment.
DriveInput InputAt(std::span<const DriveSegment> script, float time);

/// The demo's scripted drive of the tutorial scene (20 s): wheelspin and a skid on concrete (smoke),
/// the car tipping over a bump and grinding its steel body on concrete (sparks), then rocking on the
/// dirt hills (dirt).
std::span<const DriveSegment> TutorialDrive();

} // namespace cfx
