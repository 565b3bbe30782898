#include "field_widgets.h"

namespace cfx::testbed
{

DragBounds DragBoundsOf(const FieldRange& range, float step)
{
    DragBounds bounds;
    bounds.low = range.minExclusive ? range.min + kShownStep : range.min;
    bounds.high = range.max;
    bounds.speed = step > 0.0f ? step : kShownStep;
    return bounds;
}

std::string LabelOf(std::string_view prefix, std::string_view name, std::string_view unit)
{
    std::string label = std::string(prefix) + std::string(name);
    if (!unit.empty())
    {
        label += " (" + std::string(unit) + ")";
    }
    return label;
}

} // namespace cfx::testbed
