// Writing numbers and vectors as JSON that reads back to the same floats.
#pragma once

#include "scene/json_reader.h"

#include <box2d/b2_math.h>
#include <span>
#include <string>

namespace cfx::scene_detail
{

/// The JSON number that reads back as exactly `value` (the shortest decimal when it round-trips through
/// double, as it nearly always does). `value` must be finite.
Json ExactFloat(float value);

/// Builds JSON values from floats, reporting non-finite ones (which JSON cannot hold) under their path.
class JsonWriter
{
public:
    explicit JsonWriter(DiagnosticList& diagnostics) : m_diagnostics(diagnostics) {}

    Json Float(float value, const std::string& path);
    /// {"x": ..., "y": ...}
    Json Vec(b2Vec2 value, const std::string& path);
    /// {"x": [...], "y": [...]}
    Json VertexList(std::span<const b2Vec2> vertices, const std::string& path);

private:
    DiagnosticList& m_diagnostics;
};

} // namespace cfx::scene_detail
