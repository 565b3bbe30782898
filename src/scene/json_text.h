// Parsing JSON text with positions: malformed input is reported with its line and column.
#pragma once

#include "scene/json_reader.h"

#include <cstddef>
#include <optional>
#include <string_view>

namespace cfx::scene_detail
{

/// 1-based line and column of the byte at `offset` (clamped to the end of the text).
struct TextPosition
{
    int line = 1;
    int column = 1;
};
TextPosition PositionOfOffset(std::string_view text, std::size_t offset);

/// The document, or nothing after reporting where and why the text is not JSON.
std::optional<Json> ParseJsonText(std::string_view text, DiagnosticList& diagnostics);

} // namespace cfx::scene_detail
