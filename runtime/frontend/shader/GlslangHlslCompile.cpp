#include "frontend/shader/GlslangHlslCompile.h"

#include <cstring>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

namespace rmfx {

namespace {
const char kRequestHeader[] = "rmfx-hlsl-request 1\n";
}

std::string GlslangHlslRequest::serialize() const {
    return kRequestHeader + std::string(vertex ? "vertex\n" : "pixel\n") + entryPoint + "\n" + code;
}

bool GlslangHlslRequest::deserialize(const std::string& bytes, GlslangHlslRequest& out) {
    if (bytes.rfind(kRequestHeader, 0) != 0) return false;
    size_t stageStart = sizeof kRequestHeader - 1;
    size_t stageEnd = bytes.find('\n', stageStart);
    if (stageEnd == std::string::npos) return false;
    std::string stage = bytes.substr(stageStart, stageEnd - stageStart);
    if (stage != "vertex" && stage != "pixel") return false;
    size_t entryEnd = bytes.find('\n', stageEnd + 1);
    if (entryEnd == std::string::npos) return false;
    out.vertex = stage == "vertex";
    out.entryPoint = bytes.substr(stageEnd + 1, entryEnd - stageEnd - 1);
    out.code = bytes.substr(entryEnd + 1);
    return true;
}

std::string GlslangHlslOutcome::serialize() const {
    std::string bytes(1, kind);
    if (kind == Compiled) {
        bytes.append(reinterpret_cast<const char*>(spirv.data()), spirv.size() * sizeof(unsigned));
    } else {
        bytes += log;
    }
    return bytes;
}

GlslangHlslOutcome GlslangHlslOutcome::deserialize(const std::string& bytes) {
    GlslangHlslOutcome out;
    if (bytes.empty()) return out;
    out.kind = static_cast<Kind>(bytes[0]);
    if (out.kind == Compiled) {
        out.spirv.resize((bytes.size() - 1) / sizeof(unsigned));
        std::memcpy(out.spirv.data(), bytes.data() + 1, out.spirv.size() * sizeof(unsigned));
    } else if (out.kind == NoEntryPoint) {
    } else {
        out.kind = Failed;
        out.log = bytes.substr(1);
    }
    return out;
}

GlslangHlslOutcome compileHlslToSpirv(const GlslangHlslRequest& request) {
    static const bool initialized = glslang::InitializeProcess();
    (void)initialized;
    EShLanguage language = request.vertex ? EShLangVertex : EShLangFragment;
    glslang::TShader shader(language);
    const char* text = request.code.c_str();
    shader.setStrings(&text, 1);
    shader.setEntryPoint(request.entryPoint.c_str());
    shader.setEnvInput(glslang::EShSourceHlsl, language, glslang::EShClientOpenGL, 100);
    shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    shader.setEnvTargetHlslFunctionality1();  // keeps the semantics in the SPIR-V
    shader.setAutoMapLocations(true);
    shader.setAutoMapBindings(true);
    auto messages = static_cast<EShMessages>(EShMsgReadHlsl | EShMsgHlslDX9Compatible | EShMsgSpvRules);
    glslang::TProgram program;
    GlslangHlslOutcome out;
    bool parsed = shader.parse(GetDefaultResources(), 100, false, messages);
    if (parsed) program.addShader(&shader);
    if (!parsed || !program.link(messages)) {
        out.log = parsed ? program.getInfoLog() : shader.getInfoLog();
        return out;
    }
    // glslang only warns when the entry point is missing, and compiles an empty shader.
    if (std::string(program.getInfoLog()).find("Entry point not found") != std::string::npos) {
        out.kind = GlslangHlslOutcome::NoEntryPoint;
        return out;
    }
    out.kind = GlslangHlslOutcome::Compiled;
    glslang::GlslangToSpv(*program.getIntermediate(language), out.spirv);
    return out;
}

}  // namespace rmfx
