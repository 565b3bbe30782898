// Typed access to a parsed JSON document with paths and diagnostics.
//
// Every reader here reports what it expected and what it found under the JSON path of the value
// (`body[3].fixture[0].friction`) and returns nothing (or the caller's fallback) on a problem, so that a
// loader can go on and collect every problem of a file in one pass. Numbers follow the b2dJson rules: a plain
// number, or an 8-hex-digit string holding the bits of an IEEE float; a vector is {"x", "y"} or the number 0.
#pragma once

#include "contactfx/error.h"

#include <box2d/b2_math.h>
#include <cstddef>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cfx::scene_detail
{

using Json = nlohmann::json;

/// The diagnostics of one input: errors, and apart from them warnings (Diagnostic::warning). Each list keeps
/// at most kLimit - 1 entries and then ends with a note counting the rest (Diagnostic::unlisted), so that a
/// hostile file cannot make it grow without bound and the total is still known (CountProblems). Empty()
/// and Size() count the errors' entries only.
class DiagnosticList
{
public:
    static constexpr std::size_t kLimit = 1000;

    explicit DiagnosticList(std::string file);

    void Add(std::string path, std::string message);
    void AddAt(int line, int column, std::string message);
    /// A warning: the input still loads.
    void Warn(std::string path, std::string message);

    bool Empty() const { return m_items.empty(); }
    std::size_t Size() const { return m_items.size(); }
    const std::string& File() const { return m_file; }
    const std::vector<Diagnostic>& Items() const { return m_items; }
    const std::vector<Diagnostic>& Warnings() const { return m_warnings; }
    std::vector<Diagnostic> Take();
    std::vector<Diagnostic> TakeWarnings();

private:
    static void Push(std::vector<Diagnostic>& items, bool& truncated, Diagnostic diagnostic);

    std::string m_file;
    std::vector<Diagnostic> m_items;
    std::vector<Diagnostic> m_warnings;
    bool m_truncated = false;
    bool m_warningsTruncated = false;
};

/// Allowed interval of a number read from the file. Every number must also be finite.
struct NumberLimits
{
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool minExclusive = false;
};

/// Limits shared by the loader: Box2D works in metres and behaves for worlds of a few kilometres; the bound
/// keeps every derived quantity (areas, inertias, AABBs) far from float overflow.
inline constexpr double kMaxCoordinate = 1.0e6;
inline constexpr NumberLimits kAnyFinite{};
inline constexpr NumberLimits kNonNegative{0.0, std::numeric_limits<double>::infinity(), false};
inline constexpr NumberLimits kPositive{0.0, std::numeric_limits<double>::infinity(), true};
inline constexpr NumberLimits kCoordinate{-kMaxCoordinate, kMaxCoordinate, false};
inline constexpr NumberLimits kLength{0.0, kMaxCoordinate, false};

/// "base.key" ("key" when base is empty), the key escaped as detail::EscapedText escapes it: a key from a
/// file may hold a line break, and a problem is one line.
std::string JoinPath(std::string_view base, std::string_view key);
std::string IndexPath(std::string_view base, std::size_t index);

/// A short description of a JSON value for messages: `string "abc"`, `number 1.5`, `an object`, ...
std::string Describe(const Json& value);

/// Shortest text that reads back as the same float ("0.2", "-1e+30", "nan").
std::string FormatFloat(float value);

/// The float whose IEEE bits the text spells as 8 hex digits ("3F800000" -> 1.0), or nothing.
std::optional<float> ParseHexFloat(std::string_view text);
/// The 8 upper-case hex digits of the float's bits.
std::string FormatHexFloat(float value);

/// Value readers: report under `path` and return nothing on a problem.
std::optional<float> ReadFloat(const Json& value, const std::string& path, DiagnosticList& diagnostics,
                               const NumberLimits& limits = kAnyFinite);
std::optional<b2Vec2> ReadVec(const Json& value, const std::string& path, DiagnosticList& diagnostics,
                              const NumberLimits& limits = kAnyFinite);
std::optional<long long> ReadInteger(const Json& value, const std::string& path, DiagnosticList& diagnostics,
                                     long long min, long long max);
std::optional<bool> ReadBool(const Json& value, const std::string& path, DiagnosticList& diagnostics);
std::optional<std::string> ReadString(const Json& value, const std::string& path,
                                      DiagnosticList& diagnostics);
/// {"x": [...], "y": [...]} with arrays of equal length.
std::optional<std::vector<b2Vec2>> ReadVertexList(const Json& value, const std::string& path,
                                                  DiagnosticList& diagnostics, const NumberLimits& limits);
/// An array of numbers.
std::optional<std::vector<float>> ReadFloatArray(const Json& value, const std::string& path,
                                                 DiagnosticList& diagnostics, const NumberLimits& limits);

/// The fields of one JSON object. A missing field yields the fallback; a bad one is reported and also
/// yields the fallback.
class ObjectReader
{
public:
    ObjectReader(const Json& object, std::string path, DiagnosticList& diagnostics);

    const std::string& Path() const { return m_path; }
    std::string FieldPath(std::string_view key) const { return JoinPath(m_path, key); }
    DiagnosticList& Diagnostics() const { return m_diagnostics; }

    /// The field, or nullptr when absent.
    const Json* Find(std::string_view key) const;
    bool Has(std::string_view key) const { return Find(key) != nullptr; }

    float Float(std::string_view key, float fallback, const NumberLimits& limits = kAnyFinite) const;
    std::optional<float> OptionalFloat(std::string_view key, const NumberLimits& limits = kAnyFinite) const;
    b2Vec2 Vec(std::string_view key, b2Vec2 fallback, const NumberLimits& limits = kAnyFinite) const;
    bool Bool(std::string_view key, bool fallback) const;
    int Int(std::string_view key, int fallback, int min, int max) const;
    std::string String(std::string_view key, std::string fallback = {}) const;

    /// An array field: nullptr when absent or (reported) not an array.
    const Json* Array(std::string_view key) const;
    /// An object field: nullptr when absent or (reported) not an object.
    const Json* Object(std::string_view key) const;

private:
    const Json& m_object;
    std::string m_path;
    DiagnosticList& m_diagnostics;
};

} // namespace cfx::scene_detail
