#include "validation/GlslangCheck.h"

#include "core/IdentifierSearch.h"
#include "frontend/shader/GlslangProcess.h"

#include <cctype>
#include <memory>
#include <string_view>
#include <utility>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

namespace rmfx {
namespace {

EShLanguage language(ShaderStage stage) {
    return stage == ShaderStage::Vertex ? EShLangVertex : EShLangFragment;
}

// The version and profile glslang assumes for a stage without #version: the dialect's default.
// Versions below 150 have no profile, and glslang gives them the compatibility built-ins
// (gl_ModelViewProjectionMatrix, gl_LightSource, ftransform()).
std::pair<int, EProfile> defaultVersion(ShaderDialect dialect) {
    switch (dialect) {
        case ShaderDialect::GlslLegacy: return {110, ENoProfile};
        case ShaderDialect::GlslEs100: return {100, EEsProfile};
        case ShaderDialect::Glsl:
        case ShaderDialect::Hlsl: break;  // Hlsl arrives translated to GLSL 4.50
    }
    return {450, ECoreProfile};
}

}  // namespace

Result<std::vector<ActiveUniform>> checkPassProgram(const PassProgramSource& program, const std::string& element,
                                                    std::vector<std::string>* vertexInputs) {
    using Checked = Result<std::vector<ActiveUniform>>;
    initializeGlslangOnce();
    Diagnostics diagnostics;
    auto messages = static_cast<EShMessages>(EShMsgDefault);
    std::vector<std::unique_ptr<glslang::TShader>> shaders;
    glslang::TProgram linked;
    bool ok = true;
    for (const PassStage& stage : program.stages) {
        auto shader = std::make_unique<glslang::TShader>(language(stage.stage));
        const char* text = stage.shader.code.c_str();
        shader->setStrings(&text, 1);
        // No client API: plain GLSL as a GL driver sees it (the OpenGL client means GL_ARB_gl_spirv
        // rules, which demand explicit uniform locations).
        shader->setEnvInput(glslang::EShSourceGlsl, language(stage.stage), glslang::EShClientNone, 0);
        auto [version, profile] = defaultVersion(stage.dialect);
        if (!shader->parse(GetDefaultResources(), version, profile, false, false, messages)) {
            SourceLocation fallback = stage.shader.origin(1);
            for (Diagnostic d : mapCompilerLog(shader->getInfoLog(), stage.shader, fallback, element)) {
                diagnostics.push_back(std::move(d));
            }
            ok = false;
            continue;
        }
        linked.addShader(shader.get());
        shaders.push_back(std::move(shader));
    }
    if (!ok) return Checked::failure(std::move(diagnostics));
    if (!linked.link(messages)) {
        std::string log = linked.getInfoLog();
        SourceLocation where = program.stages.back().where;
        for (Diagnostic d : mapCompilerLog(log, program.stages.back().shader, where, element)) {
            d.where = where;  // link messages carry no line of their own
            d.message = "link: " + d.message;
            diagnostics.push_back(std::move(d));
        }
        return Checked::failure(std::move(diagnostics));
    }
    linked.buildReflection(EShReflectionDefault);
    if (vertexInputs)
        for (int i = 0; i < linked.getNumPipeInputs(); ++i) vertexInputs->push_back(linked.getPipeInput(i).name);
    std::vector<ActiveUniform> uniforms;
    for (int i = 0; i < linked.getNumUniformVariables(); ++i) {
        const glslang::TObjectReflection& u = linked.getUniform(i);
        if (std::string_view(u.name).substr(0, 3) == "gl_") continue;  // built-in state (compatibility profile)
        ActiveUniform a;
        a.name = u.name;
        a.glType = u.glDefineType;
        a.type = uniformTypeFromGl(u.glDefineType);
        a.arraySize = u.size > 0 ? u.size : 1;
        if (a.name.size() > 3 && a.name.compare(a.name.size() - 3, 3, "[0]") == 0) a.name.resize(a.name.size() - 3);
        uniforms.push_back(std::move(a));
    }
    return uniforms;
}

Result<std::string> preprocessStage(const PassStage& stage) {
    initializeGlslangOnce();
    glslang::TShader shader(language(stage.stage));
    const char* text = stage.shader.code.c_str();
    shader.setStrings(&text, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, language(stage.stage), glslang::EShClientNone, 0);
    auto [version, profile] = defaultVersion(stage.dialect);
    std::string out;
    glslang::TShader::ForbidIncluder includer;
    if (!shader.preprocess(GetDefaultResources(), version, profile, false, false, EShMsgDefault, &out, includer))
        return Error{shader.getInfoLog()};
    return out;
}

std::optional<SourceLocation> findUniformDeclaration(const PassProgramSource& program, const std::string& name) {
    for (const PassStage& stage : program.stages) {
        int line = 1;
        size_t start = 0;
        const std::string& code = stage.shader.code;
        while (start < code.size()) {
            size_t end = code.find('\n', start);
            if (end == std::string::npos) end = code.size();
            if (lineDeclaresUniform(std::string_view(code).substr(start, end - start), name))
                return stage.shader.origin(line);
            start = end + 1;
            ++line;
        }
    }
    return std::nullopt;
}

std::set<std::string> uniformsWithInitializers(const PassProgramSource& program) {
    std::set<std::string> out;
    auto isWordChar = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    for (const PassStage& stage : program.stages) {
        const std::string& code = stage.shader.code;
        size_t start = 0;
        while (start < code.size()) {
            size_t end = code.find_first_of(";{}", start);
            if (end == std::string::npos) end = code.size();
            std::string statement = code.substr(start, end - start);
            start = end + 1;
            size_t equals = statement.find('=');
            size_t keyword = statement.find("uniform");
            if (equals == std::string::npos || keyword == std::string::npos || keyword > equals) continue;
            if ((keyword > 0 && isWordChar(statement[keyword - 1])) || isWordChar(statement[keyword + 7])) continue;
            size_t nameEnd = statement.find_last_not_of(" \t\r\n", equals - 1);
            if (nameEnd == std::string::npos || nameEnd <= keyword + 7) continue;
            if (statement[nameEnd] == ']') {  // uniform float w[2] = float[](…)
                size_t open = statement.rfind('[', nameEnd);
                if (open == std::string::npos || open <= keyword + 7) continue;
                nameEnd = statement.find_last_not_of(" \t", open - 1);
            }
            size_t nameStart = nameEnd;
            while (nameStart > 0 && isWordChar(statement[nameStart - 1])) --nameStart;
            if (isWordChar(statement[nameEnd])) out.insert(statement.substr(nameStart, nameEnd - nameStart + 1));
        }
    }
    return out;
}

bool keepsInitialValue(const std::set<std::string>& initialized, const std::string& name) {
    return initialized.count(name) > 0 || initialized.count(name.substr(0, name.find_first_of("[."))) > 0;
}

}  // namespace rmfx
