// CheckPolygon against Box2D itself: for every polygon of the project's scenes and of ../shared/rube-samples,
// and for polygons made to sit on Box2D's thresholds (welding distance, collinearity, area), our check
// accepts exactly what b2PolygonShape::Set accepts and keeps as many vertices.
//
// Box2D's library is built with asserts on, so the oracle runs b2PolygonShape::Set in a child process: an
// assert is an abort there, and a valid shape reports its vertex count and b2PolygonShape::Validate.
#include "scene/json_reader.h"
#include "scene/polygon_check.h"
#include "scene/rube_test_util.h"

#include <box2d/b2_polygon_shape.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <iostream>
#include <random>
#include <sys/wait.h>
#include <unistd.h>

namespace cfx::scene_detail
{
namespace
{

/// What Box2D makes of the vertices: the number of vertices of the polygon it builds, or 0 when it asserts
/// (or builds a polygon that fails Validate).
int Box2DKeeps(const std::vector<b2Vec2>& vertices)
{
    const pid_t child = fork();
    if (child == 0)
    {
        const int devNull = open("/dev/null", O_WRONLY);
        dup2(devNull, STDERR_FILENO); // the assert message
        b2PolygonShape shape;
        shape.Set(vertices.data(), static_cast<int32>(vertices.size()));
        _exit(shape.Validate() ? 100 + shape.m_count : 1);
    }
    int status = 0;
    waitpid(child, &status, 0);
    if (WIFEXITED(status) && WEXITSTATUS(status) > 100)
    {
        return WEXITSTATUS(status) - 100;
    }
    return 0;
}

/// Compares CheckPolygon with Box2D on `vertices`; `what` names the polygon in a failure.
void ExpectParity(const std::vector<b2Vec2>& vertices, const std::string& what)
{
    const PolygonCheck ours = CheckPolygon(vertices);
    const int box2d = Box2DKeeps(vertices);
    if (box2d == 0)
    {
        EXPECT_TRUE(ours.error) << what << ": Box2D asserts, we accept";
        return;
    }
    EXPECT_FALSE(ours.error) << what << ": Box2D builds " << box2d << " vertices, we say " << *ours.error;
    EXPECT_EQ(ours.kept, box2d) << what;
    EXPECT_EQ(vertices.size() - ours.dropped.size(), static_cast<std::size_t>(box2d)) << what;
}

struct FilePolygons
{
    int count = 0;
    int withDroppedVertices = 0;
};

FilePolygons CheckFile(const std::filesystem::path& file)
{
    FilePolygons found;
    const nlohmann::json root = test::ReadJson(file);
    if (!root.contains("body"))
    {
        return found;
    }
    for (std::size_t b = 0; b < root["body"].size(); ++b)
    {
        const nlohmann::json& body = root["body"][b];
        if (!body.contains("fixture"))
        {
            continue;
        }
        for (std::size_t f = 0; f < body["fixture"].size(); ++f)
        {
            const nlohmann::json& fixture = body["fixture"][f];
            if (!fixture.contains("polygon") || fixture["polygon"]["vertices"]["x"].size() < 3)
            {
                continue; // two vertices make an edge
            }
            const nlohmann::json& xs = fixture["polygon"]["vertices"]["x"];
            const nlohmann::json& ys = fixture["polygon"]["vertices"]["y"];
            std::vector<b2Vec2> vertices;
            for (std::size_t i = 0; i < xs.size(); ++i)
            {
                vertices.emplace_back(test::JsonFloat(xs[i]), test::JsonFloat(ys[i]));
            }
            ExpectParity(vertices, file.filename().string() + " body[" + std::to_string(b) + "].fixture[" +
                                       std::to_string(f) + "]");
            ++found.count;
            found.withDroppedVertices += CheckPolygon(vertices).dropped.empty() ? 0 : 1;
        }
    }
    return found;
}

TEST(PolygonParity, ProjectScenes)
{
    int polygons = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::filesystem::path(CONTACTFX_SOURCE_DIR) / "scenes"))
    {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() == ".json" && !name.ends_with(".effects.json"))
        {
            polygons += CheckFile(entry.path()).count;
        }
    }
    EXPECT_GT(polygons, 10);
    std::cout << polygons << " polygons of the project's scenes agree with Box2D\n";
}

TEST(PolygonParity, RubeSamples)
{
    CONTACTFX_REQUIRE_RUBE_SAMPLES();
    int polygons = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::RubeSamplesDir()))
    {
        if (entry.path().extension() == ".json")
        {
            polygons += CheckFile(entry.path()).count;
        }
    }
    EXPECT_GT(polygons, 10);
    std::cout << polygons << " polygons of the shared samples agree with Box2D\n";
}

/// Polygons on Box2D's edges: vertices about b2_linearSlop/2 apart, three vertices nearly on a line, areas
/// about b2_epsilon, more than 8 or fewer than 3 vertices, points inside the hull.
TEST(PolygonParity, PolygonsOnTheThresholds)
{
    std::mt19937 random(20240515U);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    auto jitter = [&](float scale) { return b2Vec2(scale * unit(random), scale * unit(random)); };
    int accepted = 0;
    int rejected = 0;
    for (int trial = 0; trial < 600; ++trial)
    {
        const int count = 3 + static_cast<int>(random() % 6);
        const float size = trial % 3 == 0 ? 0.01f : 1.0f;
        std::vector<b2Vec2> vertices;
        for (int i = 0; i < count; ++i)
        {
            vertices.push_back(size * jitter(1.0f));
        }
        switch (trial % 6)
        {
        case 0: // a vertex near the welding distance of another
        {
            const float angle = unit(random) * b2_pi;
            const float distance = 0.5f * b2_linearSlop * (1.0f + 0.02f * unit(random));
            vertices.back() = vertices[0] + distance * b2Vec2(std::cos(angle), std::sin(angle));
            break;
        }
        case 1: // a vertex nearly on the line through two others
        {
            const float t = unit(random);
            const b2Vec2 a = vertices[0];
            const b2Vec2 b = vertices[1];
            vertices.back() = a + t * (b - a) + jitter(1e-6f * size);
            break;
        }
        case 2: // all vertices nearly on one line
            for (b2Vec2& v : vertices)
            {
                v.y = 1e-5f * unit(random);
            }
            break;
        case 3: // a tiny triangle, its area about b2_epsilon
            vertices = {b2Vec2(0.0f, 0.0f), b2Vec2(0.006f, 0.0f),
                        b2Vec2(0.003f, 4e-5f * (1.0f + unit(random)))};
            break;
        case 4: // one vertex too many or too few
            vertices.resize(trial % 12 == 4 ? 9 : 2, b2Vec2(0.5f, 0.5f));
            break;
        default: // random points: many lie inside the hull
            break;
        }
        const PolygonCheck ours = CheckPolygon(vertices);
        (ours.error ? rejected : accepted) += 1;
        ExpectParity(vertices, "trial " + std::to_string(trial));
        if (HasFailure())
        {
            break;
        }
    }
    EXPECT_GT(accepted, 100);
    EXPECT_GT(rejected, 100);
    std::cout << accepted << " accepted and " << rejected << " refused by both\n";
}

} // namespace
} // namespace cfx::scene_detail
