#include "runtime/HlslTranslator.h"

#include <algorithm>
#include <cctype>
#include <memory>
#include <mutex>
#include <set>
#include <vector>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv_cross/spirv_cross_c.h>

namespace rmfx {
namespace {

// The flattened $Global block's instance name; its members become plain uniforms.
constexpr const char* kGlobalBlock = "rm_hlsl_Global";
constexpr const char* kGlobalBlockType = "rm_hlsl_GlobalBlock";

void initializeGlslangOnce() {
    static std::once_flag flag;
    std::call_once(flag, [] { glslang::InitializeProcess(); });
}

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

// "TEXCOORD3" → {"TEXCOORD", 3}; "COLOR" → {"COLOR", 0}; "SV_Position" → {"SV_POSITION", 0}.
std::pair<std::string, int> splitSemantic(const std::string& semantic) {
    std::string s = upper(semantic);
    size_t digits = s.size();
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(s[digits - 1]))) --digits;
    if (digits == s.size() || digits == 0) return {s, 0};
    return {s.substr(0, digits), std::stoi(s.substr(digits, 6))};
}

bool isPositionSemantic(const std::string& semantic) {
    auto [name, index] = splitSemantic(semantic);
    return (name == "POSITION" || name == "SV_POSITION") && index == 0;
}

// Checks the D3D target against the stage: "vs_…" for vertex shaders, "ps_…" for pixel shaders.
bool checkProfile(const HlslStage& stage, const SourceLocation& where, const std::string& element,
                  Diagnostics& diagnostics) {
    if (stage.profile.empty()) return true;
    std::string p = upper(stage.profile);
    bool vertex = p.rfind("VS_", 0) == 0;
    bool pixel = p.rfind("PS_", 0) == 0;
    std::string wanted = stage.stage == ShaderStage::Vertex ? "a vertex shader target (vs_2_0, vs_3_0…)"
                                                            : "a pixel shader target (ps_2_0, ps_3_0…)";
    if ((stage.stage == ShaderStage::Vertex && vertex) || (stage.stage == ShaderStage::Fragment && pixel)) return true;
    diagnostics.push_back({Diagnostic::Severity::Error, where, element,
                           "HLSL target '" + stage.profile + "' is not " + wanted});
    return false;
}

// SPIRV-Cross stage: one compiler over one SPIR-V module, owned by its context.
class CrossCompiler {
public:
    explicit CrossCompiler(const std::vector<unsigned>& spirv) {
        spvc_context_create(&context_);
        spvc_parsed_ir ir = nullptr;
        ok_ = spvc_context_parse_spirv(context_, spirv.data(), spirv.size(), &ir) == SPVC_SUCCESS &&
              spvc_context_create_compiler(context_, SPVC_BACKEND_GLSL, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP,
                                           &compiler_) == SPVC_SUCCESS &&
              spvc_compiler_create_shader_resources(compiler_, &resources_) == SPVC_SUCCESS;
    }
    ~CrossCompiler() { spvc_context_destroy(context_); }
    CrossCompiler(const CrossCompiler&) = delete;
    CrossCompiler& operator=(const CrossCompiler&) = delete;

    bool ok() const { return ok_; }
    std::string error() const { return spvc_context_get_last_error_string(context_); }
    spvc_compiler get() const { return compiler_; }

    std::vector<spvc_reflected_resource> resources(spvc_resource_type type) const {
        const spvc_reflected_resource* list = nullptr;
        size_t count = 0;
        spvc_resources_get_resource_list_for_type(resources_, type, &list, &count);
        return {list, list + count};
    }
    std::string semantic(spvc_variable_id id) const {
        const char* s = spvc_compiler_get_decoration_string(compiler_, id, SpvDecorationHlslSemanticGOOGLE);
        return s ? s : "";
    }

private:
    spvc_context context_ = nullptr;
    spvc_compiler compiler_ = nullptr;
    spvc_resources resources_ = nullptr;
    bool ok_ = false;
};

