#include "frontend/shader/HlslTranslator.h"

#include <algorithm>
#include <cstdlib>
#include <cctype>
#include <cstdio>
#include <functional>
#include <map>
#include <sstream>
#include <optional>
#include <vector>

#include "core/IdentifierSearch.h"
#include "frontend/shader/BracketNesting.h"
#include "frontend/shader/HlslBraceElision.h"
#include "frontend/shader/GlslD3D9Pow.h"
#include "frontend/shader/HlslColorOutputs.h"
#include "frontend/shader/HlslConstructorAssignments.h"
#include "frontend/shader/HlslPs1xConstants.h"
#include "frontend/shader/HlslEffectTextures.h"
#include "frontend/shader/HlslSamplerTypes.h"
#include "frontend/shader/HlslWritableGlobals.h"
#include "frontend/shader/GlslFloatLiteral.h"
#include "frontend/shader/HlslGlobalInitializers.h"
#include "frontend/shader/HlslWorker.h"

namespace rmfx {
namespace {

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
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

// Components of a GLSL scalar, vector or float matrix type ("float" 1, "ivec3" 3, "mat3" 9,
// "mat2x3" 6…), 0 for anything else.
int components(const std::string& type) {
    static const std::map<std::string, int> sizes = {
        {"float", 1}, {"vec2", 2},  {"vec3", 3},  {"vec4", 4},  {"int", 1},   {"ivec2", 2}, {"ivec3", 3},
        {"ivec4", 4}, {"uint", 1},  {"uvec2", 2}, {"uvec3", 3}, {"uvec4", 4}, {"bool", 1},  {"bvec2", 2},
        {"bvec3", 3}, {"bvec4", 4}, {"double", 1}, {"mat2", 4}, {"mat3", 9}, {"mat4", 16}, {"mat2x2", 4},
        {"mat2x3", 6}, {"mat2x4", 8}, {"mat3x2", 6}, {"mat3x3", 9}, {"mat3x4", 12}, {"mat4x2", 8}, {"mat4x3", 12},
        {"mat4x4", 16}};
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
        return glslFloatLiteral(value);
    }
    return text;
}

// The GLSL initializer ` = …` of a uniform of `type` (an array when `arraySuffix` is "[N]") from
// the HLSL initial value, or nullopt with `why` when it cannot be one. An HLSL matrix's row i is
// its GLSL matrix's column i (the layout above), so the values, listed row by row in HLSL, fill
// GLSL's constructor column by column in the same order.
// The member types, in order, of the struct `type` as SpirvToGlsl wrote it (`struct Wave\n{\n
// float freq;\n …\n};`); nullopt unless every member is a scalar, vector or float matrix.
std::optional<std::vector<std::string>> structMemberTypes(const std::string& glsl, const std::string& type) {
    const size_t start = glsl.find("struct " + type + "\n{\n");
    if (start == std::string::npos) return std::nullopt;
    const size_t end = glsl.find("\n};", start);
    if (end == std::string::npos) return std::nullopt;
    std::vector<std::string> types;
    std::istringstream body(glsl.substr(start, end - start));
    std::string line;
    std::getline(body, line);  // struct NAME
    std::getline(body, line);  // {
    while (std::getline(body, line)) {
        std::istringstream words(line);
        std::string memberType, member;
        if (!(words >> memberType >> member) || components(memberType) == 0 || member.find('[') != std::string::npos)
            return std::nullopt;
        types.push_back(memberType);
    }
    if (types.empty()) return std::nullopt;
    return types;
}

std::optional<std::string> glslInitializer(const std::string& type, const std::string& arraySuffix,
                                           const HlslGlobalInitializer& init, const std::string& glsl, std::string& why) {
    // A struct (HLSL's `Wave wave[2] = {{1, 1, 0.5, float2(-1, 0)}, …}`): its members' values in
    // declaration order, as the brace list flattens them.
    const std::optional<std::vector<std::string>> members = components(type) == 0 ? structMemberTypes(glsl, type) : std::nullopt;
    int n = components(type);
    if (members)
        for (const std::string& m : *members) n += components(m);
    if (n == 0) {
        why = "rmfx carries over the initial values of scalars, vectors, float matrices, structs of them and arrays of "
              "those only";
        return std::nullopt;
    }
    if (!init.constant) {
        why = "it is not made of numbers";
        return std::nullopt;
    }
    int elements = 1;
    if (!arraySuffix.empty()) {
        // One dimension: "[7]".
        if (arraySuffix.front() != '[' || arraySuffix.back() != ']' || arraySuffix.find('[', 1) != std::string::npos) {
            why = "an array of arrays";
            return std::nullopt;
        }
        elements = std::atoi(arraySuffix.c_str() + 1);
        if (elements < 1) {
            why = "an array of unknown size";
            return std::nullopt;
        }
    }
    const size_t count = init.values.size();
    const size_t wanted = static_cast<size_t>(n) * static_cast<size_t>(elements);
    if (count != wanted && !(count == 1 && arraySuffix.empty())) {
        why = std::to_string(count) + " values for a " + init.declaredType + arraySuffix;
        return std::nullopt;
    }
    auto value = [&](const std::string& valueType, size_t first) {
        const int k = components(valueType);
        if (k == 1) return literal(valueType, init.values[count == 1 ? 0 : first]);
        std::string out = valueType + "(";
        for (int i = 0; i < k; ++i) out += (i ? ", " : "") + literal(valueType, init.values[count == 1 ? 0 : first + static_cast<size_t>(i)]);
        return out + ")";
    };
    auto element = [&](size_t first) {
        if (members) {
            std::string out = type + "(";
            size_t at = first;
            for (size_t m = 0; m < members->size(); ++m) {
                out += (m ? ", " : "") + value((*members)[m], at);
                at += static_cast<size_t>(components((*members)[m]));
            }
            return out + ")";
        }
        return value(type, first);
    };
    if (arraySuffix.empty()) return " = " + element(0);
    std::string out = " = " + type + arraySuffix + "(";
    for (int e = 0; e < elements; ++e) out += (e ? ", " : "") + element(static_cast<size_t>(e) * static_cast<size_t>(n));
    return out + ")";
}

// Turns each uniform block of `spirv` into plain uniforms named after its members (with their
// HLSL initial values, when rmfx can carry them over): `uniform vec4 tint;`, read as `tint`.
// `unsupported` hears of the initial values left behind.
//
// This is the one step that edits SPIRV-Cross's text, and it edits only what it named itself:
// rmfx sets HLSL globals by name through OpenGL's default uniform block, so each member has to
// be a loose uniform, and SPIRV-Cross writes a uniform block only as a block, as one uniform of a
// struct type (EMIT_UNIFORM_BUFFER_AS_PLAIN_UNIFORMS: `struct rm_hlsl_BlockType<k> { … };
// uniform rm_hlsl_BlockType<k> rm_hlsl_Block<k>;`, read as `rm_hlsl_Block<k>.member`) or as a
// vec4 array (spvc_compiler_flatten_buffer_block), none of which keeps the member names GL
// binds. The declarations are written from the reflection (SpirvToGlsl); the text step replaces
// the struct and its instance, found by the names SpirvToGlsl gave them, and drops the
// `rm_hlsl_Block<k>.` before each use.
std::string flattenBlocks(SpirvGlsl spirv, const std::map<std::string, HlslGlobalInitializer>& initial,
                          const std::function<void(const HlslGlobalInitializer&, const std::string& why)>& unsupported) {
    std::string& glsl = spirv.code;
    for (const ReflectedBlock& block : spirv.blocks) {
        std::string uniforms;
        for (const ReflectedVariable& member : block.members) {
            std::string value;
            if (auto it = initial.find(member.name); it != initial.end()) {
                std::string why;
                if (auto v = glslInitializer(member.type, member.arraySuffix, it->second, glsl, why)) value = *v;
                else unsupported(it->second, why);
            }
            uniforms += "uniform " + member.type + " " + member.name + member.arraySuffix + value + ";\n";
        }
        if (size_t start = glsl.find("struct " + block.typeName + "\n"); start != std::string::npos) {
            size_t end = glsl.find("\n};\n", start);
            glsl.replace(start, end + 4 - start, uniforms);
        }
        const std::string instance = "uniform " + block.typeName + " " + block.instanceName + ";\n";
        if (size_t at = glsl.find(instance); at != std::string::npos) glsl.erase(at, instance.size());
        const std::string prefix = block.instanceName + ".";
        for (size_t at = glsl.find(prefix); at != std::string::npos; at = glsl.find(prefix, at)) glsl.erase(at, prefix.size());
    }
    return std::move(glsl);
}

// The declaration `out TYPE NAME;` and the assignment `NAME = vec4Value.xy…;` (for the end or the
// start of main) of a varying fed from a vec4; nullopt unless it is a float scalar or vector.
std::optional<FixedFunctionVaryings> vec4Varying(const ReflectedVariable& varying, const std::string& vec4Value) {
    static const std::map<std::string, std::string> swizzles = {{"float", ".x"}, {"vec2", ".xy"}, {"vec3", ".xyz"}, {"vec4", ""}};
    auto swizzle = swizzles.find(varying.type);
    if (swizzle == swizzles.end() || !varying.arraySuffix.empty()) return std::nullopt;
    return FixedFunctionVaryings{"out " + varying.type + " " + varying.name + ";\n",
                                 "    " + varying.name + " = " + vec4Value + swizzle->second + ";\n"};
}

}  // namespace

