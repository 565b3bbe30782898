// contactfx_scene: which material each fixture of a RUBE scene has.
//
// A fixture's own custom property `material` (a string naming a material of the effects config) decides
// first, then its body's `material` property (for all its fixtures without one); a fixture without either
// gets the material of the first assignment rule of the config that matches it (assignments.h), or none.
// On a body or fixture without a `material` property, a string property one edit from the name
// ("Material", "materal", "materials") is an error: it would silently give no material. So a scene made for
// contactfx keeps full control, and a plain RUBE scene still gives effects.
#pragma once

#include "contactfx/config.h"
#include "contactfx/materials.h"
#include "contactfx/scene/rube.h"

#include <string_view>
#include <vector>

namespace cfx
{

class Effects;

/// The material of every entry of `scene.fixtures` (same order; an invalid id for none). Throws InputError
/// naming `file` and the JSON path of each bad property (e.g.
/// `body[1].fixture[0].customProperties[0].string` for a name the config does not know, `body[1].
/// customProperties[0].string` for a body's).
std::vector<MaterialId> ResolveSceneMaterials(const Scene& scene, const EffectsConfig& config,
                                              std::string_view file);

/// Gives every fixture of `scene` the material ResolveSceneMaterials finds with the effects' config.
/// Throws as it does, before changing any fixture.
void AssignSceneMaterials(const Scene& scene, Effects& effects, std::string_view file);

} // namespace cfx
