// contactfx: the built-in configurations.
#pragma once

#include "contactfx/config.h"

namespace cfx
{

/// The tutorial's rules: materials steel, rubber, concrete, dirt; rules steel+concrete -> sparks,
/// rubber+concrete -> smoke, steel+dirt and rubber+dirt -> dirt; intensity |vA - vB| * fA * fB at the
/// first manifold point, threshold 1, one particle per contact per step, particles dropped 0.05 m above
/// the static ground below the contact (SpawnPlacement::tutorialDrop: inside the tutorial car's wheel or
/// body standing there, which its particles pass through, as in the tutorial; beside a wheel or body they
/// would collide with), Box2D bodies of radius 0.01 that stop bouncing below 1 m/s (Box2D 2.3's
/// threshold), at most 100, oldest recycled. Life losses per step are expressed as lifetimes at the
/// tutorial's 60 Hz. One particle per contact per step makes the emission follow the step rate (twice as
/// many at 120 Hz as at 60), and with at most 100 the oldest are recycled sooner: the demo's smoke lives
/// 1.62 s at 30 and 60 Hz, 0.83 s at 120 Hz and 0.42 s at 240 Hz (a trial), as the tutorial's would. Fixtures
/// without a `material` property get the tutorial's guesses as assignments: steel on bodies heavier than 3
/// kg, concrete on static fixtures with friction > 0.5, dirt on static ones with friction < 0.5, rubber on
/// other dynamic bodies heavier than 0.4 kg. Where it still differs from the tutorial's own code: a contact
/// the application disabled in PreSolve emits nothing (the tutorial's loop only looks at the point count),
/// and one whose friction or tangent speed it set there emits by those (the tutorial reads the fixtures');
/// particles are drawn in contactfx's style (docs/rendering.md), not as the tutorial's 8-pixel points.
EffectsConfig TutorialPreset();

/// contactfx's model on the same materials: every manifold point, tangential speed, Box2D's friction
/// mix, pressure-weighted, thresholds per pair, rate-based emission per body pair independent of the step
/// rate and of the tessellation (of a chain ground; boxes side by side catch bodies in Box2D itself, see
/// docs/design.md), spawning outside every solid (or not at all), pool particles with colour
/// and size over life. The same assignments as the tutorial preset.
EffectsConfig DefaultPreset();

} // namespace cfx
