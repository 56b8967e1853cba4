#include "compile/RunPreparation.h"

#include <optional>

namespace rmfx {

Result<LoadedRun> loadRun(const RunRequest& request) {
    LoadedRun loaded;
    Result<Workspace> ws = request.workspace
                               ? loadWorkspace(*request.workspace, request.validation, request.load, &loaded.programs)
                               : loadDefaultWorkspace(request.validation, request.load.media, request.load.textures, &loaded.programs);
    Diagnostics diagnostics = ws.takeDiagnostics();
    if (!ws) return Result<LoadedRun>::failure(std::move(diagnostics));
    loaded.ws = std::move(*ws);
    Diagnostics set = applyOverrides(loaded.ws, request.overrides).takeDiagnostics();
    diagnostics.insert(diagnostics.end(), set.begin(), set.end());
    if (hasErrors(diagnostics)) return Result<LoadedRun>::failure(std::move(diagnostics));
    return {std::move(loaded), std::move(diagnostics)};
}

Result<void> readRunInputs(LoadedRun& loaded, const RunRequest& request) {
    loaded.viewport = request.size.x > 0 ? request.size : glm::ivec2(loaded.ws.width, loaded.ws.height);
    loaded.inputsRead = true;
    if (request.inputs.empty()) return {};
    Result<SuppliedInputs> supplied =
        supplyInputs(loaded.ws, request.inputs, request.size.x > 0 ? std::optional(request.size) : std::nullopt);
    if (!supplied) return Result<void>::failure(supplied.takeDiagnostics());
    loaded.viewport = supplied->viewport;
    loaded.givenInputs = supplied->given;
    return supplied.takeDiagnostics();
}

Result<PreparedRun> compileRun(LoadedRun loaded, const RunRequest& request) {
    Diagnostics diagnostics;
    if (!loaded.inputsRead) {
        diagnostics = readRunInputs(loaded, request).takeDiagnostics();
        if (hasErrors(diagnostics)) return Result<PreparedRun>::failure(std::move(diagnostics));
    }
    PreparedRun run;
    run.plan = request.plan;
    run.plan.givenInputs.insert(loaded.givenInputs.begin(), loaded.givenInputs.end());
    auto frame = compileFrame(std::make_shared<const Workspace>(std::move(loaded.ws)), run.plan, loaded.viewport,
                              kGuaranteedMaxTargetSize, &loaded.programs);
    Diagnostics compiled = frame.takeDiagnostics();
    diagnostics.insert(diagnostics.end(), compiled.begin(), compiled.end());
    if (!frame) return Result<PreparedRun>::failure(std::move(diagnostics));
    run.frame = std::move(*frame);
    return {std::move(run), std::move(diagnostics)};
}

Result<PreparedRun> prepareRun(const RunRequest& request) {
    Result<LoadedRun> loaded = loadRun(request);
    Diagnostics diagnostics = loaded.takeDiagnostics();
    if (!loaded) return Result<PreparedRun>::failure(std::move(diagnostics));
    Result<PreparedRun> prepared = compileRun(std::move(*loaded), request);
    Diagnostics more = prepared.takeDiagnostics();
    diagnostics.insert(diagnostics.end(), more.begin(), more.end());
    if (!prepared) return Result<PreparedRun>::failure(std::move(diagnostics));
    return {std::move(*prepared), std::move(diagnostics)};
}

}  // namespace rmfx
