#include "editor/Editor.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <optional>

#include <epoxy/gl.h>
#include <imgui.h>

#include "compile/RunPreparation.h"
#include "editor/CameraControl.h"
#include "editor/EditorWindow.h"
#include "editor/ErrorPanel.h"
#include "editor/TargetBrowser.h"
#include "editor/TextureBlit.h"
#include "editor/TimingPanel.h"
#include "editor/VariablesPanel.h"
#include "io/image/ImageIO.h"
#include "run/LiveWorkspace.h"
#include "validation/ImageInputs.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::editor {
namespace {

const ImVec4 kErrorText(1.0f, 0.45f, 0.4f, 1.0f);  // a reload, a drop or a switch that failed

glm::ivec2 windowSizeFor(glm::ivec2 effect) { return {effect.x + panelWidth, std::max(effect.y, minimumWindowHeight)}; }

// The input a dropped image fills: the only one, else the first that stands in for a target (the
// scene), else the first.
const ImageInput* inputForDroppedImage(const Workspace& ws) {
    if (ws.inputs.empty()) return nullptr;
    for (const ImageInput& input : ws.inputs)
        if (!input.replaces.empty()) return &input;
    return &ws.inputs.front();
}

class Editor {
public:
    Editor(EditorWindow& window, LiveWorkspace& session, TextureBlit& blit, std::optional<float> split)
        : window_(window), session_(session), blit_(blit), splitOn_(split.has_value()), split_(split.value_or(0.5f)),
          shownViewport_(session.executor().viewport()) {}

