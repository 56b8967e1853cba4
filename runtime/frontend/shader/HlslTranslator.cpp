#include "frontend/shader/HlslTranslator.h"

#include "frontend/shader/HlslGlobalInitializers.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <functional>
#include <map>
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

// The uniform blocks glslang makes of the HLSL globals ($Global) and of each cbuffer are renamed
// rm_hlsl_Block<k> (type rm_hlsl_BlockType<k>) and flattened: their members become plain uniforms.
std::string blockName(size_t k) { return "rm_hlsl_Block" + std::to_string(k); }
std::string blockTypeName(size_t k) { return "rm_hlsl_BlockType" + std::to_string(k); }

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

// Names the uniform blocks glslang made of the HLSL globals and cbuffers so flattenBlocks can find
// them, and drops the bindings plain uniforms cannot have. Returns how many blocks there are. (The
// blocks' matrices carry RowMajor; SPIRV-Cross reads plain uniforms the same with or without it,
// and HlslGLTest checks the resulting convention, see the header.)
size_t prepareBlocks(CrossCompiler& cross) {
    spvc_compiler c = cross.get();
    std::set<std::string> members;
    size_t blocks = 0;
    for (const spvc_reflected_resource& r : cross.resources(SPVC_RESOURCE_TYPE_UNIFORM_BUFFER)) {
        spvc_compiler_unset_decoration(c, r.id, SpvDecorationBinding);
        spvc_compiler_unset_decoration(c, r.id, SpvDecorationDescriptorSet);
        spvc_compiler_set_name(c, r.id, blockName(blocks).c_str());
        spvc_compiler_set_name(c, r.base_type_id, blockTypeName(blocks).c_str());
        spvc_type type = spvc_compiler_get_type_handle(c, r.base_type_id);
        for (unsigned i = 0; i < spvc_type_get_num_member_types(type); ++i)
            members.insert(spvc_compiler_get_member_name(c, r.base_type_id, i));
        ++blocks;
    }
    // A local variable named like a global would capture the global's uses once the blocks are
    // flattened: give it another name.
    for (unsigned id = 1; id < spvc_compiler_get_current_id_bound(c); ++id) {
        const char* name = spvc_compiler_get_name(c, id);
        if (name && members.count(name)) spvc_compiler_set_name(c, id, (std::string(name) + "_local").c_str());
    }
    for (auto type : {SPVC_RESOURCE_TYPE_SAMPLED_IMAGE, SPVC_RESOURCE_TYPE_SEPARATE_IMAGE}) {
        for (const spvc_reflected_resource& r : cross.resources(type)) {
            spvc_compiler_unset_decoration(c, r.id, SpvDecorationBinding);
            spvc_compiler_unset_decoration(c, r.id, SpvDecorationDescriptorSet);
        }
    }
    return blocks;
}

// The lines of a text, without their '\n'.
std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> out;
    size_t from = 0;
    while (from < text.size()) {
        size_t end = text.find('\n', from);
        if (end == std::string::npos) end = text.size();
        out.push_back(text.substr(from, end - from));
        from = end + 1;
    }
    return out;
}

// Components of a GLSL scalar or vector type ("float" 1, "ivec3" 3…), 0 for anything else.
int components(const std::string& type) {
    static const std::map<std::string, int> sizes = {
        {"float", 1}, {"vec2", 2},  {"vec3", 3},  {"vec4", 4},  {"int", 1},   {"ivec2", 2}, {"ivec3", 3},
        {"ivec4", 4}, {"uint", 1},  {"uvec2", 2}, {"uvec3", 3}, {"uvec4", 4}, {"bool", 1},  {"bvec2", 2},
        {"bvec3", 3}, {"bvec4", 4}, {"double", 1}};
    auto it = sizes.find(type);
    return it == sizes.end() ? 0 : it->second;
}

// One component as a GLSL literal of the type's kind.
std::string literal(const std::string& type, double value) {
    char text[40];
    if (type[0] == 'b') return value != 0.0 ? "true" : "false";  // bool, bvecN
    if (type[0] == 'i') {
        std::snprintf(text, sizeof text, "%lld", static_cast<long long>(std::clamp(value, -2147483648.0, 2147483647.0)));
    } else if (type[0] == 'u') {
        std::snprintf(text, sizeof text, "%lluu", static_cast<unsigned long long>(std::clamp(value, 0.0, 4294967295.0)));
    } else {
        std::snprintf(text, sizeof text, "%.9g", value);
        std::string s = text;
        if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
        return s;
    }
    return text;
}

// The GLSL initializer ` = …` of a uniform of `type` from the HLSL initial value, or nullopt with
// `why` when it cannot be one.
std::optional<std::string> glslInitializer(const std::string& type, const HlslGlobalInitializer& init, std::string& why) {
    const int n = components(type);
    if (n == 0 || init.array) {
        why = "rmfx carries over the initial values of scalars and vectors only";
        return std::nullopt;
    }
    if (!init.constant) {
        why = "it is not a list of numbers";
        return std::nullopt;
    }
    const size_t count = init.values.size();
    if (count != 1 && count != static_cast<size_t>(n)) {
        why = std::to_string(count) + " values for a " + init.declaredType;
        return std::nullopt;
    }
    if (n == 1) return " = " + literal(type, init.values[0]);
    std::string out = " = " + type + "(";
    for (int i = 0; i < n; ++i) out += (i ? ", " : "") + literal(type, init.values[count == 1 ? 0 : i]);
    return out + ")";
}

