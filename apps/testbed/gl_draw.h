// contactfx-testbed: the OpenGL 3.3 core backend of the draw list (contactfx/draw/draw_list.h), a peer of
// the Cairo renderer: the list decides the look, this only rasterises it.
//
// Render() turns the whole list into triangles in pixels and draws them in the list's order with one
// small shader: the background gradient as a quad, shapes as fans (fills) and quads (outlines, their width
// in pixels), soft points as quads whose opacity fades towards their rim (glows added onto what is below),
// grains as fans inside fans of their rim, streaks as quads fading towards their tail with a soft round
// head, added onto what is below as the Cairo renderer adds them, and the scale bar. Text (the overlay,
// labels, the scale bar's length) is left to the testbed's panels.
//
// Lifetime: create and destroy with the OpenGL context current; one thread.
#pragma once

#include "contactfx/draw/draw_list.h"

#include <cstddef>
#include <vector>

namespace cfx::testbed
{

class GlRenderer final
{
public:
    /// Compiles the shader and creates the buffers. Throws std::runtime_error when OpenGL refuses.
    GlRenderer();
    ~GlRenderer();
    GlRenderer(const GlRenderer&) = delete;
    GlRenderer& operator=(const GlRenderer&) = delete;

    /// Draws the shapes and sprites of `list` into the current viewport, whose size in pixels must be the
    /// list's camera's, starting with the list's background gradient.
    void Render(const DrawList& list);

private:
    struct Vertex
    {
        float x, y;       // px, y down
        float r, g, b, a; // straight alpha
        float u, v;       // position inside a soft sprite, [-1, 1]; (0, 0) for solid geometry
    };
    static_assert(sizeof(Vertex) == 32);

    /// Consecutive vertices drawn with one blend mode.
    struct Run
    {
        std::size_t first = 0;
        std::size_t count = 0;
        bool additive = false;
    };

    void Shape(const DrawList& list, const ShapeCommand& shape);
    void Sprite(const SpriteCommand& sprite);
    void Triangle(const Vertex& a, const Vertex& b, const Vertex& c);
    void Quad(const Vertex (&corners)[4]);
    void Line(b2Vec2 from, b2Vec2 to, float width, const Color& color);
    void Soft(b2Vec2 center, float radius, const Color& color);
    void Disc(b2Vec2 center, float radius, const Color& color);
    void Blend(bool additive);

    std::vector<Vertex> m_vertices; // triangles
    std::vector<Run> m_runs;
    std::vector<b2Vec2> m_outline; // px, one shape's
    unsigned m_program = 0;
    unsigned m_vao = 0;
    unsigned m_vbo = 0;
    int m_transform = -1;
};

} // namespace cfx::testbed