// Names the stage's inputs and outputs after their semantics; POSITION out of a vertex shader
// becomes gl_Position.
void renameInterface(CrossCompiler& cross, ShaderStage stage) {
    spvc_compiler c = cross.get();
    for (const spvc_reflected_resource& r : cross.resources(SPVC_RESOURCE_TYPE_STAGE_INPUT)) {
        std::string semantic = cross.semantic(r.id);
        if (semantic.empty()) continue;
        spvc_compiler_unset_decoration(c, r.id, SpvDecorationLocation);
        if (stage == ShaderStage::Vertex) {
            auto [name, index] = splitSemantic(semantic);
            spvc_compiler_set_name(c, r.id, ("rm_hlsl_in_" + name + std::to_string(index)).c_str());
            int location = index != 0 ? -1 : name == "POSITION" ? 0 : name == "NORMAL" ? 1 : name == "TEXCOORD" ? 2 : -1;
            if (location >= 0) spvc_compiler_set_decoration(c, r.id, SpvDecorationLocation, static_cast<unsigned>(location));
        } else {
            spvc_compiler_set_name(c, r.id, hlslVaryingName(semantic).c_str());
        }
    }
    for (const spvc_reflected_resource& r : cross.resources(SPVC_RESOURCE_TYPE_STAGE_OUTPUT)) {
        std::string semantic = cross.semantic(r.id);
        if (semantic.empty()) continue;
        if (stage == ShaderStage::Vertex) {
            spvc_compiler_unset_decoration(c, r.id, SpvDecorationLocation);
            if (isPositionSemantic(semantic)) {
                spvc_compiler_set_decoration(c, r.id, SpvDecorationBuiltIn, SpvBuiltInPosition);
            } else {
                spvc_compiler_set_name(c, r.id, hlslVaryingName(semantic).c_str());
            }
        } else {
            auto [name, index] = splitSemantic(semantic);
            if (name == "COLOR" || name == "SV_TARGET") {
                spvc_compiler_set_decoration(c, r.id, SpvDecorationLocation, static_cast<unsigned>(index));
                spvc_compiler_set_name(c, r.id, ("rm_hlsl_out_COLOR" + std::to_string(index)).c_str());
            }
        }
    }
}

// Names the uniform block glslang made of the HLSL globals so flattenGlobals can find it, and
// drops the bindings plain uniforms cannot have. Returns the members' names. (The block's matrices
// carry RowMajor; SPIRV-Cross reads plain uniforms the same with or without it, and
// HlslGLTest checks the resulting convention, see the header.)
std::vector<std::string> prepareGlobals(CrossCompiler& cross) {
    spvc_compiler c = cross.get();
    std::vector<std::string> members;
    for (const spvc_reflected_resource& r : cross.resources(SPVC_RESOURCE_TYPE_UNIFORM_BUFFER)) {
        spvc_compiler_unset_decoration(c, r.id, SpvDecorationBinding);
        spvc_compiler_unset_decoration(c, r.id, SpvDecorationDescriptorSet);
        if (std::string(r.name) != "$Global") continue;
        spvc_compiler_set_name(c, r.id, kGlobalBlock);
        spvc_compiler_set_name(c, r.base_type_id, kGlobalBlockType);
        spvc_type type = spvc_compiler_get_type_handle(c, r.base_type_id);
        for (unsigned i = 0; i < spvc_type_get_num_member_types(type); ++i) {
            members.push_back(spvc_compiler_get_member_name(c, r.base_type_id, i));
        }
    }
    // A local variable named like a global would capture the global's uses once the block is
    // flattened: give it another name.
    std::set<std::string> taken(members.begin(), members.end());
    for (unsigned id = 1; id < spvc_compiler_get_current_id_bound(c); ++id) {
        const char* name = spvc_compiler_get_name(c, id);
        if (name && taken.count(name)) spvc_compiler_set_name(c, id, (std::string(name) + "_local").c_str());
    }
    for (auto type : {SPVC_RESOURCE_TYPE_SAMPLED_IMAGE, SPVC_RESOURCE_TYPE_SEPARATE_IMAGE}) {
        for (const spvc_reflected_resource& r : cross.resources(type)) {
            spvc_compiler_unset_decoration(c, r.id, SpvDecorationBinding);
            spvc_compiler_unset_decoration(c, r.id, SpvDecorationDescriptorSet);
        }
    }
    return members;
}

