#include "validation/WorkspaceLoader.h"

#include "frontend/rfx/RfxCameraFraming.h"
#include "frontend/rfx/RfxImporter.h"
#include "frontend/workspace/DefaultWorkspace.h"
#include "frontend/workspace/WorkspaceParser.h"

namespace rmfx {

static Result<Workspace> validated(Result<Workspace> parsed, const ValidationOptions& options, const MediaOptions& media,
                                   const std::vector<TextureArgument>& textures, bool imported, CheckedPrograms* handOver) {
    Diagnostics diagnostics = parsed.takeDiagnostics();
    if (!parsed) return Result<Workspace>::failure(std::move(diagnostics));
    Result<void> replaced = replaceTextures(*parsed, textures);
    diagnostics.insert(diagnostics.end(), replaced.diagnostics().begin(), replaced.diagnostics().end());
    if (!replaced) return Result<Workspace>::failure(std::move(diagnostics));
    std::set<std::string> given;
    for (const TextureArgument& t : textures) given.insert(t.name);
    // References are resolved once, here: what validation, the executor and hot reload open.
    // Until they all resolve nothing reads them (a shader outside the sandbox is not even compiled).
    Result<void> resolved = resolveWorkspaceMedia(*parsed, media, given);
    diagnostics.insert(diagnostics.end(), resolved.diagnostics().begin(), resolved.diagnostics().end());
    if (!resolved) return Result<Workspace>::failure(std::move(diagnostics));
    if (imported) frameDrawnModels(*parsed);
    Diagnostics found = validateWorkspace(*parsed, options, handOver).diagnostics();
    diagnostics.insert(diagnostics.end(), found.begin(), found.end());
    if (hasErrors(diagnostics)) return Result<Workspace>::failure(std::move(diagnostics));
    return {std::move(*parsed), std::move(diagnostics)};
}

Result<Workspace> loadWorkspace(const std::filesystem::path& path, const ValidationOptions& options,
                                const WorkspaceLoadOptions& load, CheckedPrograms* handOver) {
    if (isRfxPath(path))
        return validated(importRfxFile(path, {load.effect, load.rfxMatrices}), options, load.media, load.textures, true, handOver);
    if (!load.effect.empty()) {
        return Result<Workspace>::failure(
            {{Diagnostic::Severity::Error, {path.string(), 0}, "--effect " + load.effect,
              "--effect chooses an effect of a RenderMonkey .rfx file; this is an rmfx workspace "
              "(use --effects to choose its <effect> groups)"}});
    }
    return validated(parseWorkspaceFile(path), options, load.media, load.textures, false, handOver);
}

Result<Workspace> loadDefaultWorkspace(const ValidationOptions& options, const MediaOptions& media,
                                       const std::vector<TextureArgument>& textures, CheckedPrograms* handOver) {
    return validated(parseWorkspaceText(defaultWorkspaceText(), defaultWorkspaceName, "."), options, media, textures, false,
                     handOver);
}

Result<void> applyOverrides(Workspace& ws, const std::vector<std::pair<std::string, std::string>>& overrides) {
    Diagnostics out;
    for (const auto& [name, text] : overrides) {
        Variable* v = ws.findVariable(name);
        std::string element = "--set " + name;
        if (!v) {
            std::string known;
            for (const Variable& each : ws.variables) known += (known.empty() ? "" : ", ") + each.name;
            out.push_back({Diagnostic::Severity::Error, {ws.path.string(), 0}, element,
                           "the workspace has no variable '" + name + "'" +
                               (known.empty() ? " (it declares none)" : " (it has: " + known + ")")});
            continue;
        }
        Result<Value> value = parseValue(v->value.type, text);
        std::string why = value.error();
        if (value && value->type != v->value.type) {
            // A colour's count is fixed by its default (the uniform is a vec3 or a vec4).
            bool rgb = v->value.type == ValueType::Color3;
            why = std::string("this color takes ") + (rgb ? "3 numbers (rgb), got 4" : "4 numbers (rgba), got 3");
        }
        if (!why.empty()) {
            out.push_back({Diagnostic::Severity::Error, v->where, element,
                           "variable '" + name + "' (" + valueTypeName(v->value.type) + "): " + why});
            continue;
        }
        v->value = *value;
    }
    return out;
}

}  // namespace rmfx
