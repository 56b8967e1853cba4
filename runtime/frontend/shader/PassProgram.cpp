#include "frontend/shader/PassProgram.h"

#include "frontend/shader/ClipSpaceTurnOver.h"
#include "frontend/shader/HlslAlphaTest.h"
#include "frontend/shader/HlslFixedFunctionFog.h"
#include "frontend/shader/HlslTranslationCache.h"
#include "frontend/shader/LegacyGlslVersion.h"

namespace rmfx {

namespace {

// ps_3_0 (any case): Direct3D 9 applies no fixed-function fog after it.
bool isShaderModel3(const std::string& profile) {
    return profile.size() >= 4 && (profile[0] == 'p' || profile[0] == 'P') && (profile[1] == 's' || profile[1] == 'S') &&
           profile[2] == '_' && profile[3] == '3';
}

// The text before main() of a built-in vertex shader: #version, the attributes and the varyings.
std::string builtinVertexHeader(ShaderDialect dialect, bool normal) {
    bool modern = dialect != ShaderDialect::GlslLegacy && dialect != ShaderDialect::GlslEs100;
    std::string in = modern ? "in" : "attribute", out = modern ? "out" : "varying";
    std::string text = modern ? "#version 450 core\n" : dialect == ShaderDialect::GlslEs100 ? "#version 100\n" : "#version 110\n";
    auto layout = [&](int location) { return modern ? "layout(location = " + std::to_string(location) + ") " : std::string(); };
    text += layout(0) + in + " vec3 rm_Position;\n";
    if (normal) text += layout(1) + in + " vec3 rm_NormalIn;\n";
    text += layout(2) + in + " vec2 rm_TexCoordIn;\n";
    for (const char* varying : {"vec2 vTexCoord;", "vec3 vWorldPosition;", "vec3 vWorldNormal;"}) text += out + " " + varying + "\n";
    return text;
}

// Legacy fragment shaders read the texture coordinate as gl_TexCoord[0].
std::string legacyTexCoord(ShaderDialect dialect) {
    return dialect == ShaderDialect::GlslLegacy ? "    gl_TexCoord[0] = vec4(rm_TexCoordIn, 0.0, 1.0);\n" : "";
}

}  // namespace

std::string builtinFullscreenVertexShader(ShaderDialect dialect) {
    return builtinVertexHeader(dialect, false) + R"(uniform mat4 rm_InvViewProjection;
void main() {
    vTexCoord = rm_TexCoordIn;
    vec4 far = rm_InvViewProjection * vec4(rm_Position.xy, 1.0, 1.0);
    vWorldPosition = far.xyz / far.w;
    vWorldNormal = vec3(0.0, 0.0, 1.0);
    gl_Position = vec4(rm_Position.xy, 0.0, 1.0);
)" + legacyTexCoord(dialect) + "}\n";
}

std::string builtinModelVertexShader(ShaderDialect dialect) {
    return builtinVertexHeader(dialect, true) + R"(uniform mat4 rm_Model;
uniform mat4 rm_ViewProjection;
uniform mat3 rm_NormalMatrix;
void main() {
    vec4 world = rm_Model * vec4(rm_Position, 1.0);
    vTexCoord = rm_TexCoordIn;
    vWorldPosition = world.xyz;
    vWorldNormal = rm_NormalMatrix * rm_NormalIn;
    gl_Position = rm_ViewProjection * world;
)" + legacyTexCoord(dialect) + "}\n";
}

std::string passLabel(const Pass& pass) { return "<pass name=\"" + pass.name + "\">"; }

