#include "editor/Editor.h"

#include <algorithm>
#include <chrono>
#include <iostream>

#include <epoxy/gl.h>
#include <imgui.h>

#include "editor/CameraControl.h"
#include "editor/EditorWindow.h"
#include "editor/ErrorPanel.h"
#include "editor/TargetBrowser.h"
#include "editor/TextureBlit.h"
#include "editor/TimingPanel.h"
#include "editor/VariablesPanel.h"
#include "io/image/ImageIO.h"
#include "run/LiveWorkspace.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::editor {
namespace {

class Editor {
public:
    Editor(EditorWindow& window, LiveWorkspace& session, TextureBlit& blit)
        : window_(window), session_(session), blit_(blit) {}

    // One frame: input, reload, the effect's frame, the panel, presentation (not the swap).
    void frame(const FrameClock& clock, bool userInput) {
        window_.beginFrame(userInput);
        if (session_.poll()) timing_.clear();
        handleMouse();
        GlExecutor& executor = session_.executor();
        executor.setTimingEnabled(true);
        frameErrors_ = executor.renderFrame(clock).takeDiagnostics();
        timing_.record(executor);
        targets_.setOutput(session_.workspace().outputTargetName(), session_.workspace().output.transform);
        targets_.updateThumbnails(executor, session_.workspace(), blit_);
        drawPanel(clock);
        drawViewers();
        ImGui::Render();
        present();
        window_.renderImGui();
    }

    void view(const std::string& target) { targets_.open(target); }

    Result<void> writeOutput(const std::filesystem::path& file) {
        const Workspace& ws = session_.workspace();
        Result<Image> image = session_.executor().readTarget(ws.outputTargetName());
        if (!image) return Error{image.error()};
        return writeImage(file, *image, ws.output.transform);
    }

private:
    // The effect's rectangle in ImGui's (window) coordinates: the top-left corner.
    glm::vec2 effectExtent() const { return glm::vec2(session_.executor().viewport()) / window_.framebufferScale(); }

    void handleMouse() {
        const ImGuiIO& io = ImGui::GetIO();
        const glm::vec2 extent = effectExtent();
        const bool over = !io.WantCaptureMouse && io.MousePos.x >= 0.0f && io.MousePos.y >= 0.0f &&
                          io.MousePos.x < extent.x && io.MousePos.y < extent.y;
        // A drag that starts over the effect keeps going when the cursor leaves it.
        for (int b = 0; b < 3; ++b) {
            if (ImGui::IsMouseClicked(b)) dragging_[b] = over;
            if (!ImGui::IsMouseDown(b)) dragging_[b] = false;
        }
        const glm::vec2 delta(io.MouseDelta.x, io.MouseDelta.y);
        const glm::vec2 scale = window_.framebufferScale();
        // The executor's camera: LiveWorkspace carries it over reloads (docs/hot-reload.md).
        OrbitCamera& camera = session_.executor().camera();
        if (dragging_[ImGuiMouseButton_Left]) orbitByDrag(camera, delta);
        if (dragging_[ImGuiMouseButton_Right] || dragging_[ImGuiMouseButton_Middle])
            panByDrag(camera, delta * scale, session_.executor().viewport().y);
        if (over && io.MouseWheel != 0.0f) zoomByWheel(camera, io.MouseWheel);
        // The MouseCoordinate… semantics: the cursor over the effect in its pixels (top-left origin).
        if (over)
            session_.executor().setMouse(glm::vec2(io.MousePos.x, io.MousePos.y) * scale,
                                         glm::ivec3(ImGui::IsMouseDown(ImGuiMouseButton_Left) ? 1 : 0,
                                                    ImGui::IsMouseDown(ImGuiMouseButton_Middle) ? 1 : 0,
                                                    ImGui::IsMouseDown(ImGuiMouseButton_Right) ? 1 : 0));
    }

