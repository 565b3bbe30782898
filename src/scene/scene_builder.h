// RubeDocument -> Scene: creates the b2World, bodies, fixtures and joints.
#pragma once

#include "contactfx/scene/rube.h"
#include "scene/json_reader.h"
#include "scene/rube_model.h"

namespace cfx::scene_detail
{

/// Builds a document that ReadRubeDocument accepted without problems. The few checks that need the built
/// bodies (mass updates, spring stiffness) are reported to `diagnostics`; the offending Box2D call is then
/// skipped, never made with bad values, and the scene must be thrown away.
Scene BuildScene(const RubeDocument& document, DiagnosticList& diagnostics);

} // namespace cfx::scene_detail
