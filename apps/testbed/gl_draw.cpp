#include "gl_draw.h"

#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
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
uniform vec4 transform; // xy: scale, zw: offset, pixels -> clip space
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

} // namespace

GlRenderer::GlRenderer()
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

GlRenderer::~GlRenderer()
{
    glDeleteBuffers(1, &m_vbo);
    glDeleteVertexArrays(1, &m_vao);
    glDeleteProgram(m_program);
}

void GlRenderer::Blend(bool additive)
{
    if (m_runs.empty() || m_runs.back().additive != additive)
    {
        m_runs.push_back(Run{m_vertices.size(), 0, additive});
    }
}

void GlRenderer::Triangle(const Vertex& a, const Vertex& b, const Vertex& c)
{
    m_vertices.push_back(a);
    m_vertices.push_back(b);
    m_vertices.push_back(c);
    m_runs.back().count += 3;
}

void GlRenderer::Quad(const Vertex (&corners)[4])
{
    Triangle(corners[0], corners[1], corners[2]);
    Triangle(corners[0], corners[2], corners[3]);
}

void GlRenderer::Line(b2Vec2 from, b2Vec2 to, float width, const Color& color)
{
    b2Vec2 side(from.y - to.y, to.x - from.x);
    if (side.Normalize() == 0.0f)
    {
        return;
    }
    side *= 0.5f * width;
    const Color& c = color;
    Quad({{from.x - side.x, from.y - side.y, c.r, c.g, c.b, c.a, 0.0f, 0.0f},
          {to.x - side.x, to.y - side.y, c.r, c.g, c.b, c.a, 0.0f, 0.0f},
          {to.x + side.x, to.y + side.y, c.r, c.g, c.b, c.a, 0.0f, 0.0f},
          {from.x + side.x, from.y + side.y, c.r, c.g, c.b, c.a, 0.0f, 0.0f}});
}

void GlRenderer::Soft(b2Vec2 center, float radius, const Color& c)
{
    const float x0 = center.x - radius, x1 = center.x + radius;
    const float y0 = center.y - radius, y1 = center.y + radius;
    Quad({{x0, y0, c.r, c.g, c.b, c.a, -1.0f, -1.0f},
          {x1, y0, c.r, c.g, c.b, c.a, 1.0f, -1.0f},
          {x1, y1, c.r, c.g, c.b, c.a, 1.0f, 1.0f},
          {x0, y1, c.r, c.g, c.b, c.a, -1.0f, 1.0f}});
}

void GlRenderer::Shape(const DrawList& list, const ShapeCommand& shape)
{
    const Camera& camera = list.camera;
    const b2Vec2* points = list.vertices.data() + shape.first;
    m_outline.clear();
    switch (shape.kind)
    {
    case ShapeKind::point:
    {
        const b2Vec2 at = camera.ToPixels(points[0]);
        const float half = 0.5f * shape.pointSize;
        const Color& c = shape.fill;
        Quad({{at.x - half, at.y - half, c.r, c.g, c.b, c.a, 0.0f, 0.0f},
              {at.x + half, at.y - half, c.r, c.g, c.b, c.a, 0.0f, 0.0f},
              {at.x + half, at.y + half, c.r, c.g, c.b, c.a, 0.0f, 0.0f},
              {at.x - half, at.y + half, c.r, c.g, c.b, c.a, 0.0f, 0.0f}});
        return;
    }
    case ShapeKind::circle:
        for (int i = 0; i < kCircleSegments; ++i)
        {
            const float angle = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / kCircleSegments;
            m_outline.push_back(
                camera.ToPixels(points[0] + shape.radius * b2Vec2(std::cos(angle), std::sin(angle))));
        }
        break;
    default: // polygon, segment
        for (std::uint32_t i = 0; i < shape.count; ++i)
        {
            m_outline.push_back(camera.ToPixels(points[i]));
        }
        break;
    }
    if (shape.filled && m_outline.size() >= 3)
    {
        const Color& c = shape.fill;
        const Vertex first{m_outline[0].x, m_outline[0].y, c.r, c.g, c.b, c.a, 0.0f, 0.0f};
        for (std::size_t i = 1; i + 1 < m_outline.size(); ++i)
        {
            Triangle(first, {m_outline[i].x, m_outline[i].y, c.r, c.g, c.b, c.a, 0.0f, 0.0f},
                     {m_outline[i + 1].x, m_outline[i + 1].y, c.r, c.g, c.b, c.a, 0.0f, 0.0f});
        }
    }
    if (shape.strokeWidth > 0.0f)
    {
        const bool closed = shape.kind != ShapeKind::segment;
        const std::size_t edges = closed ? m_outline.size() : m_outline.size() - 1;
        for (std::size_t i = 0; i < edges; ++i)
        {
            Line(m_outline[i], m_outline[(i + 1) % m_outline.size()], shape.strokeWidth, shape.stroke);
        }
    }
}

