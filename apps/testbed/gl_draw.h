// contactfx-testbed: the drawing interface (draw.h) in OpenGL 3.3 core.
//
// Shapes come through b2Draw, particles through ParticleDraw, both in world metres. Calls only collect
// vertices; End() uploads them and draws, in three passes: shape fills, then outlines and joints, then
// particles, so particles are never hidden behind the shapes they fly past. Everything is drawn by one
// small shader: solid geometry as is, particles as soft round points (or soft lines along their
// velocity for sparks) whose opacity is the sprite colour's alpha. Looks follow cfx::render::RenderStyle
// so that the testbed and the Cairo pictures agree.
//
// Lifetime: create and destroy with the OpenGL context current; one thread.
#pragma once

#include "contactfx/draw.h"
#include "contactfx/render/cairo_renderer.h"
#include "contactfx/render/camera.h"

#include <box2d/b2_draw.h>
#include <cstdint>
#include <span>
#include <vector>

namespace cfx::testbed
{

class GlDraw final : public b2Draw, public ParticleDraw
{
public:
    /// Compiles the shader and creates the buffers. Throws std::runtime_error when OpenGL refuses.
    explicit GlDraw(const render::RenderStyle& style);
    ~GlDraw() override;
    GlDraw(const GlDraw&) = delete;
    GlDraw& operator=(const GlDraw&) = delete;

    /// Starts collecting a frame seen through `camera` (its width and height: the viewport's, px).
    void Begin(const render::Camera& camera);
    /// Draws what was collected into the current viewport.
    void End();

    void DrawPolygon(const b2Vec2* vertices, int32 vertexCount, const b2Color& color) override;
    void DrawSolidPolygon(const b2Vec2* vertices, int32 vertexCount, const b2Color& color) override;
    void DrawCircle(const b2Vec2& center, float radius, const b2Color& color) override;
    void DrawSolidCircle(const b2Vec2& center, float radius, const b2Vec2& axis,
                         const b2Color& color) override;
    void DrawSegment(const b2Vec2& p1, const b2Vec2& p2, const b2Color& color) override;
    void DrawTransform(const b2Transform& xf) override;
    /// `size` in pixels, as in Box2D's testbed.
    void DrawPoint(const b2Vec2& p, float size, const b2Color& color) override;

    /// Soft round points of the sprite's size (at least style.minSpriteSize px); sprites with
    /// streak > 0 as soft lines from position - velocity * streak to position.
    void DrawParticles(std::span<const ParticleSprite> sprites) override;

private:
    struct Vertex
    {
        float x, y;       // m, world
        float r, g, b, a; // straight alpha
        float u, v;       // position inside a round sprite, [-1, 1]; (0, 0) for solid geometry
    };
    static_assert(sizeof(Vertex) == 32);

    void Line(b2Vec2 a, b2Vec2 b, const b2Color& color);
    void Disc(std::vector<Vertex>& out, b2Vec2 center, float radius, const Color& color);
    void Streak(b2Vec2 tail, b2Vec2 head, float width, const Color& color);
    void Upload(const std::vector<Vertex>& vertices, unsigned mode);

    render::RenderStyle m_style;
    render::Camera m_camera;
    std::vector<Vertex> m_fills;     // triangles
    std::vector<Vertex> m_lines;     // line pairs
    std::vector<Vertex> m_particles; // triangles
    unsigned m_program = 0;
    unsigned m_vao = 0;
    unsigned m_vbo = 0;
    int m_transform = -1;
};

} // namespace cfx::testbed
