// contactfx drawing layer: where the picture looks.
//
// A 2D camera maps world metres (y up) to image pixels (y down) by a centre and a scale. Renderers ask
// it for the transform (a DrawList carries one); front ends move it: fit it to the whole world, or centre it
// on a body each frame so a moving car stays in view. A camera is a plain value with no link to the world.
#pragma once

#include <box2d/b2_math.h>

class b2Body;
class b2World;

namespace cfx
{

struct Camera
{
    b2Vec2 center{0.0f, 0.0f};    ///< m, world point at the middle of the image
    float pixelsPerMetre = 50.0f; ///< > 0
    int width = 640;              ///< px, > 0
    int height = 360;             ///< px, > 0

    /// Image position (px, y down, origin at the top left corner) of a world point.
    b2Vec2 ToPixels(b2Vec2 world) const
    {
        return b2Vec2(0.5f * static_cast<float>(width) + (world.x - center.x) * pixelsPerMetre,
                      0.5f * static_cast<float>(height) - (world.y - center.y) * pixelsPerMetre);
    }
    /// World point under an image position.
    b2Vec2 ToWorld(b2Vec2 pixels) const
    {
        return b2Vec2(center.x + (pixels.x - 0.5f * static_cast<float>(width)) / pixelsPerMetre,
                      center.y - (pixels.y - 0.5f * static_cast<float>(height)) / pixelsPerMetre);
    }
    /// Metres shown across the image.
    float ViewWidth() const { return static_cast<float>(width) / pixelsPerMetre; }
};

/// A camera of the given image size showing `viewWidth` metres across (> 0), centred on `center`.
Camera MakeCamera(int width, int height, float viewWidth, b2Vec2 center);

/// Centres the camera on `body`, keeping the scale: horizontally on its origin, vertically `lift` metres
/// above its lowest point (the bottom of its fixtures' bounding box), so that a car tipping over or
/// standing on its nose keeps the ground where it was in the picture.
void Follow(Camera& camera, const b2Body& body, float lift = 0.0f);

/// Moves the camera towards `body` by one step of `dt` seconds: x at once, y eased with time constant
/// `smoothing` (s, >= 0; 0: at once), so that a car tipping over or bouncing does not shake the picture.
/// Call it after every simulation step so that the view depends only on the simulated steps.
void FollowSmoothly(Camera& camera, const b2Body& body, float lift, float dt, float smoothing);

/// Scale and centre that show every fixture of `world` with a margin of `margin` (fraction of the
/// image, [0, 0.5)). A world with no fixture leaves the camera unchanged.
void FitWorld(Camera& camera, const b2World& world, float margin = 0.05f);

} // namespace cfx
