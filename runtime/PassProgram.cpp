#include "runtime/PassProgram.h"


namespace rmfx {

const char* builtinFullscreenVertexShader() {
    return R"(#version 450 core
layout(location = 0) in vec3 rm_Position;
layout(location = 2) in vec2 rm_TexCoordIn;
uniform mat4 rm_InvViewProjection;
out vec2 vTexCoord;
out vec3 vWorldPosition;
out vec3 vWorldNormal;
void main() {
    vTexCoord = rm_TexCoordIn;
    vec4 far = rm_InvViewProjection * vec4(rm_Position.xy, 1.0, 1.0);
    vWorldPosition = far.xyz / far.w;
    vWorldNormal = vec3(0.0, 0.0, 1.0);
    gl_Position = vec4(rm_Position.xy, 0.0, 1.0);
}
)";
}

const char* builtinModelVertexShader() {
    return R"(#version 450 core
layout(location = 0) in vec3 rm_Position;
layout(location = 1) in vec3 rm_NormalIn;
layout(location = 2) in vec2 rm_TexCoordIn;
uniform mat4 rm_Model;
uniform mat4 rm_ViewProjection;
uniform mat3 rm_NormalMatrix;
out vec2 vTexCoord;
out vec3 vWorldPosition;
out vec3 vWorldNormal;
void main() {
    vec4 world = rm_Model * vec4(rm_Position, 1.0);
    vTexCoord = rm_TexCoordIn;
    vWorldPosition = world.xyz;
    vWorldNormal = rm_NormalMatrix * rm_NormalIn;
    gl_Position = rm_ViewProjection * world;
}
)";
}

std::string passLabel(const Pass& pass) { return "<pass name=\"" + pass.name + "\">"; }

std::optional<PassProgramSource> assemblePassProgram(const Workspace& ws, const Pass& pass,
                                                     const std::vector<std::string>& defines,
                                                     Diagnostics& diagnostics,
                                                     const std::vector<std::string>& declarations) {
    PassProgramSource program;
    bool ok = true;
    const ShaderSource* vertex = nullptr;
    const ShaderSource* fragment = nullptr;
    for (const ShaderSource& s : pass.shaders) (s.stage == ShaderStage::Vertex ? vertex : fragment) = &s;
    if (!fragment) {
        diagnostics.push_back({Diagnostic::Severity::Error, pass.where, passLabel(pass), "no fragment shader"});
        ok = false;
    }
    auto add = [&](const ShaderSource& s) {
        ShaderInput input;
        input.root = ws.includeFolder();
        input.defines = defines;
        input.declarations = declarations;
        input.folder = ws.folder;
        input.snippets = &ws.snippets;
        if (s.file.empty()) {
            input.code = s.code;
            input.start = {ws.path.string(), s.codeLine};
        } else {
            std::filesystem::path file = ws.folder / s.file;
            std::optional<std::string> text = readShaderFile(file);
            if (!text) {
                diagnostics.push_back({Diagnostic::Severity::Error, s.where, "<shader>",
                                       "cannot open shader file '" + s.file + "' (looked for " + file.string() + ")"});
                ok = false;
                return;
            }
            input.code = std::move(*text);
            input.start = {file.lexically_normal().string(), 1};
            input.folder = file.parent_path();
        }
        size_t before = diagnostics.size();
        PassStage stage{s.stage, preprocessShader(input, diagnostics), s.where, false};
        if (!s.file.empty()) stage.shader.files.insert(stage.shader.files.begin(), ws.folder / s.file);
        if (hasErrors(Diagnostics(diagnostics.begin() + static_cast<long>(before), diagnostics.end()))) ok = false;
        program.stages.push_back(std::move(stage));
    };
    if (vertex) {
        add(*vertex);
    } else {
        bool fullscreen = pass.draw.mesh == BuiltinMesh::FullscreenTriangle;
        ShaderInput input;
        input.code = fullscreen ? builtinFullscreenVertexShader() : builtinModelVertexShader();
        input.start = {fullscreen ? "<built-in fullscreen vertex shader>" : "<built-in model vertex shader>", 1};
        input.root = ws.includeFolder();
        input.folder = ws.folder;
        PassStage stage{ShaderStage::Vertex, preprocessShader(input, diagnostics), pass.where, true};
        program.stages.push_back(std::move(stage));
    }
    if (fragment) add(*fragment);
    if (!ok) return std::nullopt;
    return program;
}

}  // namespace rmfx