void GlRenderer::Disc(b2Vec2 center, float radius, const Color& c)
{
    constexpr int kSegments = 12;
    const Vertex middle{center.x, center.y, c.r, c.g, c.b, c.a, 0.0f, 0.0f};
    b2Vec2 last = center + b2Vec2(radius, 0.0f);
    for (int i = 1; i <= kSegments; ++i)
    {
        const float angle = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / kSegments;
        const b2Vec2 next = center + radius * b2Vec2(std::cos(angle), std::sin(angle));
        Triangle(middle, {last.x, last.y, c.r, c.g, c.b, c.a, 0.0f, 0.0f},
                 {next.x, next.y, c.r, c.g, c.b, c.a, 0.0f, 0.0f});
        last = next;
    }
}

void GlRenderer::Sprite(const SpriteCommand& sprite)
{
    const Color& c = sprite.color;
    switch (sprite.kind)
    {
    case SpriteKind::soft:
        Blend(false);
        Soft(sprite.head, 0.5f * sprite.size, c);
        return;
    case SpriteKind::glow:
        Blend(true);
        Soft(sprite.head, 0.5f * sprite.size, c);
        return;
    case SpriteKind::grain:
        Blend(false);
        Disc(sprite.head, 0.5f * sprite.size, sprite.rim);
        Disc(sprite.head, std::max(0.5f * sprite.size - sprite.rimWidth, 0.0f), c);
        return;
    case SpriteKind::streak:
        break;
    }
    // A streak: across it local v runs from -1 to 1, so its edges are soft; along it the opacity grows
    // from nothing at the tail to the colour's at the head, where a soft round head sits.
    Blend(true);
    b2Vec2 side(sprite.tail.y - sprite.head.y, sprite.head.x - sprite.tail.x);
    if (side.Normalize() > 0.0f)
    {
        side *= 0.5f * sprite.size;
        const b2Vec2& t = sprite.tail;
        const b2Vec2& h = sprite.head;
        Quad({{t.x - side.x, t.y - side.y, c.r, c.g, c.b, 0.0f, 0.0f, -1.0f},
              {h.x - side.x, h.y - side.y, c.r, c.g, c.b, c.a, 0.0f, -1.0f},
              {h.x + side.x, h.y + side.y, c.r, c.g, c.b, c.a, 0.0f, 1.0f},
              {t.x + side.x, t.y + side.y, c.r, c.g, c.b, 0.0f, 0.0f, 1.0f}});
    }
    Soft(sprite.head, 0.5f * sprite.size, c);
}

void GlRenderer::Render(const DrawList& list)
{
    m_vertices.clear();
    m_runs.clear();
    Blend(false);
    // The background gradient, top to bottom.
    const float width = static_cast<float>(list.camera.width);
    const float height = static_cast<float>(list.camera.height);
    const Color& top = list.background;
    const Color& bottom = list.backgroundBottom;
    Quad({{0.0f, 0.0f, top.r, top.g, top.b, 1.0f, 0.0f, 0.0f},
          {width, 0.0f, top.r, top.g, top.b, 1.0f, 0.0f, 0.0f},
          {width, height, bottom.r, bottom.g, bottom.b, 1.0f, 0.0f, 0.0f},
          {0.0f, height, bottom.r, bottom.g, bottom.b, 1.0f, 0.0f, 0.0f}});
    const std::size_t under = std::min(list.shapesUnderSprites, list.shapes.size());
    for (std::size_t i = 0; i < under; ++i)
    {
        Shape(list, list.shapes[i]);
    }
    for (const SpriteCommand& sprite : list.sprites)
    {
        Sprite(sprite);
    }
    Blend(false);
    for (std::size_t i = under; i < list.shapes.size(); ++i)
    {
        Shape(list, list.shapes[i]);
    }
    const ScaleBar& bar = list.overlay.scaleBar;
    if (bar.shown)
    {
        // The bar and its end ticks; its label is text, left to the testbed's panels.
        Blend(false);
        const Color light{0.92f, 0.92f, 0.92f, 0.9f};
        const float tick = 6.0f;
        const b2Vec2 right = bar.from + b2Vec2(bar.pixels, 0.0f);
        Line(bar.from, right, 2.0f, light);
        Line(bar.from, bar.from - b2Vec2(0.0f, tick), 2.0f, light);
        Line(right, right - b2Vec2(0.0f, tick), 2.0f, light);
    }

    glUseProgram(m_program);
    glUniform4f(m_transform, 2.0f / width, -2.0f / height, -1.0f, 1.0f);
    glEnable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glBindVertexArray(m_vao);
    glBindBuffer(GL_ARRAY_BUFFER, m_vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(m_vertices.size() * sizeof(Vertex)),
                 m_vertices.data(), GL_STREAM_DRAW);
    for (const Run& run : m_runs)
    {
        glBlendFunc(GL_SRC_ALPHA, run.additive ? GL_ONE : GL_ONE_MINUS_SRC_ALPHA);
        glDrawArrays(GL_TRIANGLES, static_cast<GLint>(run.first), static_cast<GLsizei>(run.count));
    }
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBindVertexArray(0);
    glUseProgram(0);
}

} // namespace cfx::testbed
