#include "frontend/shader/LegacyGlslVersion.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include "frontend/shader/CompilerLogLine.h"
#include "frontend/shader/GlslangProcess.h"

namespace rmfx {
namespace {

struct Parsed {
    bool ok = false;
    std::string log;
};

// Parsed as a desktop driver sees a stage without #version: `version`, no profile (the
// compatibility built-ins), no client API.
Parsed parseAs(const std::string& code, ShaderStage stage, int version) {
    initializeGlslangOnce();
    const EShLanguage language = stage == ShaderStage::Vertex ? EShLangVertex : EShLangFragment;
    glslang::TShader shader(language);
    const char* text = code.c_str();
    shader.setStrings(&text, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientNone, 0);
    Parsed out;
    out.ok = shader.parse(GetDefaultResources(), version, ENoProfile, false, false, EShMsgDefault);
    if (!out.ok) out.log = shader.getInfoLog();
    return out;
}

std::string firstError(const std::string& log) {
    size_t start = 0;
    while (start < log.size()) {
        size_t end = log.find('\n', start);
        if (end == std::string::npos) end = log.size();
        const std::string_view line(log.data() + start, end - start);
        if (std::optional<CompilerLogLine> parsed = parseCompilerLogLine(line); parsed && parsed->error) {
            std::string message(parsed->message);
            while (!message.empty() && message.back() == ' ') message.pop_back();
            return message;
        }
        start = end + 1;
    }
    return "it does not compile";
}

}  // namespace

std::optional<std::string> rejectedOnlyByGlsl110(const std::string& code, ShaderStage stage) {
    const Parsed as110 = parseAs(code, stage, 110);
    if (as110.ok || !parseAs(code, stage, 120).ok) return std::nullopt;
    return firstError(as110.log);
}

}  // namespace rmfx