    // One frame: input, reload, the effect's frame, the panel, presentation (not the swap).
    void frame(const FrameClock& clock, bool userInput) {
        window_.beginFrame(userInput);
        for (const std::string& file : window_.takeDroppedFiles()) useDroppedImage(file);
        if (session_.poll()) timing_.clear();
        // An input image of another size (a new file, a save) sizes the effect anew.
        if (session_.executor().viewport() != shownViewport_) {
            shownViewport_ = session_.executor().viewport();
            window_.resize(windowSizeFor(shownViewport_));
        }
        handleMouse();
        GlExecutor& executor = session_.executor();
        executor.setTimingEnabled(true);
        frameErrors_ = executor.renderFrame(clock).takeDiagnostics();
        timing_.record(executor);
        targets_.setOutput(session_.workspace().outputTargetName(), session_.workspace().output.transform);
        blit_.setRowsTopFirst(rowsTopFirst(session_.workspace().textureSpace));
        targets_.updateThumbnails(executor, session_.workspace(), blit_);
        drawPanel(clock);
        drawViewers();
        drawSplitLine();
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
        // A left drag that starts on the before/after line moves the line, not the camera.
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Left))
            draggingSplit_ = over && beforeTexture() && std::abs(io.MousePos.x - split_ * extent.x) <= 6.0f;
        if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) draggingSplit_ = false;
        if (draggingSplit_) {
            split_ = std::clamp(io.MousePos.x / std::max(extent.x, 1.0f), 0.0f, 1.0f);
            dragging_[ImGuiMouseButton_Left] = false;
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
        if (!ws.inputs.empty() && ImGui::CollapsingHeader("Input", ImGuiTreeNodeFlags_DefaultOpen)) drawInputs();
        if (ImGui::CollapsingHeader("Variables", ImGuiTreeNodeFlags_DefaultOpen)) variables_.draw(session_);
        if (ImGui::CollapsingHeader("Camera")) drawCamera();
        if (ImGui::CollapsingHeader("Render targets", ImGuiTreeNodeFlags_DefaultOpen)) {
            drawHealthCheck();
            targets_.draw(session_.executor());  // the box may have just built a new executor
        }
        if (ImGui::CollapsingHeader("Timing", ImGuiTreeNodeFlags_DefaultOpen)) {
            drawEffectSwitches();
            timing_.draw();
        }
        ImGui::End();
    }

    // The numeric health check (rmfx render --check): on, each thumbnail gets a badge of what its
    // target holds. Switching it builds the workspace anew (the check is part of the executor).
    void drawHealthCheck() {
        bool on = session_.healthCheck();
        if (ImGui::Checkbox("Check targets for NaN, Inf, negatives", &on)) {
            Result<void> switched = session_.setHealthCheck(on);
            healthError_ = switched ? "" : formatAll(switched.diagnostics());
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("after each pass, inspect on the GPU the target it wrote (as rmfx render --check);\n"
                              "a badge under each thumbnail, the first bad pixel on hover");
        if (!healthError_.empty()) ImGui::TextColored(kErrorText, "%s", healthError_.c_str());
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

    // Each <input>, the file it was given (or what stands in without one), the before/after view,
    // and what the last dropped file did.
    void drawInputs() {
        const Workspace& ws = session_.workspace();
        for (const ImageInput& input : ws.inputs) {
            const InputArgument* given = nullptr;
            for (const InputArgument& a : session_.inputs())
                if (session_.inputName(a) == input.name) given = &a;
            const Texture* texture = ws.findTexture(input.name);
            if (given && texture && texture->supplied)
                ImGui::TextWrapped("%s: %s (%dx%d)", input.name.c_str(), given->file.string().c_str(),
                                   texture->supplied->width, texture->supplied->height);
            else if (!input.replaces.empty())
                ImGui::TextWrapped("%s: no image; the workspace draws target '%s' itself", input.name.c_str(),
                                   input.replaces.c_str());
            else
                ImGui::TextWrapped("%s: no image given; the workspace's own file", input.name.c_str());
        }
        if (beforeTexture()) {
            ImGui::Checkbox("Before / after", &splitOn_);
            if (splitOn_) {
                ImGui::SameLine();
                ImGui::SetNextItemWidth(-1.0f);
                ImGui::SliderFloat("##split", &split_, 0.0f, 1.0f, "input left of %.2f");
            }
        }
        if (const ImageInput* drop = inputForDroppedImage(ws)) {
            ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
            ImGui::TextWrapped("drop an image on the window to make it input '%s'", drop->name.c_str());
            ImGui::PopStyleColor();
        }
        if (!dropMessage_.empty()) {
            if (dropFailed_) ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
            ImGui::TextWrapped("%s", dropMessage_.c_str());
            if (dropFailed_) ImGui::PopStyleColor();
        }
    }

    void useDroppedImage(const std::string& file) {
        const ImageInput* input = inputForDroppedImage(session_.workspace());
        dropFailed_ = !input;
        if (!input) {
            dropMessage_ = file + ": this workspace declares no <input> for an image to fill";
            return;
        }
        InputArgument argument;
        argument.name = input->name;
        argument.file = file;
        argument.text = file;
        Result<void> set = session_.setInput(argument);
        dropFailed_ = !set;
        dropMessage_ = set ? "input '" + argument.name + "' is now " + file : "the dropped file is not used: " + set.error();
        if (set) {
            timing_.clear();
            for (const Diagnostic& d : set.diagnostics()) dropMessage_ += "\n" + d.message;
        }
    }

    // The input image the before/after view shows: a given image that sets the viewport, so that
    // it is the effect's size; 0 when there is none.
    unsigned beforeTexture() const {
        const Workspace& ws = session_.workspace();
        for (const ImageInput& input : ws.inputs) {
            const Texture* texture = ws.findTexture(input.name);
            if (!input.sizesViewport || !texture || !texture->supplied) continue;
            if (glm::ivec2(texture->supplied->width, texture->supplied->height) != session_.executor().viewport()) continue;
            if (unsigned object = session_.executor().textureObject(input.name)) return object;
        }
        return 0;
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

    // Which passes ran: effects switched off by their switch variables run none of theirs, and
    // those whose source held nothing were skipped on the GPU (hover for why).
    void drawEffectSwitches() {
        GlExecutor& executor = session_.executor();
        std::string off;
        for (const std::string& e : executor.switchedOffEffects()) off += (off.empty() ? "" : ", ") + e;
        ImGui::TextDisabled("%zu passes ran%s%s", executor.passesRun().size(), off.empty() ? "" : "; effects switched off: ",
                            off.c_str());
        const std::map<std::string, std::string>& skipped = executor.contentSkippedEffects(false);
        if (skipped.empty()) return;
        std::string names, why;
        for (const auto& [effect, reason] : skipped) {
            names += (names.empty() ? "" : ", ") + effect;
            why += (why.empty() ? "" : "\n") + effect + ": " + reason;
        }
        ImGui::TextDisabled("skipped by content: %s", names.c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", why.c_str());
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
        const glm::ivec2 origin(0, fb.y - size.y);
        if (unsigned texture = executor.targetTexture(ws.outputTargetName())) {
            glViewport(origin.x, origin.y, size.x, size.y);
            blit_.drawExact(texture, origin, ws.output.transform);
            glViewport(0, 0, fb.x, fb.y);
        }
        const unsigned before = splitOn_ ? beforeTexture() : 0;
        if (!before) return;
        // The input left of the line, as an image viewer shows it (clamped, sRGB-encoded) whatever
        // the output's transform: the output of a workspace that encodes itself is display-ready.
        const int splitPixels = static_cast<int>(std::lround(split_ * static_cast<float>(size.x)));
        if (splitPixels < 1) return;
        // Texel for pixel from `origin`: a narrower viewport draws the image's left part.
        glViewport(origin.x, origin.y, splitPixels, size.y);
        blit_.drawExact(before, origin, DisplayTransform::Srgb);
        glViewport(0, 0, fb.x, fb.y);
    }

    // The before/after line and its labels, over the effect (ImGui draws them after present()).
    void drawSplitLine() {
        if (!splitOn_ || !beforeTexture()) return;
        const glm::vec2 extent = effectExtent();
        const float x = std::round(split_ * extent.x);
        ImDrawList* draw = ImGui::GetForegroundDrawList();
        draw->AddLine(ImVec2(x, 0.0f), ImVec2(x, extent.y), IM_COL32(255, 255, 255, 200), 1.0f);
        draw->AddText(ImVec2(std::max(x - 44.0f, 4.0f), 4.0f), IM_COL32(255, 255, 255, 220), "input");
        draw->AddText(ImVec2(x + 6.0f, 4.0f), IM_COL32(255, 255, 255, 220), "output");
    }

    EditorWindow& window_;
    LiveWorkspace& session_;
    TextureBlit& blit_;
    bool dragging_[3] = {false, false, false};
    bool splitOn_ = false, draggingSplit_ = false;
    float split_ = 0.5f;  // the before/after line, a fraction of the effect's width
    glm::ivec2 shownViewport_{0};
    std::string dropMessage_;
    bool dropFailed_ = false;
    Diagnostics frameErrors_;
    VariablesPanel variables_;
    TargetBrowser targets_;
    std::string healthError_;  // why the health check could not be switched
    TimingPanel timing_;
};

}  // namespace

int runEditor(const EditorOptions& options) {
    // Checked before any window opens: a broken workspace or input image is reported like rmfx
    // render reports it.
    const WorkspaceLoadOptions load{options.effect, options.media, options.textures, options.rfxMatrices};
    RunRequest request;
    request.workspace = options.workspace;
    request.load = load;
    request.overrides = options.overrides;
    request.inputs = options.inputs;
    request.size = options.size;
    Result<LoadedRun> loaded = loadRun(request);
    Diagnostics diagnostics = loaded.diagnostics();
    if (loaded) {
        // With its warnings: how each file was decoded.
        Result<void> read = readRunInputs(*loaded, request);
        diagnostics.insert(diagnostics.end(), read.diagnostics().begin(), read.diagnostics().end());
        if (!read) loaded = Result<LoadedRun>::failure(Diagnostics(diagnostics));
    }
    std::cerr << formatAll(diagnostics);
    if (!loaded) return 1;
    const Workspace* checked = &loaded->ws;
    for (const std::string& target : options.viewTargets)
        if (!checked->canReadTarget(target)) {
            std::cerr << "rmfx edit: --view " << target << ": the workspace has no such target (" << checked->describeTargets()
                      << ")\n";
            return 1;
        }
    auto window = EditorWindow::create("rmfx edit: " + options.workspace.filename().string(), checked->profile);
    if (!window) {
        std::cerr << "rmfx edit: " << window.error() << "\n";
        return 2;
    }
    // The size asked for, else 0: the input image's or the workspace's, which a reload may change.
    // The session's first build takes the workspace as checked here: the file is read once.
    auto opened = LiveWorkspace::open(options.workspace, options.size, options.overrides, load, options.inputs, std::move(*loaded));
    if (!opened) {
        std::cerr << formatAll(opened.diagnostics());
        return 2;
    }
    std::unique_ptr<LiveWorkspace> session = std::move(*opened);
    if (options.checkHealth)
        if (Result<void> checked = session->setHealthCheck(true); !checked) {
            std::cerr << formatAll(checked.diagnostics());
            return 2;
        }
    auto blit = TextureBlit::create();
    if (!blit) {
        std::cerr << "rmfx edit: " << blit.error() << "\n";
        return 2;
    }
    (*window)->show(windowSizeFor(session->executor().viewport()));
    (*window)->setVsync(!options.frames);

    Editor editor(**window, *session, **blit, options.split);
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
