// The effects editor's widgets take their bounds from the field tables: whatever a number widget can be
// dragged to is a value Validate accepts.
#include "field_widgets.h"

#include <gtest/gtest.h>

namespace cfx::testbed
{

namespace
{

template <typename S> void ExpectBoundsInsideRanges(std::span<const Field<S>> fields)
{
    for (const Field<S>& field : fields)
    {
        if (field.member.index() > 1) // float and optional float are the dragged numbers
        {
            continue;
        }
        const DragBounds bounds = DragBoundsOf(field.range, field.step);
        EXPECT_TRUE(field.range.Contains(bounds.low)) << field.name << " low " << bounds.low;
        EXPECT_TRUE(field.range.Contains(bounds.high)) << field.name << " high " << bounds.high;
        EXPECT_LT(bounds.low, bounds.high) << field.name;
        EXPECT_GT(bounds.speed, 0.0f) << field.name;
    }
}

} // namespace

TEST(FieldWidgets, EveryNumberWidgetStaysInsideTheFieldsRange)
{
    ExpectBoundsInsideRanges(ParticleTypeFields());
    ExpectBoundsInsideRanges(RuleFields());
    ExpectBoundsInsideRanges(IntensityFields());
    ExpectBoundsInsideRanges(AssignmentFields());
    ExpectBoundsInsideRanges(BudgetFields());
}

TEST(FieldWidgets, LabelsShowTheUnit)
{
    EXPECT_EQ(LabelOf("", "lifetime", "s"), "lifetime (s)");
    EXPECT_EQ(LabelOf("intensity.", "speed", ""), "intensity.speed");
}

} // namespace cfx::testbed
