// contactfx-testbed: how the effects editor shows a field of the configuration tables.
//
// The editor draws one widget per row of contactfx/config_fields.h; what a widget allows comes from the
// row, never from numbers of its own, so that everything the editor can produce is a value Validate
// accepts (tests/testbed checks it for every row).
#pragma once

#include "contactfx/config_fields.h"

#include <string>
#include <string_view>

namespace cfx::testbed
{

/// Digits after the point that number widgets show ("%.3f"), and the smallest step they show.
inline constexpr const char* kNumberFormat = "%.3f";
inline constexpr float kShownStep = 0.001f;

/// What a number widget keeps its value in, and its step.
struct DragBounds
{
    float low = 0.0f;
    float high = 0.0f;
    float speed = 0.0f; ///< one press of its - or + button
};

/// The field's range, an exclusive minimum moved up by the smallest step the widget shows.
DragBounds DragBoundsOf(const FieldRange& range, float step);

/// "lifetime (s)": the field's name (after `prefix`, for nested fields), and its unit when it has one.
std::string LabelOf(std::string_view prefix, std::string_view name, std::string_view unit);

} // namespace cfx::testbed
