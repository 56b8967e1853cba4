#include "bench/accuracy/VariantRun.h"

#include <algorithm>
#include <chrono>

#include <epoxy/gl.h>

#include "compile/CompiledFrame.h"
#include "gl/GlExecutor.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::accuracy {

namespace fs = std::filesystem;

Result<VariantMeasurement> measureVariant(const Workspace& stageWorkspace, const StageSpec& stage, const Variant& variant,
                                          const fs::path& inputFile, glm::ivec2 size,
                                          const std::vector<std::pair<std::string, std::string>>& extra,
                                          const FrameCounts& counts, const CheckedPrograms* programs) {
    const std::string what = "stage " + stage.name + ", variant '" + variant.name + "': ";
    Workspace ws = stageWorkspace;
    auto input = std::find_if(ws.textures.begin(), ws.textures.end(), [](const Texture& t) { return t.name == "Input"; });
    if (input == ws.textures.end() || input->kind != TextureKind::Texture2D)
        return Error{what + ws.path.string() + " has no 2D texture named 'Input' for the bench to replace"};
    input->files = {fs::absolute(inputFile).string()};

    std::vector<std::pair<std::string, std::string>> settings = variant.settings;
    settings.insert(settings.end(), extra.begin(), extra.end());
    if (Result<void> set = applyOverrides(ws, settings); !set) return Error{what + formatAll(set.diagnostics())};
    if (!ws.canReadTarget(stage.output))
        return Error{what + ws.path.string() + " has no target '" + stage.output + "' (" + ws.describeTargets() + ")"};

    ExecutorOptions options;
    options.outputs = {stage.output};
    options.effects = std::vector<std::string>{variant.effect};
    auto frame = compileFrame(std::make_shared<const Workspace>(ws), options, size, kGuaranteedMaxTargetSize, programs);
    if (!frame) return Error{what + formatAll(frame.diagnostics())};
    auto created = GlExecutor::create(std::move(*frame), options);
    if (!created) return Error{what + formatAll(created.diagnostics())};
    std::unique_ptr<GlExecutor> executor = std::move(*created);

    executor->setTimingEnabled(true);
    FrameClock clock{0.0f, 1.0f / 60.0f};
    std::vector<double> milliseconds, wallMilliseconds;
    for (int i = 0; i < counts.warmup + counts.frames; ++i) {
        auto started = std::chrono::steady_clock::now();
        if (auto frame = executor->renderFrame(clock); !frame) return Error{what + formatAll(frame.diagnostics())};
        glFinish();  // this frame's queries are complete: passTimings collects this very frame
        double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
        executor->passTimings();
        if (i >= counts.warmup) {
            milliseconds.push_back(executor->frameGpuMilliseconds());
            wallMilliseconds.push_back(wall);
        }
        clock.time += clock.deltaTime;
    }
    executor->setTimingEnabled(false);

    auto output = executor->readTarget(stage.output);
    if (!output) return Error{what + output.error()};
    return VariantMeasurement{summariseTimes(std::move(milliseconds)), summariseTimes(std::move(wallMilliseconds)),
                              std::move(*output)};
}

}  // namespace rmfx::accuracy
