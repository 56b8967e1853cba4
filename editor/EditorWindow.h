#pragma once
// The editor's GLFW window: an OpenGL 4.5 core context (GLX under X11, Mesa llvmpipe under Xvfb),
// Dear ImGui with its GLFW and OpenGL3 backends, and read-back of the whole window for screenshots.

#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/Result.h"
#include "model/Image.h"
#include "model/Workspace.h"

struct GLFWwindow;

namespace rmfx::editor {

class EditorWindow {
public:
    // Creates the window hidden, with its context current; show() once its size is known.
    static Result<std::unique_ptr<EditorWindow>> create(const std::string& title, GlProfile profile = GlProfile::Core);
    ~EditorWindow();
    EditorWindow(const EditorWindow&) = delete;
    EditorWindow& operator=(const EditorWindow&) = delete;

    // Sets the size in screen coordinates and maps the window.
    void show(glm::ivec2 size);
    void resize(glm::ivec2 size);
    void setVsync(bool on);
    bool shouldClose() const;

    // Polls events and starts an ImGui frame. Without user input (scripted --frames runs) ImGui
    // sees no mouse, so where the pointer happens to be changes nothing.
    void beginFrame(bool userInput = true);
    // Draws ImGui's frame into the back buffer (over whatever was drawn there).
    void renderImGui();
    void swapBuffers();

    glm::ivec2 framebufferSize() const;
    // Framebuffer pixels per ImGui/window unit (1 on X11, 2 on a Retina display).
    glm::vec2 framebufferScale() const;
    // The back buffer as it stands (call before swapBuffers): RGB, row 0 at the top.
    Image readFramebuffer() const;
    const std::string& description() const { return description_; }  // GL version and renderer
    // The files dropped on the window since the last call, in the order they came.
    std::vector<std::string> takeDroppedFiles();

private:
    EditorWindow() = default;
    GLFWwindow* window_ = nullptr;
    bool imguiContext_ = false, glfwBackend_ = false, openglBackend_ = false;
    std::string description_;
    std::vector<std::string> dropped_;
};

}  // namespace rmfx::editor