    void drawPanel(const FrameClock& clock) {
        const glm::vec2 scale = window_.framebufferScale();
        const glm::vec2 windowSize = glm::vec2(window_.framebufferSize()) / scale;
        const float left = effectExtent().x;
        ImGui::SetNextWindowPos(ImVec2(left, 0.0f));
        ImGui::SetNextWindowSize(ImVec2(std::max(windowSize.x - left, 200.0f), windowSize.y));
        const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                       ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings;
        const Workspace& ws = session_.workspace();
        const std::string title = "rmfx edit: " + ws.path.filename().string() + "###panel";
        ImGui::Begin(title.c_str(), nullptr, flags);
        GlExecutor& executor = session_.executor();
        ImGui::TextWrapped("%s", ws.description.empty() ? ws.name.c_str() : ws.description.c_str());
        ImGui::TextDisabled("%dx%d, frame %d, t %.2f s, %.0f fps", executor.viewport().x, executor.viewport().y,
                            executor.frameIndex(), clock.time, ImGui::GetIO().Framerate);
        ImGui::TextDisabled("%s", window_.description().c_str());
        drawReloadStatus();
        drawErrorPanel(session_.errors(), frameErrors_, session_.warnings());
        if (ImGui::CollapsingHeader("Variables", ImGuiTreeNodeFlags_DefaultOpen)) variables_.draw(session_);
        if (ImGui::CollapsingHeader("Camera")) drawCamera();
        if (ImGui::CollapsingHeader("Render targets", ImGuiTreeNodeFlags_DefaultOpen)) targets_.draw(executor);
        if (ImGui::CollapsingHeader("Timing", ImGuiTreeNodeFlags_DefaultOpen)) {
            drawEffectSwitches();
            timing_.draw();
        }
        ImGui::End();
    }

    void drawReloadStatus() {
        const size_t watched = session_.watchedFiles().size();
        const ReloadReport& r = session_.lastReload();
        if (r.changedFiles.empty()) {
            ImGui::TextDisabled("hot reload: watching %zu files", watched);
            return;
        }
        std::string what = r.failed ? "failed" : r.workspaceRebuilt ? "rebuilt the workspace" : "";
        auto list = [&](const char* label, const std::vector<std::string>& names) {
            if (names.empty() || r.workspaceRebuilt) return;
            what += (what.empty() ? "" : "; ") + std::string(label);
            for (size_t i = 0; i < names.size(); ++i) what += (i ? ", " : " ") + names[i];
        };
        list("recompiled", r.recompiledPasses);
        list("reloaded", r.reloadedTextures);
        list("reloaded", r.reloadedModels);
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
        ImGui::TextWrapped("hot reload: watching %zu files; last reload %.0f ms after the write: %s", watched,
                           session_.lastReloadMilliseconds(), what.c_str());
        ImGui::PopStyleColor();
    }

    // Viewers open below the effect when there is room, else over it; never over the panel.
    void drawViewers() {
        const glm::vec2 effect = effectExtent();
        const glm::vec2 window = glm::vec2(window_.framebufferSize()) / window_.framebufferScale();
        const float width = std::max(effect.x - 16.0f, 320.0f);
        const float below = window.y - effect.y - 16.0f;
        if (below >= 260.0f)
            targets_.drawViewers(session_.executor(), {8.0f, effect.y + 8.0f}, {width, below});
        else
            targets_.drawViewers(session_.executor(), {8.0f, 8.0f}, {width, std::min(480.0f, window.y - 16.0f)});
    }

    // Which passes ran: effects switched off by their switch variables run none of theirs.
    void drawEffectSwitches() {
        const GlExecutor& executor = session_.executor();
        std::string off;
        for (const std::string& e : executor.switchedOffEffects()) off += (off.empty() ? "" : ", ") + e;
        ImGui::TextDisabled("%zu passes ran%s%s", executor.passesRun().size(), off.empty() ? "" : "; effects switched off: ",
                            off.c_str());
    }

    void drawCamera() {
        OrbitCamera& camera = session_.executor().camera();
        const OrbitCameraSettings& s = camera.settings();
        ImGui::Text("target %.2f %.2f %.2f, distance %.2f", s.target.x, s.target.y, s.target.z, s.distance);
        ImGui::Text("yaw %.1f, pitch %.1f, fov %.0f", s.yawDegrees, s.pitchDegrees, s.fovYDegrees);
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
        ImGui::TextWrapped("over the effect: left drag orbits, right or middle drag pans, the wheel zooms");
        ImGui::PopStyleColor();
        if (ImGui::Button("Reset camera")) camera.reset(session_.workspace().camera);
    }

