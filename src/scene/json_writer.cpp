#include "scene/json_writer.h"

#include <charconv>
#include <cmath>

namespace cfx::scene_detail
{

Json ExactFloat(float value)
{
    const std::string text = FormatFloat(value);
    double shortest = 0.0;
    auto result = std::from_chars(text.data(), text.data() + text.size(), shortest);
    if (result.ec == std::errc() && static_cast<float>(shortest) == value)
    {
        return Json(shortest);
    }
    return Json(static_cast<double>(value));
}

Json JsonWriter::Float(float value, const std::string& path)
{
    if (!std::isfinite(value))
    {
        m_diagnostics.Add(path, "cannot save " + FormatFloat(value) + ": JSON holds finite numbers only");
        return Json(0.0);
    }
    return ExactFloat(value);
}

Json JsonWriter::Vec(b2Vec2 value, const std::string& path)
{
    Json vec = Json::object();
    vec["x"] = Float(value.x, JoinPath(path, "x"));
    vec["y"] = Float(value.y, JoinPath(path, "y"));
    return vec;
}

Json JsonWriter::VertexList(std::span<const b2Vec2> vertices, const std::string& path)
{
    Json xs = Json::array();
    Json ys = Json::array();
    for (std::size_t i = 0; i < vertices.size(); ++i)
    {
        xs.push_back(Float(vertices[i].x, IndexPath(JoinPath(path, "x"), i)));
        ys.push_back(Float(vertices[i].y, IndexPath(JoinPath(path, "y"), i)));
    }
    Json list = Json::object();
    list["x"] = std::move(xs);
    list["y"] = std::move(ys);
    return list;
}

} // namespace cfx::scene_detail
