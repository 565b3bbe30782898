#include "gl_draw.h"

#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace cfx::testbed
{

namespace
{

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec2 position;
layout(location = 1) in vec4 color;
layout(location = 2) in vec2 local;
uniform vec4 transform; // xy: scale, zw: offset, world metres -> clip space
out vec4 vColor;
out vec2 vLocal;
void main()
{
    vColor = color;
    vLocal = local;
    gl_Position = vec4(position * transform.xy + transform.zw, 0.0, 1.0);
}
)";

// Solid geometry has local = (0, 0) and keeps its colour; sprites fade out towards their rim.
constexpr const char* kFragmentShader = R"(#version 330 core
in vec4 vColor;
in vec2 vLocal;
out vec4 fragColor;
void main()
{
    float r2 = dot(vLocal, vLocal);
    if (r2 > 1.0)
        discard;
    fragColor = vec4(vColor.rgb, vColor.a * (1.0 - smoothstep(0.35, 1.0, r2)));
}
)";

constexpr int kCircleSegments = 32;

GLuint Compile(GLenum kind, const char* source)
{
    const GLuint shader = glCreateShader(kind);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE)
    {
        std::array<char, 1024> log{};
        glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
        glDeleteShader(shader);
        throw std::runtime_error(std::string("OpenGL refused the testbed's shader: ") + log.data());
    }
    return shader;
}

std::array<b2Vec2, kCircleSegments> CirclePoints(b2Vec2 center, float radius)
{
    std::array<b2Vec2, kCircleSegments> points;
    for (int i = 0; i < kCircleSegments; ++i)
    {
        const float angle = 2.0f * b2_pi * static_cast<float>(i) / kCircleSegments;
        points[i] = center + radius * b2Vec2(std::cos(angle), std::sin(angle));
    }
    return points;
}

} // namespace

GlDraw::GlDraw(const render::RenderStyle& style) : m_style(style)
{
    const GLuint vertex = Compile(GL_VERTEX_SHADER, kVertexShader);
    const GLuint fragment = Compile(GL_FRAGMENT_SHADER, kFragmentShader);
    m_program = glCreateProgram();
    glAttachShader(m_program, vertex);
    glAttachShader(m_program, fragment);
    glLinkProgram(m_program);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    GLint ok = GL_FALSE;
    glGetProgramiv(m_program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE)
    {
        glDeleteProgram(m_program);
        throw std::runtime_error("OpenGL refused to link the testbed's shader");
    }
    m_transform = glGetUniformLocation(m_program, "transform");

    glGenVertexArrays(1, &m_vao);
    glGenBuffers(1, &m_vbo);
    glBindVertexArray(m_vao);
    glBindBuffer(GL_ARRAY_BUFFER, m_vbo);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, x)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, r)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, u)));
    glBindVertexArray(0);
}

GlDraw::~GlDraw()
{
    glDeleteBuffers(1, &m_vbo);
    glDeleteVertexArrays(1, &m_vao);
    glDeleteProgram(m_program);
}

void GlDraw::Begin(const render::Camera& camera)
{
    m_camera = camera;
    m_fills.clear();
    m_lines.clear();
    m_particles.clear();
}

void GlDraw::Upload(const std::vector<Vertex>& vertices, unsigned mode)
{
    if (vertices.empty())
    {
        return;
    }
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)), vertices.data(),
                 GL_STREAM_DRAW);
    glDrawArrays(mode, 0, static_cast<GLsizei>(vertices.size()));
}

void GlDraw::End()
{
    const float scaleX = 2.0f * m_camera.pixelsPerMetre / static_cast<float>(m_camera.width);
    const float scaleY = 2.0f * m_camera.pixelsPerMetre / static_cast<float>(m_camera.height);
    glUseProgram(m_program);
    glUniform4f(m_transform, scaleX, scaleY, -m_camera.center.x * scaleX, -m_camera.center.y * scaleY);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glBindVertexArray(m_vao);
    glBindBuffer(GL_ARRAY_BUFFER, m_vbo);
    Upload(m_fills, GL_TRIANGLES);
    Upload(m_lines, GL_LINES);
    Upload(m_particles, GL_TRIANGLES);
    glBindVertexArray(0);
    glUseProgram(0);
}

void GlDraw::Line(b2Vec2 a, b2Vec2 b, const b2Color& color)
{
    m_lines.push_back({a.x, a.y, color.r, color.g, color.b, color.a, 0.0f, 0.0f});
    m_lines.push_back({b.x, b.y, color.r, color.g, color.b, color.a, 0.0f, 0.0f});
}

void GlDraw::DrawPolygon(const b2Vec2* vertices, int32 vertexCount, const b2Color& color)
{
    for (int32 i = 0; i < vertexCount; ++i)
    {
        Line(vertices[i], vertices[(i + 1) % vertexCount], color);
    }
}