// SPIRV-Cross writes the block as `struct rm_hlsl_GlobalBlock { … }; uniform rm_hlsl_GlobalBlock
// rm_hlsl_Global;` (plain-uniform mode) and reads members as `rm_hlsl_Global.name`: turn each
// member into `uniform TYPE name;` and every use into `name`.
std::string flattenGlobals(std::string glsl) {
    const std::string structHead = std::string("struct ") + kGlobalBlockType + "\n{\n";
    size_t start = glsl.find(structHead);
    if (start != std::string::npos) {
        size_t bodyEnd = glsl.find("\n};\n", start);
        std::string body = glsl.substr(start + structHead.size(), bodyEnd - start - structHead.size());
        std::string uniforms;
        size_t from = 0;
        while (from < body.size()) {
            size_t end = body.find('\n', from);
            if (end == std::string::npos) end = body.size();
            std::string line = body.substr(from, end - from);
            line.erase(0, line.find_first_not_of(" \t"));
            if (!line.empty()) uniforms += "uniform " + line + "\n";
            from = end + 1;
        }
        glsl.replace(start, bodyEnd + 4 - start, uniforms);
    }
    const std::string instance = std::string("uniform ") + kGlobalBlockType + " " + kGlobalBlock + ";\n";
    if (size_t at = glsl.find(instance); at != std::string::npos) glsl.erase(at, instance.size());
    const std::string prefix = std::string(kGlobalBlock) + ".";
    for (size_t at = glsl.find(prefix); at != std::string::npos; at = glsl.find(prefix, at)) glsl.erase(at, prefix.size());
    return glsl;
}

// The combined samplers SPIRV-Cross makes of separate textures and samplers (Texture2D +
// SamplerState) are named after the texture, as a sampler2D of that name would be.
void nameCombinedSamplers(CrossCompiler& cross) {
    spvc_compiler c = cross.get();
    spvc_compiler_build_combined_image_samplers(c);
    const spvc_combined_image_sampler* combined = nullptr;
    size_t count = 0;
    spvc_compiler_get_combined_image_samplers(c, &combined, &count);
    for (size_t i = 0; i < count; ++i) {
        spvc_compiler_set_name(c, combined[i].combined_id, spvc_compiler_get_name(c, combined[i].image_id));
    }
}

std::optional<std::string> spirvToGlsl(const std::vector<unsigned>& spirv, ShaderStage stage, std::string& error) {
    CrossCompiler cross(spirv);
    if (!cross.ok()) {
        error = cross.error();
        return std::nullopt;
    }
    renameInterface(cross, stage);
    prepareGlobals(cross);
    nameCombinedSamplers(cross);
    spvc_compiler_options options = nullptr;
    spvc_compiler_create_compiler_options(cross.get(), &options);
    spvc_compiler_options_set_uint(options, SPVC_COMPILER_OPTION_GLSL_VERSION, 450);
    spvc_compiler_options_set_bool(options, SPVC_COMPILER_OPTION_GLSL_ES, SPVC_FALSE);
    spvc_compiler_options_set_bool(options, SPVC_COMPILER_OPTION_GLSL_EMIT_UNIFORM_BUFFER_AS_PLAIN_UNIFORMS, SPVC_TRUE);
    spvc_compiler_options_set_bool(options, SPVC_COMPILER_OPTION_FIXUP_DEPTH_CONVENTION, SPVC_TRUE);
    spvc_compiler_install_compiler_options(cross.get(), options);
    const char* glsl = nullptr;
    if (spvc_compiler_compile(cross.get(), &glsl) != SPVC_SUCCESS) {
        error = cross.error();
        return std::nullopt;
    }
    return flattenGlobals(glsl);
}

}  // namespace

