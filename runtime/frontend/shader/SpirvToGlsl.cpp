#include "frontend/shader/SpirvToGlsl.h"

#include <map>
#include <optional>
#include <regex>
#include <set>

#include <spirv_cross/spirv_cross_c.h>

#include "core/IdentifierSearch.h"
#include "frontend/shader/HlslSemantics.h"

namespace rmfx {
namespace {

// One compiler over one SPIR-V module, owned by its context.
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
    std::string name(spvc_variable_id id) const {
        const char* s = spvc_compiler_get_name(compiler_, id);
        return s ? s : "";
    }

private:
    spvc_context context_ = nullptr;
    spvc_compiler compiler_ = nullptr;
    spvc_resources resources_ = nullptr;
    bool ok_ = false;
};

// The GLSL spelling of a scalar, vector or matrix type ("vec2", "ivec3", "mat4", "mat2x3"), or a
// struct's name; empty for a type the translation does not expect in an interface or a block.
std::string glslTypeName(spvc_compiler c, spvc_type_id id) {
    spvc_type type = spvc_compiler_get_type_handle(c, id);
    const char* prefix = nullptr;
    const char* scalar = nullptr;
    switch (spvc_type_get_basetype(type)) {
        case SPVC_BASETYPE_STRUCT: {
            const char* name = spvc_compiler_get_name(c, spvc_type_get_base_type_id(type));
            return name ? name : "";
        }
        case SPVC_BASETYPE_FP32: prefix = "", scalar = "float"; break;
        case SPVC_BASETYPE_FP64: prefix = "d", scalar = "double"; break;
        case SPVC_BASETYPE_INT32: prefix = "i", scalar = "int"; break;
        case SPVC_BASETYPE_UINT32: prefix = "u", scalar = "uint"; break;
        case SPVC_BASETYPE_BOOLEAN: prefix = "b", scalar = "bool"; break;
        default: return "";
    }
    const unsigned rows = spvc_type_get_vector_size(type), columns = spvc_type_get_columns(type);
    if (columns > 1) {
        std::string size = columns == rows ? std::to_string(columns) : std::to_string(columns) + "x" + std::to_string(rows);
        return std::string(prefix) + "mat" + size;
    }
    return rows > 1 ? std::string(prefix) + "vec" + std::to_string(rows) : scalar;
}

// "[4]", "[2][3]": SPIRV-Cross lists the dimensions innermost first.
std::string arraySuffix(spvc_compiler c, spvc_type_id id) {
    spvc_type type = spvc_compiler_get_type_handle(c, id);
    std::string out;
    for (unsigned i = spvc_type_get_num_array_dimensions(type); i-- > 0;)
        out += "[" + std::to_string(spvc_type_get_array_dimension(type, i)) + "]";
    return out;
}

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

// Names the uniform blocks glslang made of the HLSL globals and cbuffers rm_hlsl_Block<k> (type
// rm_hlsl_BlockType<k>), and drops the bindings plain uniforms cannot have. (The blocks' matrices
// carry RowMajor; SPIRV-Cross reads plain uniforms the same with or without it, and HlslGLTest
// checks the resulting convention, see HlslTranslator.h.) Returns the blocks' type ids.
std::vector<spvc_type_id> prepareBlocks(CrossCompiler& cross) {
    spvc_compiler c = cross.get();
    std::set<std::string> members;
    std::vector<spvc_type_id> blocks;
    for (const spvc_reflected_resource& r : cross.resources(SPVC_RESOURCE_TYPE_UNIFORM_BUFFER)) {
        const std::string k = std::to_string(blocks.size());
        spvc_compiler_unset_decoration(c, r.id, SpvDecorationBinding);
        spvc_compiler_unset_decoration(c, r.id, SpvDecorationDescriptorSet);
        spvc_compiler_set_name(c, r.id, ("rm_hlsl_Block" + k).c_str());
        spvc_compiler_set_name(c, r.base_type_id, ("rm_hlsl_BlockType" + k).c_str());
        spvc_type type = spvc_compiler_get_type_handle(c, r.base_type_id);
        for (unsigned i = 0; i < spvc_type_get_num_member_types(type); ++i)
            members.insert(spvc_compiler_get_member_name(c, r.base_type_id, i));
        blocks.push_back(r.base_type_id);
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

// The samplers' names before compiling: SPIRV-Cross prefixes '_' to names on its list of GLSL
// words (a sampler called `noise`, common in RenderMonkey effects, becomes `_noise`), and rmfx
// binds a sampler by its HLSL name.
std::map<spvc_variable_id, std::string> samplerNames(const CrossCompiler& cross) {
    std::map<spvc_variable_id, std::string> names;
    for (const spvc_reflected_resource& r : cross.resources(SPVC_RESOURCE_TYPE_SAMPLED_IMAGE)) names[r.id] = cross.name(r.id);
    const spvc_combined_image_sampler* combined = nullptr;
    size_t count = 0;
    spvc_compiler_get_combined_image_samplers(cross.get(), &combined, &count);
    for (size_t i = 0; i < count; ++i) names[combined[i].combined_id] = cross.name(combined[i].combined_id);
    return names;
}

// Whether GLSL 4.50 takes `name` as a sampler's name in code that SPIRV-Cross wrote: not a
// keyword, and not a built-in function such code calls (a sampler named `texture` would hide it).
bool usableSamplerName(const std::string& name) {
    static const std::set<std::string> taken = {
        "attribute", "const", "uniform", "varying", "buffer", "shared", "coherent", "volatile", "restrict", "readonly",
        "writeonly", "layout", "centroid", "flat", "smooth", "noperspective", "patch", "sample", "break", "continue",
        "do", "for", "while", "switch", "case", "default", "if", "else", "subroutine", "in", "out", "inout", "float",
        "double", "int", "void", "bool", "true", "false", "invariant", "precise", "discard", "return", "struct",
        "common", "partition", "active", "asm", "class", "union", "enum", "typedef", "template", "this", "resource",
        "goto", "inline", "noinline", "public", "static", "extern", "external", "interface", "long", "short", "half",
        "fixed", "unsigned", "superp", "input", "output", "filter", "sizeof", "cast", "namespace", "using", "lowp",
        "mediump", "highp", "precision", "main", "texture", "textureLod", "textureProj", "textureProjLod", "textureGrad",
        "textureOffset", "textureLodOffset", "textureGradOffset", "textureSize", "textureQueryLod", "textureQueryLevels",
        "texelFetch", "texelFetchOffset", "textureGather", "textureGatherOffset", "textureGatherOffsets",
        "textureProjOffset", "textureProjLodOffset", "textureProjGrad", "textureProjGradOffset", "textureSamples"};
    return !name.empty() && !taken.count(name) && name.rfind("gl_", 0) != 0;
}

// Read after compiling: SPIRV-Cross renames identifiers GLSL reserves while it compiles.
ReflectedBlock reflectBlock(spvc_compiler c, spvc_type_id blockType) {
    ReflectedBlock block;
    block.typeName = spvc_compiler_get_name(c, blockType);
    block.instanceName = "rm_hlsl_Block" + block.typeName.substr(std::string("rm_hlsl_BlockType").size());
    spvc_type type = spvc_compiler_get_type_handle(c, blockType);
    for (unsigned i = 0; i < spvc_type_get_num_member_types(type); ++i) {
        spvc_type_id member = spvc_type_get_member_type(type, i);
        block.members.push_back({spvc_compiler_get_member_name(c, blockType, i), glslTypeName(c, member), arraySuffix(c, member), ""});
    }
    return block;
}

// A pixel shader's VPOS and VFACE inputs: their declarations become definitions of what the
// rasterizer gives (pixelSystemValue), so they are not varyings for a vertex shader to write.
void defineSystemValueInputs(const CrossCompiler& cross, ShaderStage stage, std::string& code) {
    if (stage != ShaderStage::Fragment) return;
    for (const spvc_reflected_resource& r : cross.resources(SPVC_RESOURCE_TYPE_STAGE_INPUT)) {
        const std::string type = glslTypeName(cross.get(), r.type_id);
        const std::optional<std::string> value = pixelSystemValue(cross.semantic(r.id), type);
        if (!value) continue;
        const std::string name = cross.name(r.id);
        const std::regex declaration("(^|\n)(layout\\([^)]*\\)\\s*)?in " + type + " " + name + ";");
        code = std::regex_replace(code, declaration, "$1#define " + name + " " + *value);
    }
}

std::vector<ReflectedVariable> reflectInputs(const CrossCompiler& cross, ShaderStage stage) {
    std::vector<ReflectedVariable> inputs;
    for (const spvc_reflected_resource& r : cross.resources(SPVC_RESOURCE_TYPE_STAGE_INPUT)) {
        std::string semantic = cross.semantic(r.id);
        if (semantic.empty()) continue;
        if (stage == ShaderStage::Fragment && pixelSystemValue(semantic, glslTypeName(cross.get(), r.type_id))) continue;
        auto [name, index] = splitSemantic(semantic);
        inputs.push_back({cross.name(r.id), glslTypeName(cross.get(), r.type_id), arraySuffix(cross.get(), r.type_id),
                          name + std::to_string(index)});
    }
    return inputs;
}

}  // namespace

Result<SpirvGlsl> spirvToGlsl(const std::vector<unsigned>& spirv, ShaderStage stage) {
    CrossCompiler cross(spirv);
    if (!cross.ok()) return Error{cross.error()};
    renameInterface(cross, stage);
    const std::vector<spvc_type_id> blocks = prepareBlocks(cross);
    nameCombinedSamplers(cross);
    const std::map<spvc_variable_id, std::string> samplersBefore = samplerNames(cross);
    spvc_compiler_options options = nullptr;
    spvc_compiler_create_compiler_options(cross.get(), &options);
    spvc_compiler_options_set_uint(options, SPVC_COMPILER_OPTION_GLSL_VERSION, 450);
    spvc_compiler_options_set_bool(options, SPVC_COMPILER_OPTION_GLSL_ES, SPVC_FALSE);
    spvc_compiler_options_set_bool(options, SPVC_COMPILER_OPTION_GLSL_EMIT_UNIFORM_BUFFER_AS_PLAIN_UNIFORMS, SPVC_TRUE);
    spvc_compiler_options_set_bool(options, SPVC_COMPILER_OPTION_FIXUP_DEPTH_CONVENTION, SPVC_TRUE);
    spvc_compiler_install_compiler_options(cross.get(), options);
    const char* glsl = nullptr;
    if (spvc_compiler_compile(cross.get(), &glsl) != SPVC_SUCCESS) return Error{cross.error()};
    SpirvGlsl out;
    out.code = glsl;
    for (const auto& [id, before] : samplerNames(cross))
        if (auto original = samplersBefore.find(id); original != samplersBefore.end() && original->second != before &&
                                                     usableSamplerName(original->second))
            replaceIdentifier(out.code, before, original->second);
    for (spvc_type_id block : blocks) out.blocks.push_back(reflectBlock(cross.get(), block));
    defineSystemValueInputs(cross, stage, out.code);
    out.inputs = reflectInputs(cross, stage);
    return out;
}

}  // namespace rmfx