Result<FixedFunctionVaryings> hlslFixedFunctionVaryings(const std::vector<ReflectedVariable>& pixelInputs) {
    FixedFunctionVaryings out;
    for (const ReflectedVariable& input : pixelInputs) {
        auto [semantic, index] = splitSemantic(input.semantic);
        std::string value = semantic == "TEXCOORD" ? "vec4(rm_TexCoordIn, 0.0, 1.0)" : semantic == "COLOR" ? "vec4(1.0)" : "";
        std::optional<FixedFunctionVaryings> varying = value.empty() ? std::nullopt : vec4Varying(input, value);
        if (!varying) {
            return Error{"the HLSL pixel shader reads " + input.semantic +
                         ", which a pass without a vertex shader (Direct3D's fixed-function vertex processing) does "
                         "not provide: give the pass a vertex shader"};
        }
        out.declarations += varying->declarations;
        out.assignments += varying->assignments;
    }
    return out;
}

std::vector<std::string> supplyUnwrittenVaryings(std::string& vertexGlsl, const std::vector<ReflectedVariable>& pixelInputs) {
    std::string declarations, assignments;
    std::vector<std::string> supplied;
    for (const ReflectedVariable& input : pixelInputs) {
        if (mentionsIdentifier(vertexGlsl, input.name)) continue;
        const std::string value = splitSemantic(input.semantic).first == "COLOR" ? "vec4(1.0)" : "vec4(0.0, 0.0, 0.0, 1.0)";
        std::optional<FixedFunctionVaryings> varying = vec4Varying(input, value);
        if (!varying) continue;
        declarations += varying->declarations;
        assignments += varying->assignments;
        supplied.push_back(input.semantic);
    }
    const size_t main = vertexGlsl.find("void main()");
    const size_t body = main == std::string::npos ? std::string::npos : vertexGlsl.find('{', main);
    if (supplied.empty() || body == std::string::npos) return {};
    vertexGlsl.insert(body + 1, "\n" + assignments);
    vertexGlsl.insert(main, declarations);
    return supplied;
}

