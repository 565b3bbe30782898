#include "window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <stdexcept>
#include <string>

namespace cfx::testbed
{

namespace
{

std::string g_lastError; // GLFW reports errors through a callback; the constructor turns them into text

void RememberError(int /*code*/, const char* description)
{
    g_lastError = description != nullptr ? description : "unknown GLFW error";
}

[[noreturn]] void Fail(const char* what)
{
    throw std::runtime_error(std::string(what) + ": " +
                             (g_lastError.empty() ? "no reason given" : g_lastError));
}

} // namespace

Window::Window(int width, int height, const char* title, bool vsync)
{
    glfwSetErrorCallback(RememberError);
    if (glfwInit() != GLFW_TRUE)
    {
        Fail("cannot open a window (no display? run under a desktop session or xvfb-run)");
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    m_window = glfwCreateWindow(width, height, title, nullptr, nullptr);
    if (m_window == nullptr)
    {
        glfwTerminate();
        Fail("cannot open a window with OpenGL 3.3");
    }
    glfwMakeContextCurrent(m_window);
    glfwSwapInterval(vsync ? 1 : 0);
}

void Window::StartUi()
{
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // the layout is fixed; leave no imgui.ini behind
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(m_window, true); // chains to the callbacks installed before
    ImGui_ImplOpenGL3_Init("#version 330 core");
    m_ui = true;
}

Window::~Window()
{
    if (m_ui)
    {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    glfwDestroyWindow(m_window);
    glfwTerminate();
}

bool Window::ShouldClose() const
{
    return glfwWindowShouldClose(m_window) == GLFW_TRUE;
}

void Window::BeginFrame()
{
    glfwPollEvents();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void Window::RenderUi()
{
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void Window::Present()
{
    glfwSwapBuffers(m_window);
}

void Window::Size(int& width, int& height) const
{
    glfwGetFramebufferSize(m_window, &width, &height);
}

} // namespace cfx::testbed