Result<PassProgramSource> assemblePassProgram(const Workspace& ws, const Pass& pass,
                                              const std::vector<std::string>& defines,
                                              const std::vector<std::string>& declarations) {
    Diagnostics diagnostics;
    PassProgramSource program;
    std::vector<ReflectedVariable> pixelInputs;  // of an HLSL fragment shader
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
        input.dialect = s.dialect;
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
        auto failed = [&] { return hasErrors(Diagnostics(diagnostics.begin() + static_cast<long>(before), diagnostics.end())); };
        PassStage stage{s.stage, preprocessShader(input, diagnostics), s.where, false, s.dialect};
        if (s.dialect == ShaderDialect::GlslLegacy && !failed() && !openingVersion(stage.shader.code)) {
            if (std::optional<std::string> why = rejectedOnlyByGlsl110(stage.shader.code, s.stage)) {
                stage.shader.code.insert(0, "#version 120\n");
                stage.shader.lineOrigins.insert(stage.shader.lineOrigins.begin(), stage.shader.origin(1));
                diagnostics.push_back({Diagnostic::Severity::Warning, s.where, passLabel(pass),
                                       std::string(s.stage == ShaderStage::Vertex ? "vertex" : "fragment") +
                                           " shader without #version: GLSL 1.10 rejects it (" + *why +
                                           "), so it is compiled with GLSL 1.20's rules (implicit int to float), "
                                           "as the lenient drivers it was written for did"});
            }
        }
        if (s.dialect == ShaderDialect::Hlsl && !failed()) {
            HlslStage hlsl{s.stage, s.entryPoint, s.profile};
            Result<HlslTranslation> translated =
                HlslTranslationCache::shared().translate(stage.shader, hlsl, s.where, passLabel(pass));
            diagnostics.insert(diagnostics.end(), translated.diagnostics().begin(), translated.diagnostics().end());
            if (translated) {
                stage.shader = std::move(translated->glsl);
                if (s.stage == ShaderStage::Fragment) pixelInputs = std::move(translated->inputs);
                // Direct3D 9 tests alpha after every pixel shader, and fogs after ps_1_x and ps_2_x
                // ones (ps_3_0 ones fog themselves).
                if (s.stage == ShaderStage::Fragment && pass.alphaTest.enabled && !appendAlphaTest(stage.shader.code, pass.alphaTest))
                    diagnostics.push_back({Diagnostic::Severity::Warning, s.where, passLabel(pass),
                                           "the pixel shader writes no COLOR0 for Direct3D's alpha test: drawn untested"});
                if (s.stage == ShaderStage::Fragment && pass.fog.applies() && !isShaderModel3(s.profile) &&
                    !appendFixedFunctionFog(stage.shader.code, pass.fog))
                    diagnostics.push_back({Diagnostic::Severity::Warning, pass.fog.where, passLabel(pass),
                                           "the pixel shader writes no COLOR0 for Direct3D's fog to blend: drawn without fog"});
            }
            stage.dialect = ShaderDialect::Glsl;
        }
        if (!s.file.empty()) stage.shader.files.insert(stage.shader.files.begin(), ws.folder / s.file);
        if (failed()) ok = false;
        program.stages.push_back(std::move(stage));
    };
    if (vertex) add(*vertex);
    if (fragment) add(*fragment);
    if (vertex && fragment && vertex->dialect == ShaderDialect::Hlsl && fragment->dialect == ShaderDialect::Hlsl && ok &&
        program.stages.size() == 2) {
        std::vector<std::string> supplied = supplyUnwrittenVaryings(program.stages[0].shader.code, pixelInputs);
        if (!supplied.empty()) {
            std::string list;
            for (const std::string& semantic : supplied) list += (list.empty() ? "" : ", ") + semantic;
            diagnostics.push_back({Diagnostic::Severity::Warning, fragment->where, passLabel(pass),
                                   "the pixel shader takes " + list + " as input, which the vertex shader does not write; " +
                                       "Direct3D 9 ran it anyway, so rmfx supplies " +
                                       (supplied.size() == 1 ? "it" : "them") +
                                       " (COLORn opaque white, others (0, 0, 0, 1))"});
        }
        std::vector<std::string> matched = matchVaryingSizes(program.stages[0].shader.code, pixelInputs);
        if (!matched.empty()) {
            std::string list;
            for (const std::string& m : matched) list += (list.empty() ? "" : ", ") + m;
            diagnostics.push_back({Diagnostic::Severity::Warning, fragment->where, passLabel(pass),
                                   "the stages declare " + list + " with different sizes; Direct3D 9 matched them by "
                                   "register, so rmfx passes the value on, cut to the size read or filled with 0 (w 1)"});
        }
    }
    if (!vertex) {
        bool fullscreen = pass.draw.mesh == BuiltinMesh::FullscreenTriangle;
        // An HLSL fragment shader arrives as GLSL 4.50, so its built-in vertex shader is GLSL 4.50.
        const bool hlsl = fragment && fragment->dialect == ShaderDialect::Hlsl;
        ShaderDialect dialect = fragment && !hlsl ? fragment->dialect : ShaderDialect::Glsl;
        ShaderInput input;
        input.dialect = dialect;
        input.code = fullscreen ? builtinFullscreenVertexShader(dialect) : builtinModelVertexShader(dialect);
        if (hlsl && ok) {
            // Direct3D runs a pass without a vertex shader through its fixed-function vertex
            // processing; the built-in vertex shader hands the pixel shader what that would.
            if (Result<FixedFunctionVaryings> varyings = hlslFixedFunctionVaryings(pixelInputs)) {
                input.code.insert(input.code.find("void main() {"), varyings->declarations);
                input.code.insert(input.code.rfind('}'), varyings->assignments);
            } else {
                diagnostics.push_back({Diagnostic::Severity::Error, fragment->where, passLabel(pass), varyings.error()});
                ok = false;
            }
        }
        input.start = {fullscreen ? "<built-in fullscreen vertex shader>" : "<built-in model vertex shader>", 1};
        input.root = ws.includeFolder();
        input.folder = ws.folder;
        PassStage stage{ShaderStage::Vertex, preprocessShader(input, diagnostics), pass.where, true, dialect};
        program.stages.insert(program.stages.begin(), std::move(stage));
    }
    if (!ok || hasErrors(diagnostics)) return Result<PassProgramSource>::failure(std::move(diagnostics));
    turnClipSpaceOver(program.stages.front().shader, ws.textureSpace);
    return {std::move(program), std::move(diagnostics)};
}

}  // namespace rmfx