void GlDraw::DrawSolidPolygon(const b2Vec2* vertices, int32 vertexCount, const b2Color& color)
{
    const float shade = m_style.fillShade;
    const Vertex first{vertices[0].x, vertices[0].y, color.r * shade, color.g * shade, color.b * shade, 1.0f,
                       0.0f,          0.0f};
    for (int32 i = 1; i + 1 < vertexCount; ++i)
    {
        m_fills.push_back(first);
        for (int32 k = i; k <= i + 1; ++k)
        {
            m_fills.push_back({vertices[k].x, vertices[k].y, first.r, first.g, first.b, 1.0f, 0.0f, 0.0f});
        }
    }
    DrawPolygon(vertices, vertexCount, color);
}

void GlDraw::DrawCircle(const b2Vec2& center, float radius, const b2Color& color)
{
    const std::array<b2Vec2, kCircleSegments> points = CirclePoints(center, radius);
    DrawPolygon(points.data(), kCircleSegments, color);
}

void GlDraw::DrawSolidCircle(const b2Vec2& center, float radius, const b2Vec2& axis, const b2Color& color)
{
    const std::array<b2Vec2, kCircleSegments> points = CirclePoints(center, radius);
    DrawSolidPolygon(points.data(), kCircleSegments, color);
    Line(center, center + radius * axis, color);
}

void GlDraw::DrawSegment(const b2Vec2& p1, const b2Vec2& p2, const b2Color& color)
{
    Line(p1, p2, color);
}

void GlDraw::DrawTransform(const b2Transform& xf)
{
    constexpr float kAxis = 0.4f; // m
    Line(xf.p, xf.p + kAxis * xf.q.GetXAxis(), b2Color(1.0f, 0.0f, 0.0f));
    Line(xf.p, xf.p + kAxis * xf.q.GetYAxis(), b2Color(0.0f, 1.0f, 0.0f));
}

void GlDraw::DrawPoint(const b2Vec2& p, float size, const b2Color& color)
{
    Disc(m_particles, p, 0.5f * size / m_camera.pixelsPerMetre, Color{color.r, color.g, color.b, color.a});
}

void GlDraw::Disc(std::vector<Vertex>& out, b2Vec2 center, float radius, const Color& color)
{
    const float x0 = center.x - radius, x1 = center.x + radius;
    const float y0 = center.y - radius, y1 = center.y + radius;
    const Vertex corners[4] = {{x0, y0, color.r, color.g, color.b, color.a, -1.0f, -1.0f},
                               {x1, y0, color.r, color.g, color.b, color.a, 1.0f, -1.0f},
                               {x1, y1, color.r, color.g, color.b, color.a, 1.0f, 1.0f},
                               {x0, y1, color.r, color.g, color.b, color.a, -1.0f, 1.0f}};
    for (int index : {0, 1, 2, 0, 2, 3})
    {
        out.push_back(corners[index]);
    }
}

void GlDraw::Streak(b2Vec2 tail, b2Vec2 head, float width, const Color& color)
{
    b2Vec2 side = head - tail;
    side = b2Vec2(-side.y, side.x);
    side.Normalize();
    side *= 0.5f * width;
    // Across the line local v runs from -1 to 1, so its edges are soft; along it the colour is even.
    const Vertex corners[4] = {
        {tail.x - side.x, tail.y - side.y, color.r, color.g, color.b, color.a, 0.0f, -1.0f},
        {head.x - side.x, head.y - side.y, color.r, color.g, color.b, color.a, 0.0f, -1.0f},
        {head.x + side.x, head.y + side.y, color.r, color.g, color.b, color.a, 0.0f, 1.0f},
        {tail.x + side.x, tail.y + side.y, color.r, color.g, color.b, color.a, 0.0f, 1.0f}};
    for (int index : {0, 1, 2, 0, 2, 3})
    {
        m_particles.push_back(corners[index]);
    }
}

void GlDraw::DrawParticles(std::span<const ParticleSprite> sprites)
{
    const float minimum = m_style.minSpriteSize / m_camera.pixelsPerMetre; // m
    for (const ParticleSprite& sprite : sprites)
    {
        const float size = std::max(sprite.size, minimum);
        const b2Vec2 tail = sprite.position - sprite.streak * sprite.velocity;
        if (sprite.streak > 0.0f && b2DistanceSquared(tail, sprite.position) > 0.25f * size * size)
        {
            Streak(tail, sprite.position, size, sprite.color);
        }
        else
        {
            Disc(m_particles, sprite.position, 0.5f * size, sprite.color);
        }
    }
}

} // namespace cfx::testbed
