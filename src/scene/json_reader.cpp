#include "scene/json_reader.h"

#include "quoted_text.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace cfx::scene_detail
{

namespace
{

constexpr std::size_t kMaxQuotedChars = 40;

std::string FormatDouble(double value)
{
    char buffer[64];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

/// Cuts a valid UTF-8 string at a character boundary.
std::string Shorten(const std::string& text)
{
    if (text.size() <= kMaxQuotedChars)
    {
        return text;
    }
    std::size_t end = kMaxQuotedChars;
    while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0U) == 0x80U)
    {
        --end;
    }
    return text.substr(0, end) + "...";
}

std::string Quote(const std::string& text)
{
    return Json(text).dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string LimitText(const NumberLimits& limits)
{
    const bool hasMin = std::isfinite(limits.min);
    const bool hasMax = std::isfinite(limits.max);
    const std::string lower = (limits.minExclusive ? "> " : ">= ") + FormatDouble(limits.min);
    if (hasMin && hasMax)
    {
        if (limits.minExclusive)
        {
            return lower + " and <= " + FormatDouble(limits.max);
        }
        return "between " + FormatDouble(limits.min) + " and " + FormatDouble(limits.max);
    }
    if (hasMin)
    {
        return lower;
    }
    return "<= " + FormatDouble(limits.max);
}

// A limit as the float a number written as the limit reads as; beyond float range, infinite.
float AsFloatLimit(double limit)
{
    constexpr double kFloatMax = std::numeric_limits<float>::max();
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    return std::fabs(limit) <= kFloatMax ? static_cast<float>(limit) : (limit < 0.0 ? -kInfinity : kInfinity);
}

// Compared as floats: the number was read into one, and the limit as written ("1e24") must pass even where
// the float it rounds to lies beyond the decimal value (1e24 as a float is 1.0000000138e24).
bool WithinLimits(float value, const NumberLimits& limits)
{
    const float min = AsFloatLimit(limits.min);
    if (limits.minExclusive ? !(value > min) : !(value >= min))
    {
        return false;
    }
    return value <= AsFloatLimit(limits.max);
}

std::string Missing(std::string_view expected)
{
    return "expected " + std::string(expected) + ", but the field is missing";
}

} // namespace

DiagnosticList::DiagnosticList(std::string file) : m_file(std::move(file)) {}

void DiagnosticList::Push(std::vector<Diagnostic>& items, bool& truncated, Diagnostic diagnostic)
{
    if (!truncated && items.size() + 1 < kLimit)
    {
        items.push_back(std::move(diagnostic));
        return;
    }
    if (!truncated)
    {
        truncated = true;
        Diagnostic note{diagnostic.file, "", ""};
        note.warning = diagnostic.warning;
        items.push_back(std::move(note));
    }
    // The note counts what it does not list, so that the total is still known.
    Diagnostic& note = items.back();
    note.unlisted += 1;
    note.message = "too many " + std::string(note.warning ? "warnings" : "problems") + ": " +
                   std::to_string(note.unlisted) + " more not listed (" +
                   std::to_string(kLimit - 1 + note.unlisted) + " in all)";
}

void DiagnosticList::Add(std::string path, std::string message)
{
    Push(m_items, m_truncated, Diagnostic{m_file, std::move(path), std::move(message)});
}

void DiagnosticList::AddAt(int line, int column, std::string message)
{
    Diagnostic diagnostic{m_file, "", std::move(message)};
    diagnostic.line = line;
    diagnostic.column = column;
    Push(m_items, m_truncated, std::move(diagnostic));
}

void DiagnosticList::Warn(std::string path, std::string message)
{
    Diagnostic diagnostic{m_file, std::move(path), std::move(message)};
    diagnostic.warning = true;
    Push(m_warnings, m_warningsTruncated, std::move(diagnostic));
}

std::vector<Diagnostic> DiagnosticList::Take()
{
    m_truncated = false;
    return std::exchange(m_items, {});
}

std::vector<Diagnostic> DiagnosticList::TakeWarnings()
{
    m_warningsTruncated = false;
    return std::exchange(m_warnings, {});
}

std::string JoinPath(std::string_view base, std::string_view key)
{
    // A key from the file may hold a line break: escaped, a problem stays one line.
    const std::string escaped = detail::EscapedText(key);
    if (base.empty())
    {
        return escaped;
    }
    std::string path;
    path.reserve(base.size() + 1 + escaped.size());
    path.append(base).append(".").append(escaped);
    return path;
}

std::string IndexPath(std::string_view base, std::size_t index)
{
    return std::string(base) + "[" + std::to_string(index) + "]";
}

std::string Describe(const Json& value)
{
    switch (value.type())
    {
    case Json::value_t::null:
        return "null";
    case Json::value_t::boolean:
        return value.get<bool>() ? "boolean true" : "boolean false";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
        return "number " + value.dump();
    case Json::value_t::string:
        return "string " + Quote(Shorten(value.get_ref<const std::string&>()));
    case Json::value_t::object:
        return "an object";
    case Json::value_t::array:
        return "an array";
    default:
        return "an unsupported value";
    }
}

std::string FormatFloat(float value)
{
    char buffer[64];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::optional<float> ParseHexFloat(std::string_view text)
{
    if (text.size() != 8)
    {
        return std::nullopt;
    }
    std::uint32_t bits = 0;
    for (char c : text)
    {
        std::uint32_t digit = 0;
        if (c >= '0' && c <= '9')
        {
            digit = static_cast<std::uint32_t>(c - '0');
        }
        else if (c >= 'A' && c <= 'F')
        {
            digit = static_cast<std::uint32_t>(c - 'A' + 10);
        }
        else if (c >= 'a' && c <= 'f')
        {
            digit = static_cast<std::uint32_t>(c - 'a' + 10);
        }
        else
        {
            return std::nullopt;
        }
        bits = (bits << 4U) | digit;
    }
    return std::bit_cast<float>(bits);
}

std::string FormatHexFloat(float value)
{
    static constexpr char kDigits[] = "0123456789ABCDEF";
    const auto bits = std::bit_cast<std::uint32_t>(value);
    std::string text(8, '0');
    for (int i = 0; i < 8; ++i)
    {
        text[static_cast<std::size_t>(7 - i)] = kDigits[(bits >> (4U * static_cast<unsigned>(i))) & 0xFU];
    }
    return text;
}

std::optional<float> ReadFloat(const Json& value, const std::string& path, DiagnosticList& diagnostics,
                               const NumberLimits& limits)
{
    float result = 0.0f;
    if (value.is_number())
    {
        const double number = value.get<double>();
        if (!std::isfinite(number))
        {
            diagnostics.Add(path, "expected a finite number, found " + Describe(value));
            return std::nullopt;
        }
        // Doubles below the midpoint between FLT_MAX and the next power of two still round to FLT_MAX
        // ("3.4028235e+38", FLT_MAX printed shortest, is one of them).
        constexpr double kFloatLimit = 0x1.ffffffp+127;
        constexpr double kFloatMax = std::numeric_limits<float>::max();
        if (!(std::fabs(number) < kFloatLimit))
        {
            diagnostics.Add(path, "expected a number within float range, found " + Describe(value));
            return std::nullopt;
        }
        result = static_cast<float>(std::clamp(number, -kFloatMax, kFloatMax));
    }
    else if (value.is_string())
    {
        const auto& text = value.get_ref<const std::string&>();
        const std::optional<float> hex = ParseHexFloat(text);
        if (!hex)
        {
            diagnostics.Add(path, "expected a number, found " + Describe(value));
            return std::nullopt;
        }
        if (std::isnan(*hex))
        {
            diagnostics.Add(path, "expected a finite number, found NaN (hex float " + Quote(text) + ")");
            return std::nullopt;
        }
        if (std::isinf(*hex))
        {
            diagnostics.Add(path, "expected a finite number, found " + std::string(*hex < 0 ? "-" : "") +
                                      "infinity (hex float " + Quote(text) + ")");
            return std::nullopt;
        }
        result = *hex;
    }
    else
    {
        diagnostics.Add(path, "expected a number, found " + Describe(value));
        return std::nullopt;
    }
    if (!WithinLimits(result, limits))
    {
        diagnostics.Add(path, "expected a number " + LimitText(limits) + ", found " + FormatFloat(result));
        return std::nullopt;
    }
    return result;
}

std::optional<b2Vec2> ReadVec(const Json& value, const std::string& path, DiagnosticList& diagnostics,
                              const NumberLimits& limits)
{
    if (value.is_number())
    {
        if (value.get<double>() == 0.0)
        {
            return b2Vec2(0.0f, 0.0f);
        }
        diagnostics.Add(path,
                        "expected a vector ({\"x\": number, \"y\": number} or 0), found " + Describe(value));
        return std::nullopt;
    }
    if (!value.is_object())
    {
        diagnostics.Add(path,
                        "expected a vector ({\"x\": number, \"y\": number} or 0), found " + Describe(value));
        return std::nullopt;
    }
    std::optional<float> x;
    std::optional<float> y;
    bool ok = true;
    for (const char* key : {"x", "y"})
    {
        auto field = value.find(key);
        const std::string fieldPath = JoinPath(path, key);
        if (field == value.end())
        {
            diagnostics.Add(fieldPath, Missing("a number"));
            ok = false;
            continue;
        }
        auto number = ReadFloat(*field, fieldPath, diagnostics, limits);
        if (!number)
        {
            ok = false;
        }
        (key[0] == 'x' ? x : y) = number;
    }
    if (!ok)
    {
        return std::nullopt;
    }
    return b2Vec2(*x, *y);
}

std::optional<long long> ReadInteger(const Json& value, const std::string& path, DiagnosticList& diagnostics,
                                     long long min, long long max)
{
    const std::string range = "an integer between " + std::to_string(min) + " and " + std::to_string(max);
    long long result = 0;
    if (value.is_number_integer())
    {
        if (value.is_number_unsigned())
        {
            const auto number = value.get<std::uint64_t>();
            if (number > static_cast<std::uint64_t>(std::numeric_limits<long long>::max()))
            {
                diagnostics.Add(path, "expected " + range + ", found " + Describe(value));
                return std::nullopt;
            }
            result = static_cast<long long>(number);
        }
        else
        {
            result = value.get<long long>();
        }
    }
    else if (value.is_number_float())
    {
        const double number = value.get<double>();
        if (!std::isfinite(number) || std::floor(number) != number)
        {
            diagnostics.Add(path, "expected an integer, found " + Describe(value));
            return std::nullopt;
        }
        if (number < static_cast<double>(min) || number > static_cast<double>(max))
        {
            diagnostics.Add(path, "expected " + range + ", found " + Describe(value));
            return std::nullopt;
        }
        result = static_cast<long long>(number);
    }
    else
    {
        diagnostics.Add(path, "expected an integer, found " + Describe(value));
        return std::nullopt;
    }
    if (result < min || result > max)
    {
        diagnostics.Add(path, "expected " + range + ", found " + Describe(value));
        return std::nullopt;
    }
    return result;
}

std::optional<bool> ReadBool(const Json& value, const std::string& path, DiagnosticList& diagnostics)
{
    if (!value.is_boolean())
    {
        diagnostics.Add(path, "expected true or false, found " + Describe(value));
        return std::nullopt;
    }
    return value.get<bool>();
}

std::optional<std::string> ReadString(const Json& value, const std::string& path, DiagnosticList& diagnostics)
{
    if (!value.is_string())
    {
        diagnostics.Add(path, "expected a string, found " + Describe(value));
        return std::nullopt;
    }
    return value.get<std::string>();
}

std::optional<std::vector<float>> ReadFloatArray(const Json& value, const std::string& path,
                                                 DiagnosticList& diagnostics, const NumberLimits& limits)
{
    if (!value.is_array())
    {
        diagnostics.Add(path, "expected an array of numbers, found " + Describe(value));
        return std::nullopt;
    }
    std::vector<float> numbers;
    numbers.reserve(value.size());
    bool ok = true;
    for (std::size_t i = 0; i < value.size(); ++i)
    {
        auto number = ReadFloat(value[i], IndexPath(path, i), diagnostics, limits);
        ok = ok && number.has_value();
        numbers.push_back(number.value_or(0.0f));
    }
    if (!ok)
    {
        return std::nullopt;
    }
    return numbers;
}

std::optional<std::vector<b2Vec2>> ReadVertexList(const Json& value, const std::string& path,
                                                  DiagnosticList& diagnostics, const NumberLimits& limits)
{
    if (!value.is_object())
    {
        diagnostics.Add(path, "expected a vertex list {\"x\": [numbers], \"y\": [numbers]}, found " +
                                  Describe(value));
        return std::nullopt;
    }
    std::optional<std::vector<float>> coordinates[2];
    bool ok = true;
    for (int axis = 0; axis < 2; ++axis)
    {
        const char* key = axis == 0 ? "x" : "y";
        auto field = value.find(key);
        if (field == value.end())
        {
            diagnostics.Add(JoinPath(path, key), Missing("an array of numbers"));
            ok = false;
            continue;
        }
        coordinates[axis] = ReadFloatArray(*field, JoinPath(path, key), diagnostics, limits);
        ok = ok && coordinates[axis].has_value();
    }
    if (!ok)
    {
        return std::nullopt;
    }
    if (coordinates[0]->size() != coordinates[1]->size())
    {
        diagnostics.Add(path, "expected as many y as x values, found " +
                                  std::to_string(coordinates[0]->size()) + " x and " +
                                  std::to_string(coordinates[1]->size()) + " y");
        return std::nullopt;
    }
    std::vector<b2Vec2> vertices(coordinates[0]->size());
    for (std::size_t i = 0; i < vertices.size(); ++i)
    {
        vertices[i] = b2Vec2((*coordinates[0])[i], (*coordinates[1])[i]);
    }
    return vertices;
}

ObjectReader::ObjectReader(const Json& object, std::string path, DiagnosticList& diagnostics)
    : m_object(object), m_path(std::move(path)), m_diagnostics(diagnostics)
{
}

const Json* ObjectReader::Find(std::string_view key) const
{
    if (!m_object.is_object())
    {
        return nullptr;
    }
    auto it = m_object.find(std::string(key));
    return it == m_object.end() ? nullptr : &*it;
}

float ObjectReader::Float(std::string_view key, float fallback, const NumberLimits& limits) const
{
    return OptionalFloat(key, limits).value_or(fallback);
}

std::optional<float> ObjectReader::OptionalFloat(std::string_view key, const NumberLimits& limits) const
{
    const Json* value = Find(key);
    if (value == nullptr)
    {
        return std::nullopt;
    }
    return ReadFloat(*value, FieldPath(key), m_diagnostics, limits);
}

b2Vec2 ObjectReader::Vec(std::string_view key, b2Vec2 fallback, const NumberLimits& limits) const
{
    const Json* value = Find(key);
    if (value == nullptr)
    {
        return fallback;
    }
    return ReadVec(*value, FieldPath(key), m_diagnostics, limits).value_or(fallback);
}

bool ObjectReader::Bool(std::string_view key, bool fallback) const
{
    const Json* value = Find(key);
    if (value == nullptr)
    {
        return fallback;
    }
    return ReadBool(*value, FieldPath(key), m_diagnostics).value_or(fallback);
}

int ObjectReader::Int(std::string_view key, int fallback, int min, int max) const
{
    const Json* value = Find(key);
    if (value == nullptr)
    {
        return fallback;
    }
    auto number = ReadInteger(*value, FieldPath(key), m_diagnostics, min, max);
    return number ? static_cast<int>(*number) : fallback;
}

std::string ObjectReader::String(std::string_view key, std::string fallback) const
{
    const Json* value = Find(key);
    if (value == nullptr)
    {
        return fallback;
    }
    auto text = ReadString(*value, FieldPath(key), m_diagnostics);
    return text ? std::move(*text) : fallback;
}

const Json* ObjectReader::Array(std::string_view key) const
{
    const Json* value = Find(key);
    if (value == nullptr)
    {
        return nullptr;
    }
    if (!value->is_array())
    {
        m_diagnostics.Add(FieldPath(key), "expected an array, found " + Describe(*value));
        return nullptr;
    }
    return value;
}

const Json* ObjectReader::Object(std::string_view key) const
{
    const Json* value = Find(key);
    if (value == nullptr)
    {
        return nullptr;
    }
    if (!value->is_object())
    {
        m_diagnostics.Add(FieldPath(key), "expected an object, found " + Describe(*value));
        return nullptr;
    }
    return value;
}

} // namespace cfx::scene_detail
