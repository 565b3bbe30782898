// contactfx drawing layer: what a user tuning effects needs to see, drawn over the picture.
//
// Each touching contact whose two materials have a rule ("tracked") shows its manifold points coloured
// by intensity (the rule's intensity model, blue at 0 through green to red at twice its threshold; a
// white ring marks points above the threshold), its normal, its normal impulse as a line along the
// normal, and the rule's name. Particles show their velocity. Everything is read through the public
// Effects API and Box2D's contact list after Effects::Step; nothing is changed. Pressure is each
// contact's own normal force (its points' impulses / stepTime), which is what emission uses when a body
// pair touches through one contact.
#pragma once

#include "contactfx/draw.h"
#include "contactfx/draw/draw_list.h"

#include <span>
#include <string>

namespace cfx
{

class Effects;

/// Which debug layers are drawn.
struct DebugLayers
{
    bool manifoldPoints = false; ///< points coloured by intensity, ringed above the rule's threshold
    bool normals = false;        ///< each contact's normal, normalLength m long, from fixture A to B
    bool impulses = false;       ///< normal impulse at each point, impulseScale m per N s, along the normal
    bool ruleNames = false;      ///< "materialA/materialB: type" beside each tracked contact
    bool velocities = false;     ///< each particle's motion over the next velocityTime s
    float normalLength = 0.4f;   ///< m, > 0
    float impulseScale = 0.2f;   ///< m per N s, > 0
    float velocityTime = 0.05f;  ///< s, > 0
    float stepTime =
        1.0f / 60.0f; ///< s, > 0: the step the impulses were solved over (force = impulse / step)

    /// Every layer on.
    static DebugLayers All();
    bool Any() const { return manifoldPoints || normals || impulses || ruleNames || velocities; }
};

/// Colours of the layers, fixed so that tests and users can find them.
inline constexpr Color kDebugNormalColor{0.2f, 0.85f, 1.0f, 1.0f};   ///< cyan
inline constexpr Color kDebugImpulseColor{1.0f, 0.2f, 0.85f, 1.0f};  ///< magenta
inline constexpr Color kDebugVelocityColor{0.6f, 1.0f, 0.3f, 0.8f};  ///< light green
inline constexpr Color kDebugThresholdColor{1.0f, 1.0f, 1.0f, 1.0f}; ///< the ring above the threshold
inline constexpr float kDebugPointSize = 6.0f;                       ///< px, a manifold point's square
inline constexpr float kDebugLineWidth = 2.0f;                       ///< px, normals, impulses and velocities

/// The colour of a manifold point of `intensity` under a rule with `threshold` (>= 0): blue at 0, green
/// at the threshold, red from twice the threshold; opaque.
Color IntensityColor(float intensity, float threshold);

/// The rule's name as the layers print it: "steel/concrete: sparks".
std::string RuleLabel(const Effects& effects, RuleId rule);

/// Appends the layers switched on in `layers` for `effects` (its world's contacts after its last Step)
/// and `sprites` (its particles, CollectSprites) to `list`: shapes in world metres, labels in pixels.
void AddDebugLayers(DrawList& list, const Effects& effects, std::span<const ParticleSprite> sprites,
                    const DebugLayers& layers, const DrawStyle& style);

} // namespace cfx
