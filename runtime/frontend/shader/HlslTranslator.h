#pragma once
// Direct3D 9 HLSL (RenderMonkey's RmHLSLShader) to GLSL 4.50 core: glslang's HLSL front end in
// DX9-compatibility mode compiles one stage to SPIR-V, SPIRV-Cross writes it back as GLSL, and
// the result is shaped so that rmfx runs it like its own shaders:
//
// - Uniforms keep their HLSL names as plain `uniform` declarations (glslang gathers HLSL globals
//   into a `$Global` block; it is flattened), so rmfx binds them by name.
// - `sampler2D s` + `tex2D(s, uv)` become a combined `uniform sampler2D s`.
// - Stage inputs and outputs are named after their semantic (hlslVaryingName), so a vertex shader
//   and a pixel shader translated separately link by name: TEXCOORD1 meets TEXCOORD1.
//   Vertex inputs are named by hlslVertexInputName; POSITION0, NORMAL0 and TEXCOORD0 also get
//   locations 0, 1 and 2, the ones rmfx's meshes feed. Pixel outputs COLORn write location n.
// - A vertex output with semantic POSITION (or SV_Position) is gl_Position, and its z is mapped
//   from Direct3D's clip-space range [0, w] to OpenGL's [-w, w] (z' = 2z - w).
//
// Matrices: rmfx uploads a matrix as 16 floats in its column-major order (column c of the
// mathematical matrix, then the next). HLSL reads those 16 floats as rows: HLSL element M[r][c]
// is rmfx's element at column r, row c. So Direct3D's row-vector idiom `mul(v, M)` computes
// rmfx's `M * v`: a D3D effect's `mul(pos, WorldViewProjection)` works with rmfx's own
// (column-vector) WorldViewProjection, untransposed, as D3DX does with a D3DXMATRIX, whose 16
// floats are the same. `mul(M, v)` computes transpose(M) * v.
//
// Texture origin: Direct3D puts texture coordinate v = 0 at an image's top row; rmfx, like
// OpenGL, puts t = 0 at its bottom row (GlTexture uploads images flipped), and Assimp gives
// meshes lower-left texture coordinates. Coordinates that come from a mesh therefore sample the
// same texel as in Direct3D. Coordinates a shader derives itself with Direct3D's v pointing down
// (from a screen position, say) read the image upside down: the translator flips nothing.

#include <optional>
#include <string>

#include "core/Diagnostic.h"
#include "frontend/shader/ShaderPreprocessor.h"
#include "model/Workspace.h"

namespace rmfx {

struct HlslStage {
    ShaderStage stage = ShaderStage::Fragment;
    std::string entryPoint;  // "main" when empty
    std::string profile;     // "vs_2_0", "ps_3_0"…; empty: not checked
};

// Translates one preprocessed HLSL stage. Errors are reported at the HLSL source's file and line
// (through hlsl.origin) under `element`; returns nullopt when the code does not compile. The
// result's lineOrigins all point at `where` (the generated GLSL has no lines of the user's).
std::optional<PreprocessedShader> translateHlsl(const PreprocessedShader& hlsl, const HlslStage& stage,
                                                const SourceLocation& where, const std::string& element,
                                                Diagnostics& diagnostics);

// For a pass with an HLSL pixel shader and no vertex shader, what Direct3D 9's fixed-function
// vertex processing hands the pixel shader: GLSL 4.50 declarations and assignments, for rmfx's
// built-in vertex shader, of every input of `pixelGlsl` (the translated pixel shader):
// TEXCOORDn the mesh's texture coordinates as (u, v, 0, 1), COLORn opaque white (the material
// colour with lighting off). nullopt, with the semantic in `unsupported`, for any other input.
struct FixedFunctionVaryings {
    std::string declarations;  // `out vec2 rm_hlsl_TEXCOORD0;` …
    std::string assignments;   // statements for the end of main(), reading vec2 rm_TexCoordIn
};
std::optional<FixedFunctionVaryings> hlslFixedFunctionVaryings(const std::string& pixelGlsl, std::string& unsupported);

// "TEXCOORD" → rm_hlsl_TEXCOORD0, "color1" → rm_hlsl_COLOR1: the GLSL name of a varying.
std::string hlslVaryingName(const std::string& semantic);
// The GLSL attribute name of a vertex input with that usage: (TexCoord, 1) → rm_hlsl_in_TEXCOORD1.
std::string hlslVertexInputName(VertexUsage usage, int usageIndex);

}  // namespace rmfx
