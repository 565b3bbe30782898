// contactfx-testbed: the window, its OpenGL 3.3 core context and Dear ImGui, closed together.
//
// Lifetime: one Window per process; everything that uses OpenGL must be destroyed before it.
#pragma once

struct GLFWwindow;

namespace cfx::testbed
{

class Window
{
public:
    /// Opens a `width` x `height` window. Throws std::runtime_error with GLFW's reason when no display
    /// can be opened or OpenGL 3.3 is not available. `vsync`: wait for the display between frames.
    Window(int width, int height, const char* title, bool vsync);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    /// Starts Dear ImGui. Its GLFW callbacks chain to the ones the application installed before.
    void StartUi();

    GLFWwindow* Handle() const { return m_window; }
    bool ShouldClose() const;
    /// Reads events and starts an ImGui frame.
    void BeginFrame();
    /// Draws ImGui's frame over what is in the back buffer (not yet shown).
    void RenderUi();
    /// Shows the back buffer.
    void Present();
    /// Framebuffer size, px.
    void Size(int& width, int& height) const;

private:
    GLFWwindow* m_window = nullptr;
    bool m_ui = false;
};

} // namespace cfx::testbed