    // The effect's output, texel for pixel, at the framebuffer's top-left corner.
    void present() {
        const glm::ivec2 fb = window_.framebufferSize();
        GlExecutor& executor = session_.executor();
        const glm::ivec2 size = executor.viewport();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, fb.x, fb.y);
        glDisable(GL_SCISSOR_TEST);
        glClearColor(0.1f, 0.1f, 0.11f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        const Workspace& ws = session_.workspace();
        if (unsigned texture = executor.targetTexture(ws.outputTargetName())) {
            const glm::ivec2 origin(0, fb.y - size.y);
            glViewport(origin.x, origin.y, size.x, size.y);
            blit_.drawExact(texture, origin, ws.output.transform);
            glViewport(0, 0, fb.x, fb.y);
        }
    }

    EditorWindow& window_;
    LiveWorkspace& session_;
    TextureBlit& blit_;
    bool dragging_[3] = {false, false, false};
    Diagnostics frameErrors_;
    VariablesPanel variables_;
    TargetBrowser targets_;
    TimingPanel timing_;
};

}  // namespace

int runEditor(const EditorOptions& options) {
    // Checked before any window opens: a broken workspace is reported like rmfx render reports it,
    // and its size sets the window's.
    Result<Workspace> loaded = loadWorkspace(options.workspace, {}, {options.effect, options.media, {}});
    Diagnostics diagnostics = loaded.diagnostics();
    Workspace* checked = loaded ? &*loaded : nullptr;
    if (checked) {
        Result<void> set = applyOverrides(*checked, options.overrides);
        diagnostics.insert(diagnostics.end(), set.diagnostics().begin(), set.diagnostics().end());
        if (!set) checked = nullptr;
    }
    std::cerr << formatAll(diagnostics);
    if (!checked) return 1;
    for (const std::string& target : options.viewTargets)
        if (!checked->canReadTarget(target)) {
            std::cerr << "rmfx edit: --view " << target << ": the workspace has no such target (" << checked->describeTargets()
                      << ")\n";
            return 1;
        }
    const glm::ivec2 effect = options.size.x > 0 ? options.size : glm::ivec2(checked->width, checked->height);

    auto window = EditorWindow::create("rmfx edit: " + options.workspace.filename().string(), checked->profile);
    if (!window) {
        std::cerr << "rmfx edit: " << window.error() << "\n";
        return 2;
    }
    // The size asked for, else 0: the workspace's, which a reload may change.
    auto opened = LiveWorkspace::open(options.workspace, options.size, options.overrides, {options.effect, options.media, {}});
    if (!opened) {
        std::cerr << formatAll(opened.diagnostics());
        return 2;
    }
    std::unique_ptr<LiveWorkspace> session = std::move(*opened);
    auto blit = TextureBlit::create();
    if (!blit) {
        std::cerr << "rmfx edit: " << blit.error() << "\n";
        return 2;
    }
    (*window)->show({effect.x + panelWidth, std::max(effect.y, minimumWindowHeight)});
    (*window)->setVsync(!options.frames);

    Editor editor(**window, *session, **blit);
    for (const std::string& target : options.viewTargets) editor.view(target);
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    Clock::time_point previous = start;
    for (int i = 0; !(*window)->shouldClose(); ++i) {
        FrameClock clock;
        if (options.frames) {
            clock = {static_cast<float>(i) * options.deltaTime, options.deltaTime};
        } else {
            Clock::time_point now = Clock::now();
            clock = {std::chrono::duration<float>(now - start).count(), std::chrono::duration<float>(now - previous).count()};
            previous = now;
        }
        editor.frame(clock, !options.frames);
        if (options.frames && i + 1 >= *options.frames) {
            int status = 0;
            if (options.screenshot) {
                if (auto written = writeImage(*options.screenshot, (*window)->readFramebuffer()); !written) {
                    std::cerr << "rmfx edit: " << written.error() << "\n";
                    status = 2;
                }
            }
            if (options.outputScreenshot) {
                if (auto written = editor.writeOutput(*options.outputScreenshot); !written) {
                    std::cerr << "rmfx edit: " << written.error() << "\n";
                    status = 2;
                }
            }
            return status;
        }
        (*window)->swapBuffers();
    }
    return 0;
}

}  // namespace rmfx::editor
