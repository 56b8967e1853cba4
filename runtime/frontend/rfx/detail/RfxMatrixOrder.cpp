#include "frontend/rfx/detail/RfxMatrixOrder.h"

#include <algorithm>

#include <charconv>
#include <cctype>
#include <set>
#include <string_view>
#include <tuple>
#include <utility>

#include "core/IdentifierSearch.h"
#include "frontend/rfx/detail/RfxDeclarations.h"
#include "frontend/rfx/detail/RfxShaderCode.h"
#include "frontend/shader/HlslMulOperands.h"
#include "model/SemanticValues.h"

namespace rmfx::rfx {
namespace {

// The version's order; nullopt when XML_VERSION is missing or unreadable.
std::optional<HlslMatrixOrder> versionOrder(const std::optional<std::string>& version) {
    const std::string_view prefix = "RenderMonkey ";
    if (!version || version->rfind(prefix, 0) != 0) return std::nullopt;
    const char* first = version->data() + prefix.size();
    const char* last = version->data() + version->size();
    int major = 0;
    auto [afterMajor, majorError] = std::from_chars(first, last, major);
    if (majorError != std::errc() || afterMajor >= last || *afterMajor != '.') return std::nullopt;
    // "1.71" is 1.71, so only the first digit after the point orders minor versions.
    const char* digit = afterMajor + 1;
    if (digit >= last || *digit < '0' || *digit > '9') return std::nullopt;
    const int minor = *digit - '0';
    return major < 1 || (major == 1 && minor < 6) ? HlslMatrixOrder::ColumnVector : HlslMatrixOrder::RowVector;
}

// The transforms a semantic matrix applies, as the stages a position goes through (0 world,
// 1 view, 2 projection): first and last. Nullopt for an inverse, a transpose or another semantic.
std::optional<std::pair<int, int>> stages(std::string_view semantic) {
    for (const auto& [name, first, last] : {std::tuple{"World", 0, 0}, {"View", 1, 1}, {"Projection", 2, 2}, {"WorldView", 0, 1},
                                            {"ViewProjection", 1, 2}, {"WorldViewProjection", 0, 2}})
        if (semantic == name) return std::pair{first, last};
    return std::nullopt;
}

const char* spelled(HlslMatrixOrder order) { return order == HlslMatrixOrder::ColumnVector ? "mul(M, v)" : "mul(v, M)"; }

std::string where(const MatrixOrderEvidence::Use& use) { return use.where.file + ":" + std::to_string(use.where.line); }

}  // namespace

MatrixOrderEvidence matrixOrderEvidence(const RfxElement& effect, const VisibleScopes& scopes) {
    MatrixOrderEvidence evidence;
    Diagnostics quiet;  // the pass reader reports what is wrong with the shaders and declarations
    for (const tinyxml2::XMLElement* pass = effect.xml()->FirstChildElement(); pass; pass = pass->NextSiblingElement()) {
        // The pass's own variables first, as the pass reader looks them up.
        Declarations passLevel;
        for (const tinyxml2::XMLElement* x = pass->FirstChildElement(); x; x = x->NextSiblingElement())
            if (std::string_view(x->Name()).find("Variable") != std::string_view::npos) readDeclaration(RfxElement(x, effect.file(), quiet), passLevel);
        auto matrixVariable = [&](const MulOperandVariable& operand) -> const Variable* {
            if (operand.name.empty()) return nullptr;
            const Variable* v = nullptr;
            for (const Variable& own : passLevel.variables)
                if (own.name == operand.name) v = &own;
            if (!v) v = scopes.variable(operand.name);
            return v && v->value.type == ValueType::Mat4 ? v : nullptr;
        };
        for (const tinyxml2::XMLElement* x = pass->FirstChildElement("RmHLSLShader"); x; x = x->NextSiblingElement("RmHLSLShader")) {
            std::optional<RfxShaderCode> code = shaderCodeOf(RfxElement(x, effect.file(), quiet));
            if (!code) continue;
            const std::map<std::string, MulOperandShape> declared = declaredShapes(code->code);
            // Local matrices computed from a semantic one (`float4x4 mtr = mul(matWorld,
            // view_proj_matrix);`): a vector multiplied by such a local says the order as the
            // semantic matrix itself would (rainBow_transp-1 then writes mul(mtr, Pos)).
            std::set<std::string> derived;
            for (const MatrixAssignment& assignment : matrixAssignments(code->code)) {
                // A local is derived when a word of its value (not starting with a digit) names a semantic matrix.
                const std::string_view value = assignment.value;
                for (size_t i = 0; i < value.size();) {
                    if (!isIdentifierChar(value[i])) {
                        ++i;
                        continue;
                    }
                    size_t end = i;
                    while (end < value.size() && isIdentifierChar(value[end])) ++end;
                    const std::string_view word = value.substr(i, end - i);
                    i = end;
                    if (std::isdigit(static_cast<unsigned char>(word[0]))) continue;
                    const Variable* m = matrixVariable({std::string(word), false});
                    if (m && !m->semantic.empty() && findSemantic(m->semantic)) {
                        derived.insert(std::string(assignment.name));
                        break;
                    }
                }
            }
            for (const MulCall& call : mulCalls(code->code)) {
                const MulOperandVariable first = mulOperandVariable(call.first), second = mulOperandVariable(call.second);
                const Variable* a = matrixVariable(first);
                const Variable* b = matrixVariable(second);
                auto note = [&](bool columnVector) {
                    std::pair<int, int>& own = evidence.byShader[x];
                    ++(columnVector ? own.first : own.second);
                    std::optional<MatrixOrderEvidence::Use>& use = columnVector ? evidence.columnVector : evidence.rowVector;
                    if (!use) use = MatrixOrderEvidence::Use{{effect.file(), code->line + call.line - 1}, "mul(" + call.first + ", " + call.second + ")", 0};
                    ++use->count;
                };
                auto span = [](const Variable* m, const MulOperandVariable& operand) -> std::optional<std::pair<int, int>> {
                    std::optional<SemanticInfo> semantic = !m || m->semantic.empty() ? std::nullopt : findSemantic(m->semantic);
                    if (!semantic || operand.transposed) return std::nullopt;
                    return stages(semantic->name);
                };
                const auto left = span(a, first), right = span(b, second);
                // Another matrix known not to project: stored, local, or a semantic before the projection.
                auto beforeProjection = [](const Variable* m, const std::optional<std::pair<int, int>>& stages) {
                    return stages ? stages->second < 2 : !m || m->semantic.empty();
                };
                const bool leftMatrix = a || mulOperandShape(call.first, declared) == MulOperandShape::Matrix;
                const bool rightMatrix = b || mulOperandShape(call.second, declared) == MulOperandShape::Matrix;
                if (leftMatrix && rightMatrix) {
                    // A product of matrices: the one applied later stands on the left in M·v's order
                    // (mul(ViewProjection, World)), on the right in v·M's. Known for two semantic
                    // matrices; and nothing comes after a projection, so one ending in it
                    // (Projection, ViewProjection, WorldViewProjection) stands last whatever the other
                    // is (mul(view_proj_matrix, matWorld) with a stored world matrix).
                    if (left && right && left->first > right->second) note(true);
                    else if (left && right && left->second < right->first) note(false);
                    else if (left && left->second == 2 && beforeProjection(b, right)) note(true);
                    else if (right && right->second == 2 && beforeProjection(a, left)) note(false);
                    continue;
                }
                if (!a && !b) {
                    // A local computed from a semantic matrix, on one side of a vector.
                    const bool leftDerived = derived.count(first.name) > 0, rightDerived = derived.count(second.name) > 0;
                    if (leftDerived != rightDerived &&
                        mulOperandShape(leftDerived ? call.second : call.first, declared) == MulOperandShape::Vector)
                        note(leftDerived);
                    continue;
                }
                // Only a vector on the other side says it: World on the left of a matrix is v·W·VP's
                // order, on the left of a vector M·v's.
                if (mulOperandShape(a ? call.second : call.first, declared) != MulOperandShape::Vector) continue;
                const Variable& m = a ? *a : *b;
                std::optional<SemanticInfo> semantic = m.semantic.empty() ? std::nullopt : findSemantic(m.semantic);
                if (!semantic || semantic->type != UniformType::Mat4) continue;
                bool columnVector = a != nullptr;
                if (std::string_view(semantic->name).ends_with("Transpose") != (a ? first : second).transposed) columnVector = !columnVector;
                note(columnVector);
            }
        }
    }
    return evidence;
}

std::map<const tinyxml2::XMLElement*, HlslMatrixOrder> shaderMatrixOrders(const MatrixOrderEvidence& code) {
    std::map<const tinyxml2::XMLElement*, HlslMatrixOrder> orders;
    for (const auto& [shader, counts] : code.byShader) {
        if ((counts.first > 0) != (counts.second > 0)) {
            orders[shader] = counts.first > 0 ? HlslMatrixOrder::ColumnVector : HlslMatrixOrder::RowVector;
        } else if (counts.first > 0 && (shader->UnsignedAttribute("COMPILER_FLAGS") & kColumnVectorFlag) != 0) {
            // A shader that says both ways round, compiled with the flag RenderMonkey gave the
            // shaders of 1.5 files: mul(M, v), as every such shader that says one way writes.
            orders[shader] = HlslMatrixOrder::ColumnVector;
        }
    }
    return orders;
}

HlslMatrixOrder hlslMatrixOrderOf(const RfxElement& workspace, const MatrixOrderEvidence& code) {
    const std::optional<std::string> version = workspace.text("XML_VERSION", false);
    const std::optional<HlslMatrixOrder> byVersion = versionOrder(version);
    const std::string versionText = version ? "\"" + *version + "\"" : std::string("missing");
    const bool oneShaderSaysBoth = std::any_of(code.byShader.begin(), code.byShader.end(),
                                               [](const auto& shader) { return shader.second.first > 0 && shader.second.second > 0; });
    if (code.columnVector && code.rowVector && !oneShaderSaysBoth) return byVersion.value_or(HlslMatrixOrder::RowVector);
    if (code.columnVector && code.rowVector) {
        const HlslMatrixOrder order = byVersion.value_or(HlslMatrixOrder::RowVector);
        const auto& c = *code.columnVector;
        const auto& r = *code.rowVector;
        workspace.warning("the effect's HLSL multiplies its semantic matrices both ways round (" +
                          c.call + " at " + where(c) + ", " + std::to_string(c.count) + " such; " +
                          r.call + " at " + where(r) + ", " + std::to_string(r.count) +
                          " such): they are passed for " + spelled(order) +
                          (byVersion ? ", as RenderMonkey of XML_VERSION " + versionText + " did"
                                     : ", as RenderMonkey 1.6 and later did (XML_VERSION " + versionText + ")") +
                          " (--rfx-matrices to choose)");
        return order;
    }
    if (code.columnVector || code.rowVector) {
        const HlslMatrixOrder order = code.columnVector ? HlslMatrixOrder::ColumnVector : HlslMatrixOrder::RowVector;
        if (byVersion && *byVersion != order) {
            const auto& use = code.columnVector ? *code.columnVector : *code.rowVector;
            workspace.warning(where(use) + " multiplies " + use.call + " (" +
                              std::to_string(use.count) + " such in the effect), where RenderMonkey of XML_VERSION " + versionText +
                              " passed its semantic matrices for " + spelled(*byVersion) + ": they are passed for " + spelled(order) +
                              ", as the code asks (--rfx-matrices to choose)");
        }
        return order;
    }
    if (byVersion) return *byVersion;
    workspace.warning("XML_VERSION " + versionText + ": HLSL semantic matrices are passed as RenderMonkey 1.6 and later did, for mul(v, M)");
    return HlslMatrixOrder::RowVector;
}

}  // namespace rmfx::rfx
