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
// Texture origin: a Direct3D effect runs in Direct3D 9's texture space (model/Workspace.h
// TextureSpace): images and render targets hold their top row at v = 0 and the executor turns
// clip-space y over after the vertex shader (ClipSpaceTurnOver), so the translator flips nothing:
// texture coordinates from a mesh or from a shader's own arithmetic mean what they meant in
// Direct3D.

#include <optional>
#include <string>
#include <vector>

#include "core/Diagnostic.h"
#include "core/Result.h"
#include "frontend/shader/HlslSemantics.h"
#include "frontend/shader/ShaderPreprocessor.h"
#include "frontend/shader/SpirvToGlsl.h"
#include "model/Workspace.h"

namespace rmfx {

struct HlslStage {
    ShaderStage stage = ShaderStage::Fragment;
    std::string entryPoint;  // "main" when empty
    std::string profile;     // "vs_2_0", "ps_3_0"…; empty: not checked
};

struct HlslTranslation {
    PreprocessedShader glsl;
    std::vector<ReflectedVariable> inputs;  // the stage inputs with a semantic, from SPIRV-Cross's reflection
};

// Translates one preprocessed HLSL stage. Errors are reported at the HLSL source's file and line
// (through hlsl.origin) under `element`, as are the warnings that come with a translation. The
// result's lineOrigins all point at `where` (the generated GLSL has no lines of the user's).
Result<HlslTranslation> translateHlslStage(const PreprocessedShader& hlsl, const HlslStage& stage,
                                           const SourceLocation& where, const std::string& element);

// For a pass with an HLSL pixel shader and no vertex shader, what Direct3D 9's fixed-function
// vertex processing hands the pixel shader: GLSL 4.50 declarations and assignments, for rmfx's
// built-in vertex shader, of every input of the translated pixel shader (its
// HlslTranslation::inputs): TEXCOORDn the mesh's texture coordinates as (u, v, 0, 1), COLORn
// opaque white (the material colour with lighting off). Fails, saying which semantic, for any
// other input (or one that is not a float scalar or vector).
struct FixedFunctionVaryings {
    std::string declarations;  // `out vec2 rm_hlsl_TEXCOORD0;` …
    std::string assignments;   // statements for the end of main(), reading vec2 rm_TexCoordIn
};
Result<FixedFunctionVaryings> hlslFixedFunctionVaryings(const std::vector<ReflectedVariable>& pixelInputs);

// For a pass whose HLSL vertex shader does not write an input its pixel shader declares
// (RenderMonkey's own template passes `float4 inDiffuse : COLOR0` to a pixel shader whose vertex
// shader writes only TEXCOORD0): Direct3D 9 ran it, GL does not link it. Adds each missing output
// to the translated vertex shader, written at the start of its main() with a defined value:
// COLORn opaque white, any other semantic (0, 0, 0, 1) cut to the input's size. Returns the
// semantics supplied, for a warning; none when nothing is missing.
std::vector<std::string> supplyUnwrittenVaryings(std::string& vertexGlsl, const std::vector<ReflectedVariable>& pixelInputs);

// For a varying the two HLSL stages declare with different sizes (the vertex shader writes
// `float Depth : TEXCOORD2`, the pixel shader reads `float4 … : TEXCOORD2`): Direct3D 9 matched
// them by register, GL's link refuses the types. The vertex shader's value is kept in a private
// variable and the output, of the pixel shader's type, is set from it at the end of main(): cut
// to the size read, or filled with 0 (and 1 in w). Returns "SEMANTIC (vertex type → pixel type)"
// for each, for a warning.
std::vector<std::string> matchVaryingSizes(std::string& vertexGlsl, const std::vector<ReflectedVariable>& pixelInputs);

}  // namespace rmfx
