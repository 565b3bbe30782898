// Typed JSON access: hex floats, the zero-vector shorthand, paths, positions of malformed JSON.
#include "scene/json_reader.h"
#include "scene/json_text.h"
#include "scene/json_writer.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace cfx::scene_detail
{
namespace
{

TEST(HexFloat, ParsesIeeeBits)
{
    EXPECT_EQ(ParseHexFloat("3F800000"), 1.0f);
    EXPECT_EQ(ParseHexFloat("3f800000"), 1.0f);
    EXPECT_EQ(ParseHexFloat("BF800000"), -1.0f);
    EXPECT_EQ(ParseHexFloat("00000000"), 0.0f);
    EXPECT_EQ(ParseHexFloat("40490FDB"), 3.14159274f);
    EXPECT_FALSE(ParseHexFloat("3F80000"));   // 7 digits
    EXPECT_FALSE(ParseHexFloat("3F8000000")); // 9 digits
    EXPECT_FALSE(ParseHexFloat("3G800000"));
    EXPECT_FALSE(ParseHexFloat("abc"));
    EXPECT_TRUE(std::isnan(*ParseHexFloat("7FC00000")));
}

TEST(HexFloat, FormatsAndParsesBack)
{
    for (float value : {0.0f, -0.0f, 1.0f, 0.1f, -123.456f, 1e-30f, 3.4e38f})
    {
        EXPECT_EQ(std::bit_cast<std::uint32_t>(*ParseHexFloat(FormatHexFloat(value))),
                  std::bit_cast<std::uint32_t>(value));
    }
    EXPECT_EQ(FormatHexFloat(1.0f), "3F800000");
}

TEST(ReadFloat, AcceptsNumbersAndHexAndReportsTheRest)
{
    DiagnosticList diagnostics("f.json");
    EXPECT_EQ(ReadFloat(Json(2.5), "a", diagnostics), 2.5f);
    EXPECT_EQ(ReadFloat(Json(3), "a", diagnostics), 3.0f);
    EXPECT_EQ(ReadFloat(Json("40200000"), "a", diagnostics), 2.5f);
    EXPECT_TRUE(diagnostics.Empty());

    EXPECT_FALSE(ReadFloat(Json("abc"), "body[0].angle", diagnostics));
    ASSERT_EQ(diagnostics.Size(), 1u);
    EXPECT_EQ(diagnostics.Items()[0].path, "body[0].angle");
    EXPECT_EQ(diagnostics.Items()[0].message, "expected a number, found string \"abc\"");

    EXPECT_FALSE(ReadFloat(Json("7FC00000"), "p", diagnostics));
    EXPECT_NE(diagnostics.Items().back().message.find("NaN"), std::string::npos);
    EXPECT_FALSE(ReadFloat(Json("7F800000"), "p", diagnostics));
    EXPECT_NE(diagnostics.Items().back().message.find("infinity"), std::string::npos);
    EXPECT_FALSE(ReadFloat(Json(1e39), "p", diagnostics));
    EXPECT_NE(diagnostics.Items().back().message.find("float range"), std::string::npos);
    EXPECT_EQ(ReadFloat(Json::parse("3.4028235e+38"), "p", diagnostics), std::numeric_limits<float>::max());
    EXPECT_FALSE(ReadFloat(Json::parse("3.4028236e+38"), "p", diagnostics));
    EXPECT_FALSE(ReadFloat(Json(true), "p", diagnostics));
    EXPECT_EQ(diagnostics.Items().back().message, "expected a number, found boolean true");
    EXPECT_FALSE(ReadFloat(Json(-1.0), "p", diagnostics, kNonNegative));
    EXPECT_EQ(diagnostics.Items().back().message, "expected a number >= 0, found -1");
    EXPECT_FALSE(ReadFloat(Json(0), "p", diagnostics, kPositive));
    EXPECT_EQ(diagnostics.Items().back().message, "expected a number > 0, found 0");
}

TEST(ReadVec, AcceptsObjectsAndTheZeroShorthand)
{
    DiagnosticList diagnostics("f.json");
    auto zero = ReadVec(Json(0), "v", diagnostics);
    ASSERT_TRUE(zero);
    EXPECT_EQ(zero->x, 0.0f);
    EXPECT_EQ(zero->y, 0.0f);
    auto vec = ReadVec(Json::parse(R"({"x": 1.5, "y": "BF800000"})"), "v", diagnostics);
    ASSERT_TRUE(vec);
    EXPECT_EQ(vec->x, 1.5f);
    EXPECT_EQ(vec->y, -1.0f);
    EXPECT_TRUE(diagnostics.Empty());

    EXPECT_FALSE(ReadVec(Json(1), "v", diagnostics));
    EXPECT_FALSE(ReadVec(Json::parse(R"({"x": 1})"), "v", diagnostics));
    EXPECT_EQ(diagnostics.Items().back().path, "v.y");
    EXPECT_FALSE(ReadVec(Json::parse(R"([1, 2])"), "v", diagnostics));
    EXPECT_EQ(diagnostics.Size(), 3u);
}

TEST(ReadInteger, RequiresIntegersInRange)
{
    DiagnosticList diagnostics("f.json");
    EXPECT_EQ(ReadInteger(Json(2), "t", diagnostics, 0, 2), 2);
    EXPECT_EQ(ReadInteger(Json(2.0), "t", diagnostics, 0, 2), 2);
    EXPECT_TRUE(diagnostics.Empty());
    EXPECT_FALSE(ReadInteger(Json(3), "t", diagnostics, 0, 2));
    EXPECT_EQ(diagnostics.Items().back().message, "expected an integer between 0 and 2, found number 3");
    EXPECT_FALSE(ReadInteger(Json(1.5), "t", diagnostics, 0, 2));
    EXPECT_FALSE(ReadInteger(Json(18446744073709551615ull), "t", diagnostics, 0, 2));
    EXPECT_FALSE(ReadInteger(Json("1"), "t", diagnostics, 0, 2));
    EXPECT_EQ(diagnostics.Size(), 4u);
}

TEST(ReadFloat, ALimitAsWrittenIsWithinItself)
{
    // 1e24 and 0.1 as floats lie above the decimal values; the numbers written as the limits still pass,
    // and the next float beyond them does not.
    DiagnosticList diagnostics("f.json");
    EXPECT_EQ(ReadFloat(Json(1e24), "a", diagnostics, NumberLimits{0.0, 1e24}), 1e24f);
    EXPECT_EQ(ReadFloat(Json(0.1), "a", diagnostics, NumberLimits{-0.1, 0.1}), 0.1f);
    EXPECT_EQ(ReadFloat(Json(-0.1), "a", diagnostics, NumberLimits{-0.1, 0.1}), -0.1f);
    EXPECT_TRUE(diagnostics.Empty()) << diagnostics.Items().front().ToString();
    EXPECT_FALSE(ReadFloat(Json(static_cast<double>(std::nextafter(1e24f, 2e24f))), "a", diagnostics,
                           NumberLimits{0.0, 1e24}));
    EXPECT_FALSE(ReadFloat(Json(0.1), "a", diagnostics, NumberLimits{0.1, 1.0, true}));
    EXPECT_EQ(diagnostics.Size(), 2u);
}

TEST(Paths, JoinKeysAndIndices)
{
    EXPECT_EQ(JoinPath("", "body"), "body");
    EXPECT_EQ(JoinPath(IndexPath(JoinPath(IndexPath("body", 3), "fixture"), 0), "friction"),
              "body[3].fixture[0].friction");
}

TEST(DiagnosticList, StopsAtItsLimit)
{
    DiagnosticList diagnostics("f.json");
    for (int i = 0; i < 5000; ++i)
    {
        diagnostics.Add("p", "m");
    }
    EXPECT_EQ(diagnostics.Size(), DiagnosticList::kLimit);
    // The last entry is a note counting the rest, not a problem of its own: the total is still known.
    const Diagnostic& note = diagnostics.Items().back();
    EXPECT_EQ(note.message, "too many problems: 4001 more not listed (5000 in all)");
    EXPECT_EQ(note.unlisted, 4001u);
    EXPECT_EQ(diagnostics.Items()[DiagnosticList::kLimit - 2].unlisted, 0u);
    EXPECT_EQ(CountProblems(diagnostics.Items()), 5000u);
    for (int i = 0; i < 2000; ++i)
    {
        diagnostics.Warn("p", "w");
    }
    EXPECT_EQ(diagnostics.Warnings().back().message, "too many warnings: 1001 more not listed (2000 in all)");
    EXPECT_EQ(CountProblems(diagnostics.Warnings()), 2000u);
}

TEST(DiagnosticList, ListsEverythingUpToItsLimit)
{
    DiagnosticList diagnostics("f.json");
    for (std::size_t i = 0; i < DiagnosticList::kLimit - 1; ++i)
    {
        diagnostics.Add("p", "m");
    }
    EXPECT_EQ(diagnostics.Items().back().message, "m");
    EXPECT_EQ(CountProblems(diagnostics.Items()), DiagnosticList::kLimit - 1);
    diagnostics.Add("p", "m");
    EXPECT_EQ(diagnostics.Items().back().message, "too many problems: 1 more not listed (1000 in all)");
    EXPECT_EQ(CountProblems(diagnostics.Items()), DiagnosticList::kLimit);
}

TEST(JsonText, ReportsLineAndColumnOfMalformedJson)
{
    DiagnosticList diagnostics("f.json");
    EXPECT_FALSE(ParseJsonText("{\n  \"a\": 1,\n  \"b\": ]\n}", diagnostics));
    ASSERT_EQ(diagnostics.Size(), 1u);
    EXPECT_EQ(diagnostics.Items()[0].line, 3);
    EXPECT_EQ(diagnostics.Items()[0].column, 8);
    EXPECT_NE(diagnostics.Items()[0].message.find("malformed JSON"), std::string::npos);

    DiagnosticList truncated("f.json");
    EXPECT_FALSE(ParseJsonText("{\n  \"a\": [1, 2", truncated));
    ASSERT_EQ(truncated.Size(), 1u);
    EXPECT_EQ(truncated.Items()[0].line, 2);
    EXPECT_GT(truncated.Items()[0].column, 0);

    DiagnosticList overflow("f.json");
    EXPECT_FALSE(ParseJsonText("{\"a\": 1e400}", overflow));
    ASSERT_EQ(overflow.Size(), 1u);
    EXPECT_EQ(overflow.Items()[0].line, 1);
    EXPECT_GT(overflow.Items()[0].column, 0);
}

// A repeated key is reported under its JSON path (nlohmann would keep the last value silently); the
// document is still built, so that the reader goes on and reports the other problems too.
TEST(JsonText, ReportsDuplicateKeysWithTheirPath)
{
    DiagnosticList diagnostics("f.json");
    const std::optional<Json> document = ParseJsonText(
        R"({"a": [1, {"b": {"c": 1, "c": 2}}], "d": [{"k": 1}, {"k": 2}], "a": 3})", diagnostics);
    ASSERT_TRUE(document.has_value());
    ASSERT_EQ(diagnostics.Size(), 2u);
    EXPECT_EQ(diagnostics.Items()[0].path, "a[1].b.c");
    EXPECT_EQ(diagnostics.Items()[0].message, "duplicate key \"c\": each key may appear once in an object");
    EXPECT_EQ(diagnostics.Items()[0].file, "f.json");
    EXPECT_EQ(diagnostics.Items()[1].path, "a");

    DiagnosticList none("f.json"); // the same key in different objects, nested or side by side, is fine
    EXPECT_TRUE(ParseJsonText(R"({"k": {"k": [{"k": 1}, {"k": 2}]}})", none).has_value());
    EXPECT_TRUE(none.Empty());
}

TEST(JsonText, PositionOfOffset)
{
    const std::string text = "ab\ncd\n\nef";
    EXPECT_EQ(PositionOfOffset(text, 0).line, 1);
    EXPECT_EQ(PositionOfOffset(text, 0).column, 1);
    EXPECT_EQ(PositionOfOffset(text, 4).line, 2);
    EXPECT_EQ(PositionOfOffset(text, 4).column, 2);
    EXPECT_EQ(PositionOfOffset(text, 7).line, 4);
    EXPECT_EQ(PositionOfOffset(text, 7).column, 1);
    EXPECT_EQ(PositionOfOffset(text, 100).line, 4); // clamped to the end
}

TEST(JsonText, SurvivesDeepNesting)
{
    DiagnosticList diagnostics("f.json");
    const std::string deep = std::string(200000, '[') + std::string(200000, ']');
    auto document = ParseJsonText(deep, diagnostics);
    EXPECT_TRUE(document.has_value());
}

TEST(ExactFloat, ReadsBackToTheSameFloat)
{
    std::uint32_t state = 12345;
    for (int i = 0; i < 100000; ++i)
    {
        state = state * 1664525u + 1013904223u;
        const float value = std::bit_cast<float>(state);
        if (!std::isfinite(value))
        {
            continue;
        }
        const Json number = Json::parse(ExactFloat(value).dump());
        ASSERT_EQ(static_cast<float>(number.get<double>()), value) << number.dump();
    }
    EXPECT_EQ(ExactFloat(0.2f).dump(), "0.2");
}

} // namespace
} // namespace cfx::scene_detail
