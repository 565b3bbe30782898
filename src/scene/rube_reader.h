// RUBE JSON document -> RubeDocument, with every problem reported.
#pragma once

#include "scene/json_reader.h"
#include "scene/rube_model.h"

namespace cfx::scene_detail
{

/// Reads and checks the whole document. The result is only meant to be built when `diagnostics` stayed
/// empty; it is complete enough for counting otherwise.
RubeDocument ReadRubeDocument(const Json& root, DiagnosticList& diagnostics);

} // namespace cfx::scene_detail
