#pragma once
// Which way round a RenderMonkey effect's HLSL multiplies its semantic matrices (World,
// ViewProjection…, which rmfx fills). First from the code: a mul() with such a matrix on one side
// and a vector on the other (a constructor, a member or swizzle, or a variable declared as a
// vector) says it, mul(M, v) for OpenGL's layout (M·v) and mul(v, M) for D3DX's (a matrix whose
// semantic ends in Transpose, or inside transpose(), counts the other way). A product of matrices
// says it by their order where the order of the transforms is known: the one applied later
// (ViewProjection after World) stands on the left in M·v's order, mul(ViewProjection, World), and
// on the right in v·M's; that is known for two semantic matrices, and for one ending in the
// projection (nothing comes after it) against any other matrix (inverses and transposes say
// nothing there). Otherwise a product says nothing: a stored World stands on the left in v·W·VP
// and on the right in P·V·W·v. Where the code says nothing, or says both, the version that saved the file decides
// (RmEffectWorkspace XML_VERSION="RenderMonkey 1.5"): up to 1.5 RenderMonkey passed matrices in
// OpenGL's layout, so its HLSL wrote mul(view_proj_matrix, Pos); from 1.6 on it passed them as
// D3DX does, and its template wrote mul(Input.Position, matViewProjection). Of the public files
// tried, one saved by 1.71 writes mul(g_matViewProj, v) (docs/rendermonkey.md, "Matrices").

#include <map>
#include <optional>
#include <string>
#include <utility>

#include "frontend/rfx/detail/RfxElement.h"
#include "frontend/rfx/detail/RfxPassReader.h"
#include "model/Workspace.h"

namespace rmfx::rfx {

// What an effect's HLSL shaders say: the first mul() of each order, and how many there are.
struct MatrixOrderEvidence {
    struct Use {
        SourceLocation where;  // the line of the mul in the file
        std::string call;      // as written: "mul(g_matViewProj, float4(modPos, 1))"
        int count = 0;         // uses of this order
    };
    std::optional<Use> columnVector, rowVector;  // mul(M, v); mul(v, M)
    // Each <RmHLSLShader>'s own count of each order (mul(M, v), mul(v, M)).
    std::map<const tinyxml2::XMLElement*, std::pair<int, int>> byShader;
};

// From the <RmHLSLShader> code of the effect's passes, the matrices looked up among each pass's own
// variables, then in `scopes`.
MatrixOrderEvidence matrixOrderEvidence(const RfxElement& effect, const VisibleScopes& scopes);

// The code's order where it says one, else the version's (ColumnVector before 1.6, RowVector for
// later ones, and for a missing or unreadable XML_VERSION, with a warning). A warning names the
// line where the code goes against the version, or where it says both.
HlslMatrixOrder hlslMatrixOrderOf(const RfxElement& workspace, const MatrixOrderEvidence& code);

// The shaders whose own code multiplies their semantic matrices one way round only: each is passed
// them for that order, whatever the rest of the effect does. RenderMonkey compiled a shader with
// its own flags (COMPILER_FLAGS), and files upgraded from 1.5 keep such shaders, writing
// mul(M, v), beside new ones writing mul(v, M) (MY_PROJ/PLANET/atMOS_PassMethod_03.rfx).
// A shader whose code says both ways round gets mul(M, v) when RenderMonkey compiled it with
// COMPILER_FLAGS bit 32: in the public files every shader with that flag whose code says one way
// writes mul(M, v) (over 200 of them; none writes only mul(v, M)), and every shader without it,
// mul(v, M).
std::map<const tinyxml2::XMLElement*, HlslMatrixOrder> shaderMatrixOrders(const MatrixOrderEvidence& code);
inline constexpr unsigned kColumnVectorFlag = 32;

}  // namespace rmfx::rfx