std::vector<std::string> matchVaryingSizes(std::string& vertexGlsl, const std::vector<ReflectedVariable>& pixelInputs) {
    static const std::map<std::string, int> sizes = {{"float", 1}, {"vec2", 2}, {"vec3", 3}, {"vec4", 4}};
    static const char* const swizzles[] = {"", ".x", ".xy", ".xyz"};
    std::vector<std::string> matched;
    std::string assignments;
    for (const ReflectedVariable& input : pixelInputs) {
        auto wanted = sizes.find(input.type);
        if (wanted == sizes.end() || !input.arraySuffix.empty()) continue;
        for (const auto& [type, size] : sizes) {
            const std::string declaration = "out " + type + " " + input.name + ";";
            const size_t at = vertexGlsl.find(declaration);
            if (at == std::string::npos || type == input.type) continue;
            const std::string kept = input.name + "_written";
            // Every use of the output now reads and writes the private variable.
            replaceIdentifier(vertexGlsl, input.name, kept);
            const std::string privateDeclaration = "out " + type + " " + kept + ";";
            const size_t declared = vertexGlsl.find(privateDeclaration);
            if (declared == std::string::npos) break;
            // Interpolation qualifiers before `out` (flat, noperspective, centroid) stay with the output.
            const size_t lineStart = vertexGlsl.rfind('\n', declared) == std::string::npos ? 0 : vertexGlsl.rfind('\n', declared) + 1;
            const std::string qualifiers = vertexGlsl.substr(lineStart, declared - lineStart);
            vertexGlsl.replace(lineStart, declared + privateDeclaration.size() - lineStart,
                               type + " " + kept + ";\n" + qualifiers + "out " + input.type + " " + input.name + ";");
            std::string value;
            if (size > wanted->second) {
                value = kept + swizzles[wanted->second];
            } else {
                value = input.type + "(" + kept;
                for (int c = size; c < wanted->second; ++c) value += c == 3 ? ", 1.0" : ", 0.0";
                value += ")";
            }
            assignments += "    " + input.name + " = " + value + ";\n";
            matched.push_back(input.semantic + " (" + type + " → " + input.type + ")");
            break;
        }
    }
    // SPIRV-Cross writes the vertex shader's outputs in main(), its last function.
    const size_t end = vertexGlsl.rfind('}');
    if (matched.empty() || end == std::string::npos) return {};
    vertexGlsl.insert(end, assignments);
    return matched;
}

