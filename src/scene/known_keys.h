// Keys a reader knows, and what to say about the others.
//
// A misspelt key must not silently do nothing: `"gravty": {"x": 0, "y": -10}` would otherwise load a world
// without gravity. RUBE scenes report unknown keys as warnings (b2dJson itself ignores them, and RUBE
// versions add fields), effects configs as errors; both name the nearest known key. Which kind of file a
// JSON object is shows in its top-level keys, so a scene given as an effects config (or the reverse) gets
// one error that says so instead of a list of unknown keys.
#pragma once

#include "nearest_name.h"
#include "scene/json_reader.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace cfx::scene_detail
{

using detail::EditDistance; // nearest_name.h
using detail::NearestKey;

/// "unknown key, did you mean `gravity`?" or "unknown key (ignored)"; `noun` replaces "key".
std::string UnknownKeyMessage(std::string_view key, std::span<const std::string_view> known,
                              std::string_view noun = "key", std::string_view ignored = " (ignored)");

/// Warns about every key of a RUBE document the reader does not read (world, bodies, fixtures, shapes,
/// joints by type, images, custom properties), under its JSON path.
void WarnUnknownRubeKeys(const Json& root, DiagnosticList& diagnostics);

/// The top-level keys that mark an effects config ("particleTypes", "rules", ...) / a RUBE scene ("body",
/// "gravity", ...) found in `root`, joined as `"a", "b"`; empty when there are none.
std::string EffectsConfigKeys(const Json& root);
std::string RubeSceneKeys(const Json& root);

} // namespace cfx::scene_detail
