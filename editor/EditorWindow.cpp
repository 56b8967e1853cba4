#include "editor/EditorWindow.h"

#include <cfloat>
#include <utility>

#include <epoxy/gl.h>
// After epoxy: GLFW must not include the system GL header.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

namespace rmfx::editor {
namespace {

std::string glfwErrorText() {
    const char* description = nullptr;
    int code = glfwGetError(&description);
    if (code == GLFW_NO_ERROR) return "unknown GLFW error";
    return description ? description : "GLFW error " + std::to_string(code);
}

}  // namespace

Result<std::unique_ptr<EditorWindow>> EditorWindow::create(const std::string& title, GlProfile profile) {
    const bool core = profile == GlProfile::Core;
    if (!glfwInit()) return Error{"cannot open a window: " + glfwErrorText()};
    std::unique_ptr<EditorWindow> w(new EditorWindow);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    // Compatibility: legacy GLSL and the fixed-function state it reads (Workspace::profile).
    glfwWindowHint(GLFW_OPENGL_PROFILE, core ? GLFW_OPENGL_CORE_PROFILE : GLFW_OPENGL_COMPAT_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, core ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    glfwWindowHint(GLFW_SAMPLES, 0);
    w->window_ = glfwCreateWindow(640, 480, title.c_str(), nullptr, nullptr);
    if (!w->window_) {
        std::string error = std::string("cannot create a window with an OpenGL 4.5 ") + (core ? "core" : "compatibility") +
                            " context: " + glfwErrorText();
        glfwTerminate();
        return Error{error};
    }
    glfwMakeContextCurrent(w->window_);
    // ImGui's GLFW backend keeps its state elsewhere and installs no drop callback: both are ours.
    glfwSetWindowUserPointer(w->window_, w.get());
    glfwSetDropCallback(w->window_, [](GLFWwindow* window, int count, const char** paths) {
        auto* self = static_cast<EditorWindow*>(glfwGetWindowUserPointer(window));
        for (int i = 0; i < count; ++i) self->dropped_.emplace_back(paths[i]);
    });
    w->description_ = std::string(reinterpret_cast<const char*>(glGetString(GL_VERSION))) + ", " +
                      reinterpret_cast<const char*>(glGetString(GL_RENDERER));

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    w->imguiContext_ = true;
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini in the user's folder
    ImGui::StyleColorsDark();
    w->glfwBackend_ = ImGui_ImplGlfw_InitForOpenGL(w->window_, true);
    w->openglBackend_ = ImGui_ImplOpenGL3_Init("#version 450 core");
    if (!w->glfwBackend_ || !w->openglBackend_) return Error{"cannot start Dear ImGui's GLFW or OpenGL 3 backend"};
    return w;
}

EditorWindow::~EditorWindow() {
    if (openglBackend_) ImGui_ImplOpenGL3_Shutdown();
    if (glfwBackend_) ImGui_ImplGlfw_Shutdown();
    if (imguiContext_) ImGui::DestroyContext();
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

void EditorWindow::show(glm::ivec2 size) {
    glfwSetWindowSize(window_, size.x, size.y);
    glfwShowWindow(window_);
    glfwPollEvents();
}

void EditorWindow::resize(glm::ivec2 size) { glfwSetWindowSize(window_, size.x, size.y); }

std::vector<std::string> EditorWindow::takeDroppedFiles() { return std::exchange(dropped_, {}); }

void EditorWindow::setVsync(bool on) { glfwSwapInterval(on ? 1 : 0); }

bool EditorWindow::shouldClose() const { return glfwWindowShouldClose(window_); }

void EditorWindow::beginFrame(bool userInput) {
    glfwPollEvents();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    if (!userInput) {
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
        for (bool& down : io.MouseDown) down = false;
        io.MouseWheel = io.MouseWheelH = 0.0f;
    }
    ImGui::NewFrame();
}

void EditorWindow::renderImGui() { ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData()); }

void EditorWindow::swapBuffers() { glfwSwapBuffers(window_); }

glm::ivec2 EditorWindow::framebufferSize() const {
    glm::ivec2 size(0);
    glfwGetFramebufferSize(window_, &size.x, &size.y);
    return size;
}

glm::vec2 EditorWindow::framebufferScale() const {
    glm::ivec2 window(0);
    glfwGetWindowSize(window_, &window.x, &window.y);
    glm::ivec2 fb = framebufferSize();
    if (window.x < 1 || window.y < 1) return glm::vec2(1.0f);
    return glm::vec2(fb) / glm::vec2(window);
}

Image EditorWindow::readFramebuffer() const {
    glm::ivec2 size = framebufferSize();
    Image image;
    image.width = size.x;
    image.height = size.y;
    image.channels = 3;
    image.bitsPerChannel = 8;
    std::vector<unsigned char> bytes(static_cast<size_t>(size.x) * size.y * 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size.x, size.y, GL_RGB, GL_UNSIGNED_BYTE, bytes.data());
    image.pixels.resize(bytes.size());
    const size_t row = static_cast<size_t>(size.x) * 3;
    for (int y = 0; y < size.y; ++y)  // GL rows run bottom-up
        for (size_t i = 0; i < row; ++i)
            image.pixels[static_cast<size_t>(y) * row + i] = bytes[static_cast<size_t>(size.y - 1 - y) * row + i] / 255.0f;
    return image;
}

}  // namespace rmfx::editor
