#include "gl/GlProgramBuild.h"

#include <algorithm>
#include <cstring>
#include <optional>

#include <epoxy/gl.h>

#include "frontend/shader/PassProgram.h"
#include "validation/GlslangCheck.h"

namespace rmfx {
namespace {

template <class GetLength, class GetLog>
std::string infoLog(GetLength getLength, GetLog getLog) {
    GLint length = 0;
    getLength(&length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    getLog(length, log.data());
    log.resize(std::strlen(log.c_str()));
    return log;
}

// Compiles `code` as a stage of `type` and attaches it to `program`; the compiler's log when it
// fails, nullopt when it compiles.
std::optional<std::string> compileInto(GLuint program, GLenum type, const std::string& code) {
    ShaderHandle shader = createShader(type);
    const char* text = code.c_str();
    glShaderSource(shader.get(), 1, &text, nullptr);
    glCompileShader(shader.get());
    GLint compiled = 0;
    glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &compiled);
    glAttachShader(program, shader.get());
    if (compiled) return std::nullopt;
    return infoLog([&](GLint* n) { glGetShaderiv(shader.get(), GL_INFO_LOG_LENGTH, n); },
                   [&](GLint n, char* log) { glGetShaderInfoLog(shader.get(), n, nullptr, log); });
}

// Links `program` with the built-in vertex shaders' attributes at rmfx's locations (for dialects
// without layout qualifiers); the linker's log when it fails.
std::optional<std::string> linkWithBuiltinAttributes(GLuint program) {
    for (GLuint a = 0; a < 3; ++a) glBindAttribLocation(program, a, builtinAttributeLocations[a]);
    glLinkProgram(program);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (linked) return std::nullopt;
    return infoLog([&](GLint* n) { glGetProgramiv(program, GL_INFO_LOG_LENGTH, n); },
                   [&](GLint n, char* log) { glGetProgramInfoLog(program, n, nullptr, log); });
}

}  // namespace

Result<PassGlProgram> linkPassProgram(const Pass& pass, const PassProgramSource& source) {
    Diagnostics d;
    PassGlProgram built;
    built.initializedUniforms = uniformsWithInitializers(source);
    std::string label = passLabel(pass);
    built.program = createProgram();
    const GLuint program = built.program.get();
    bool ok = true;
    for (const PassStage& stage : source.stages) {
        const bool vertex = stage.stage == ShaderStage::Vertex;
        (vertex ? built.vertexCode : built.fragmentCode) = stage.shader.code;
        if (std::optional<std::string> log = compileInto(program, vertex ? GL_VERTEX_SHADER : GL_FRAGMENT_SHADER, stage.shader.code)) {
            auto mapped = mapCompilerLog(*log, stage.shader, stage.where, label);
            if (mapped.empty()) mapped.push_back({Diagnostic::Severity::Error, stage.where, label, "shader failed to compile"});
            d.insert(d.end(), mapped.begin(), mapped.end());
            ok = false;
        }
    }
    if (!ok) return Result<PassGlProgram>::failure(std::move(d));
    if (std::optional<std::string> log = linkWithBuiltinAttributes(program)) {
        d.push_back({Diagnostic::Severity::Error, pass.where, label, "shaders failed to link: " + *log});
        return Result<PassGlProgram>::failure(std::move(d));
    }
    return built;
}

Result<PassGlProgram> buildPassProgram(const Workspace& ws, const Pass& pass, const ShaderPrelude& prelude) {
    Result<PassProgramSource> source = assemblePassProgram(ws, pass, prelude.defines, prelude.declarations);
    Diagnostics d = source.diagnostics();
    if (!source) return Result<PassGlProgram>::failure(std::move(d));
    Result<PassGlProgram> linked = linkPassProgram(pass, *source);
    Diagnostics more = linked.diagnostics();
    d.insert(d.end(), more.begin(), more.end());
    if (!linked) return Result<PassGlProgram>::failure(std::move(d));
    return Result<PassGlProgram>(std::move(*linked), std::move(d));
}

Result<ProgramHandle> relinkWithFragment(const PassGlProgram& built, const std::string& fragmentCode) {
    ProgramHandle program = createProgram();
    for (const auto& [type, code] : {std::pair{GL_VERTEX_SHADER, &built.vertexCode}, {GL_FRAGMENT_SHADER, &fragmentCode}})
        if (std::optional<std::string> log = compileInto(program.get(), type, *code)) return Error{*log};
    if (std::optional<std::string> log = linkWithBuiltinAttributes(program.get())) return Error{*log};
    return program;
}

std::vector<ProgramUniform> programUniforms(unsigned program) {
    std::vector<ProgramUniform> uniforms;
    GLint count = 0;
    glGetProgramInterfaceiv(program, GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
    for (GLint i = 0; i < count; ++i) {
        const GLenum props[4] = {GL_TYPE, GL_LOCATION, GL_ARRAY_SIZE, GL_BLOCK_INDEX};
        GLint values[4] = {};
        glGetProgramResourceiv(program, GL_UNIFORM, static_cast<GLuint>(i), 4, props, 4, nullptr, values);
        if (values[3] != -1 || values[1] < 0) continue;  // block members are not rmfx variables
        char nameBuffer[256] = {};
        glGetProgramResourceName(program, GL_UNIFORM, static_cast<GLuint>(i), sizeof nameBuffer, nullptr, nameBuffer);
        std::string name = nameBuffer;
        if (name.size() > 3 && name.compare(name.size() - 3, 3, "[0]") == 0) name.resize(name.size() - 3);
        uniforms.push_back({name, values[0], values[1], values[2]});
    }
    return uniforms;
}

std::set<std::string> activeInputs(unsigned program) {
    std::set<std::string> inputs;
    GLint count = 0;
    glGetProgramInterfaceiv(program, GL_PROGRAM_INPUT, GL_ACTIVE_RESOURCES, &count);
    for (GLint i = 0; i < count; ++i) {
        char name[256] = {};
        glGetProgramResourceName(program, GL_PROGRAM_INPUT, static_cast<GLuint>(i), sizeof name, nullptr, name);
        inputs.insert(name);
    }
    return inputs;
}

}  // namespace rmfx