std::string hlslVaryingName(const std::string& semantic) {
    auto [name, index] = splitSemantic(semantic);
    return "rm_hlsl_" + name + std::to_string(index);
}

std::string hlslVertexInputName(VertexUsage usage, int usageIndex) {
    const char* name = "POSITION";
    switch (usage) {
        case VertexUsage::Position: name = "POSITION"; break;
        case VertexUsage::Normal: name = "NORMAL"; break;
        case VertexUsage::TexCoord: name = "TEXCOORD"; break;
        case VertexUsage::Tangent: name = "TANGENT"; break;
        case VertexUsage::Binormal: name = "BINORMAL"; break;
        case VertexUsage::Color: name = "COLOR"; break;
    }
    return std::string("rm_hlsl_in_") + name + std::to_string(usageIndex);
}

std::optional<PreprocessedShader> translateHlsl(const PreprocessedShader& hlsl, const HlslStage& stage,
                                                const SourceLocation& where, const std::string& element,
                                                Diagnostics& diagnostics) {
    if (!checkProfile(stage, where, element, diagnostics)) return std::nullopt;
    initializeGlslangOnce();
    // The preprocessor puts a GLSL #version first; HLSL has none. Blank it, keeping the line count.
    std::string code = hlsl.code;
    if (code.rfind("#version", 0) == 0) code.erase(0, code.find('\n'));

    EShLanguage language = stage.stage == ShaderStage::Vertex ? EShLangVertex : EShLangFragment;
    glslang::TShader shader(language);
    const char* text = code.c_str();
    shader.setStrings(&text, 1);
    std::string entry = stage.entryPoint.empty() ? "main" : stage.entryPoint;
    shader.setEntryPoint(entry.c_str());
    shader.setEnvInput(glslang::EShSourceHlsl, language, glslang::EShClientOpenGL, 100);
    shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    shader.setEnvTargetHlslFunctionality1();  // keeps the semantics in the SPIR-V
    shader.setAutoMapLocations(true);
    shader.setAutoMapBindings(true);
    auto messages = static_cast<EShMessages>(EShMsgReadHlsl | EShMsgHlslDX9Compatible | EShMsgSpvRules);
    glslang::TProgram program;
    bool parsed = shader.parse(GetDefaultResources(), 100, false, messages);
    if (parsed) program.addShader(&shader);
    if (!parsed || !program.link(messages)) {
        std::string log = parsed ? program.getInfoLog() : shader.getInfoLog();
        Diagnostics mapped = mapCompilerLog(log, hlsl, where, element);
        // glslang closes its located errors with an unlocated summary ("HLSL parsing failed").
        if (mapped.size() > 1) {
            std::erase_if(mapped, [](const Diagnostic& d) { return d.message.find("HLSL parsing failed") != std::string::npos; });
        }
        if (mapped.empty()) mapped.push_back({Diagnostic::Severity::Error, where, element, "HLSL failed to compile"});
        diagnostics.insert(diagnostics.end(), mapped.begin(), mapped.end());
        return std::nullopt;
    }
    // glslang only warns when the entry point is missing, and compiles an empty shader.
    if (std::string(program.getInfoLog()).find("Entry point not found") != std::string::npos) {
        diagnostics.push_back({Diagnostic::Severity::Error, where, element,
                               "HLSL entry point '" + entry + "' is not defined in the shader"});
        return std::nullopt;
    }
    std::vector<unsigned> spirv;
    glslang::GlslangToSpv(*program.getIntermediate(language), spirv);

    std::string error;
    std::optional<std::string> glsl = spirvToGlsl(spirv, stage.stage, error);
    if (!glsl) {
        diagnostics.push_back({Diagnostic::Severity::Error, where, element, "HLSL to GLSL translation failed: " + error});
        return std::nullopt;
    }
    PreprocessedShader out;
    out.code = std::move(*glsl);
    out.files = hlsl.files;
    out.lineOrigins.assign(static_cast<size_t>(std::count(out.code.begin(), out.code.end(), '\n')) + 1, where);
    return out;
}

}  // namespace rmfx