// SPIRV-Cross writes each block as `struct rm_hlsl_BlockType<k> { … }; uniform rm_hlsl_BlockType<k>
// rm_hlsl_Block<k>;` (plain-uniform mode) and reads members as `rm_hlsl_Block<k>.name`: turn each
// member into `uniform TYPE name;` (with its HLSL initial value, when it has one rmfx can carry
// over) and every use into `name`. `unsupported` hears of the initial values left behind.
std::string flattenBlocks(std::string glsl, size_t blocks, const std::map<std::string, HlslGlobalInitializer>& initial,
                          const std::function<void(const HlslGlobalInitializer&, const std::string& why)>& unsupported) {
    for (size_t k = 0; k < blocks; ++k) {
        const std::string structHead = "struct " + blockTypeName(k) + "\n{\n";
        size_t start = glsl.find(structHead);
        if (start != std::string::npos) {
            size_t bodyEnd = glsl.find("\n};\n", start);
            std::string body = glsl.substr(start + structHead.size(), bodyEnd - start - structHead.size());
            std::string uniforms;
            for (std::string line : splitLines(body)) {
                line.erase(0, line.find_first_not_of(" \t"));
                if (line.empty()) continue;
                // "vec4 Tint;", "layout(row_major) mat4 M;", "vec4 List[4];"
                std::string declaration = line.substr(0, line.find_last_not_of("; ") + 1);
                size_t nameStart = declaration.find_last_of(" \t") + 1;
                std::string name = declaration.substr(nameStart, declaration.find('[', nameStart) - nameStart);
                std::string type = declaration.substr(0, nameStart);  // "layout(row_major) mat4 "
                type.erase(type.find_last_not_of(" \t") + 1);
                if (size_t space = type.find_last_of(" \t"); space != std::string::npos) type.erase(0, space + 1);
                std::string value;
                if (auto it = initial.find(name); it != initial.end()) {
                    std::string why;
                    if (auto v = glslInitializer(type, it->second, why)) value = *v;
                    else unsupported(it->second, why);
                }
                uniforms += "uniform " + declaration + value + ";\n";
            }
            glsl.replace(start, bodyEnd + 4 - start, uniforms);
        }
        const std::string instance = "uniform " + blockTypeName(k) + " " + blockName(k) + ";\n";
        if (size_t at = glsl.find(instance); at != std::string::npos) glsl.erase(at, instance.size());
        const std::string prefix = blockName(k) + ".";
        for (size_t at = glsl.find(prefix); at != std::string::npos; at = glsl.find(prefix, at)) glsl.erase(at, prefix.size());
    }
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

struct Translated {
    std::string glsl;
    size_t blocks = 0;
};

std::optional<Translated> spirvToGlsl(const std::vector<unsigned>& spirv, ShaderStage stage, std::string& error) {
    CrossCompiler cross(spirv);
    if (!cross.ok()) {
        error = cross.error();
        return std::nullopt;
    }
    renameInterface(cross, stage);
    const size_t blocks = prepareBlocks(cross);
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
    return Translated{glsl, blocks};
}

}  // namespace

std::optional<FixedFunctionVaryings> hlslFixedFunctionVaryings(const std::string& pixelGlsl, std::string& unsupported) {
    static const std::map<std::string, std::string> swizzles = {{"float", ".x"}, {"vec2", ".xy"}, {"vec3", ".xyz"}, {"vec4", ""}};
    FixedFunctionVaryings out;
    const std::string prefix = "rm_hlsl_";
    for (const std::string& line : splitLines(pixelGlsl)) {
        // "in vec2 rm_hlsl_TEXCOORD0;", maybe with qualifiers first ("flat in float …")
        if (line.empty() || line.back() != ';') continue;
        std::vector<std::string> words;
        for (size_t i = 0; i + 1 < line.size();) {
            size_t j = line.find(' ', i);
            if (j == std::string::npos || j > line.size() - 1) j = line.size() - 1;
            if (j > i) words.push_back(line.substr(i, j - i));
            i = j + 1;
        }
        if (words.size() < 3 || words.back().rfind(prefix, 0) != 0 ||
            std::find(words.begin(), words.end() - 2, "in") == words.end() - 2)
            continue;
        const std::string type = words[words.size() - 2], name = words.back();
        auto [semantic, index] = splitSemantic(name.substr(prefix.size()));
        auto swizzle = swizzles.find(type);
        std::string value = semantic == "TEXCOORD" ? "vec4(rm_TexCoordIn, 0.0, 1.0)" : semantic == "COLOR" ? "vec4(1.0)" : "";
        if (value.empty() || swizzle == swizzles.end()) {
            unsupported = semantic + std::to_string(index);
            return std::nullopt;
        }
        out.declarations += "out " + type + " " + name + ";\n";
        out.assignments += "    " + name + " = " + value + swizzle->second + ";\n";
    }
    return out;
}

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
    std::optional<Translated> translated = spirvToGlsl(spirv, stage.stage, error);
    if (!translated) {
        diagnostics.push_back({Diagnostic::Severity::Error, where, element, "HLSL to GLSL translation failed: " + error});
        return std::nullopt;
    }
    std::map<std::string, HlslGlobalInitializer> initial;
    for (HlslGlobalInitializer& init : findHlslGlobalInitializers(code)) initial[init.name] = std::move(init);
    auto unsupported = [&](const HlslGlobalInitializer& init, const std::string& why) {
        diagnostics.push_back({Diagnostic::Severity::Warning, hlsl.origin(init.line), element,
                               "the initial value of HLSL global '" + init.name + "' is not carried over (" + why +
                                   "): it starts at 0 unless a variable feeds it"});
    };
    PreprocessedShader out;
    out.code = flattenBlocks(std::move(translated->glsl), translated->blocks, initial, unsupported);
    out.files = hlsl.files;
    out.lineOrigins.assign(static_cast<size_t>(std::count(out.code.begin(), out.code.end(), '\n')) + 1, where);
    return out;
}

}  // namespace rmfx