Result<HlslTranslation> translateHlslStage(const PreprocessedShader& hlsl, const HlslStage& stage,
                                           const SourceLocation& where, const std::string& element) {
    Diagnostics diagnostics;
    if (!checkProfile(stage, where, element, diagnostics)) return Result<HlslTranslation>::failure(std::move(diagnostics));
    // The preprocessor puts a GLSL #version first; HLSL has none. Blank it, keeping the line count.
    std::string code = hlsl.code;
    if (code.rfind("#version", 0) == 0) code.erase(0, code.find('\n'));
    // What fxc accepted and glslang does not, written out: brace elision, untyped samplers,
    // constructors assigned to, effect-framework textures, writes to globals.
    code = writeOutConstructorAssignments(typeGenericSamplers(nestFlatArrayInitializers(blankEffectTextures(code)))).code;
    std::string entry = stage.entryPoint.empty() ? "main" : stage.entryPoint;
    HlslWritableGlobals writable = giveWrittenGlobalsACopy(code, entry);
    code = std::move(writable.code);
    for (size_t i = 0; i < writable.written.size(); ++i)
        diagnostics.push_back({Diagnostic::Severity::Warning, hlsl.origin(writable.lines[i]), element,
                               "the shader assigns to HLSL global '" + writable.written[i] +
                                   "': Direct3D 9's compiler gave each run of the shader a writable copy of the "
                                   "constant, and so does rmfx"});

    // Debian's glslang crashes on mismatched brackets (BracketNesting.h): reported here, with their line.
    if (std::optional<BracketMismatch> bad = findBracketMismatch(code)) {
        SourceLocation at = hlsl.origin(bad->line);
        diagnostics.push_back({Diagnostic::Severity::Error, at.file.empty() ? where : at, element, bad->message});
        return Result<HlslTranslation>::failure(std::move(diagnostics));
    }
    // In a process of its own: Debian's glslang crashes on some malformed HLSL (core/IsolatedWorker.h).
    Result<GlslangHlslOutcome> isolated = compileHlslInWorker({stage.stage == ShaderStage::Vertex, entry, code});
    if (!isolated) {
        diagnostics.push_back({Diagnostic::Severity::Error, where, element,
                               isolated.error().rfind("glslang ", 0) == 0
                                   ? isolated.error() + " reading this HLSL shader: most likely a syntax error "
                                                        "that Debian's glslang cannot report"
                                   : "cannot compile this HLSL shader: " + isolated.error()});
        return Result<HlslTranslation>::failure(std::move(diagnostics));
    }
    const GlslangHlslOutcome& compiled = *isolated;
    if (compiled.kind == GlslangHlslOutcome::Failed) {
        Diagnostics mapped = mapCompilerLog(compiled.log, hlsl, where, element);
        // glslang closes its located errors with an unlocated summary ("HLSL parsing failed").
        if (mapped.size() > 1) {
            std::erase_if(mapped, [](const Diagnostic& d) { return d.message.find("HLSL parsing failed") != std::string::npos; });
        }
        if (mapped.empty()) mapped.push_back({Diagnostic::Severity::Error, where, element, "HLSL failed to compile"});
        diagnostics.insert(diagnostics.end(), mapped.begin(), mapped.end());
        return Result<HlslTranslation>::failure(std::move(diagnostics));
    }
    if (compiled.kind == GlslangHlslOutcome::NoEntryPoint) {
        diagnostics.push_back({Diagnostic::Severity::Error, where, element,
                               "HLSL entry point '" + entry + "' is not defined in the shader"});
        return Result<HlslTranslation>::failure(std::move(diagnostics));
    }
    const std::vector<unsigned>& spirv = compiled.spirv;

    Result<SpirvGlsl> translated = spirvToGlsl(spirv, stage.stage);
    if (!translated) {
        diagnostics.push_back({Diagnostic::Severity::Error, where, element, "HLSL to GLSL translation failed: " + translated.error()});
        return Result<HlslTranslation>::failure(std::move(diagnostics));
    }
    std::map<std::string, HlslGlobalInitializer> initial;
    for (HlslGlobalInitializer& init : findHlslGlobalInitializers(code)) initial[init.name] = std::move(init);
    auto unsupported = [&](const HlslGlobalInitializer& init, const std::string& why) {
        diagnostics.push_back({Diagnostic::Severity::Warning, hlsl.origin(init.line), element,
                               "the initial value of HLSL global '" + init.name + "' is not carried over (" + why +
                                   "): it starts at 0 unless a variable feeds it"});
    };
    HlslTranslation out;
    out.inputs = std::move(translated->inputs);
    out.glsl.code = flattenBlocks(std::move(*translated), initial, unsupported);
    if (stage.stage == ShaderStage::Vertex) out.glsl.code = clampColorOutputs(std::move(out.glsl.code), stage.profile);
    else out.glsl.code = clampPs1xConstants(std::move(out.glsl.code), stage.profile);
    out.glsl.code = powOfAbsoluteBase(std::move(out.glsl.code));
    out.glsl.files = hlsl.files;
    out.glsl.lineOrigins.assign(static_cast<size_t>(std::count(out.glsl.code.begin(), out.glsl.code.end(), '\n')) + 1, where);
    return {std::move(out), std::move(diagnostics)};
}

}  // namespace rmfx
