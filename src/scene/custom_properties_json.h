// RUBE custom properties <-> JSON: an array of {"name": ..., one of "int" | "float" | "string" | "bool" |
// "vec2" | "color": value}; a color is [r, g, b, a] with integers 0..255.
#pragma once

#include "contactfx/scene/rube.h"
#include "scene/json_reader.h"
#include "scene/json_writer.h"

#include <string>

namespace cfx::scene_detail
{

/// The "customProperties" field of `owner` (empty when absent); problems are reported.
CustomProperties ReadCustomProperties(const ObjectReader& owner);

/// The JSON array for the properties, or null when there are none.
Json WriteCustomProperties(const CustomProperties& properties, JsonWriter& writer, const std::string& path);

} // namespace cfx::scene_detail
