#pragma once
// The in-memory workspace: what every front end (the XML format, a RenderMonkey importer)
// produces and what validation, the pass graph and the GL executor consume. Plain data:
// no GL, no file access. Every object remembers where it was declared.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/Diagnostic.h"
#include "core/Value.h"
#include "model/GlProfile.h"
#include "model/Image.h"
#include "model/Mesh.h"

namespace rmfx {

enum class WidgetHint { Auto, Slider, Drag, Color, Checkbox, Combo };

struct Variable {
    std::string name;
    Value value;  // the default, as written in the file
    // A value the runtime fills every frame, by RenderMonkey's VARIABLE_SEMANTIC name
    // ("ViewProjection", "Time0_X", "ViewportWidth"…); empty: the variable holds `value`.
    std::string semantic;
    bool editable = true;  // shown as a tweakable (RenderMonkey's ARTIST_EDITABLE)
    std::optional<float> min, max, step;
    WidgetHint widget = WidgetHint::Auto;
    std::vector<std::string> options;  // labels of a combo: value i selects options[i]
    bool hdr = false;                  // colour values may exceed 1
    std::string description;
    SourceLocation where;
};

enum class ColorSpace { Linear, Srgb };
enum class TextureKind { Texture2D, Cube, Volume };  // Volume: a 3D texture (sampler3D)
// The workspace element that declares one: "texture", "cubemap" or "volume".
inline const char* textureElementName(TextureKind kind) {
    return kind == TextureKind::Cube ? "cubemap" : kind == TextureKind::Volume ? "volume" : "texture";
}
// FromImage: one image whose shape says its layout, 2:1 equirect or a 4:3 / 3:4 cross (rmfx render --texture).
enum class CubeLayout { Faces, Cross, Equirect, FromImage };

struct Texture {
    std::string name;
    TextureKind kind = TextureKind::Texture2D;
    CubeLayout layout = CubeLayout::Faces;   // cube maps only
    std::vector<std::string> files;          // one, or six faces (+x -x +y -y +z -z) for CubeLayout::Faces
    std::vector<SourceLocation> fileLocations;  // where each file was named
    ColorSpace colorSpace = ColorSpace::Linear;
    bool mipmaps = true;
    int faceSize = 0;  // equirect → cube face size; 0: image height / 2
    // read-when="VARIABLE=VALUE": the passes sample this texture only while the variable has that
    // value (a shader's own branch, which rmfx cannot see); a --texture given for it otherwise is
    // said to have no effect, naming the setting that would give it one. Empty: always read.
    std::string readWhenVariable;
    std::string readWhenValue;
    // An <input>'s texture has no files: its image is supplied at run time (rmfx render --input),
    // decoded to linear RGBA at the size it is used at.
    std::shared_ptr<const Image> supplied;
    SourceLocation where;
};

// An image from outside the workspace (rmfx render --input [NAME=]FILE): a 2D texture of the same
// name holds it. With `replaces`, the image stands in for that target: when it is given, the
// passes that write the target before the first pass sampling the input are culled; when it is
// not, the passes sampling the input are, and the workspace draws the target itself. Without
// `replaces`, the texture's file (<input file>) is used when no image is given; with no file
// either, the image is required.
struct ImageInput {
    std::string name;
    std::string replaces;  // a render target; empty: none
    bool sizesViewport = false;  // a given image sets the viewport's size (default: when it replaces a target)
    std::string description;
    SourceLocation where;
};

enum class TargetFormat { RGBA8, RGBA16F, RGBA32F, R16F, R32F, RG16F, RG32F, RGBA16, R11G11B10F, RGB10A2, R8, RG8, RG16 };

struct TargetSize {
    bool relative = true;
    double scaleX = 1.0, scaleY = 1.0;  // relative: fraction of the viewport
    int width = 0, height = 0;          // absolute
};

struct RenderTarget {
    std::string name;
    TargetFormat format = TargetFormat::RGBA16F;  // with formatVariable: formats[0]
    // format-by: the int variable whose value i picks formats[i] (the format follows an encoding
    // chosen by a variable or --set); empty: the format is fixed.
    std::string formatVariable;
    std::vector<TargetFormat> formats;
    TargetSize size;  // with scaleVariable: scales[0]
    // scale-by: the int variable whose value i picks scales[i] (a downsample factor chosen by a
    // variable or --set); empty: the size is fixed.
    std::string scaleVariable;
    std::vector<TargetSize> scales;
    bool mipmaps = false;
    glm::vec4 initial{0.0f};  // contents before the first frame writes it (seen by frame="previous")
    SourceLocation where;
};

enum class Filter { Nearest, Linear };
enum class MipmapMode { None, Nearest, Linear };
enum class Wrap { Repeat, Clamp, Mirror, Border };

struct Sampler {
    std::string uniform;      // the sampler uniform in the pass's shaders
    std::string texture;      // a texture name, or
    std::string target;       // a render-target name
    bool previousFrame = false;  // read the target as the previous frame left it
    Filter filter = Filter::Linear;
    MipmapMode mipmap = MipmapMode::None;
    Wrap wrapS = Wrap::Clamp, wrapT = Wrap::Clamp, wrapR = Wrap::Clamp;  // R: volume textures' third axis
    glm::vec4 border{0.0f};
    SourceLocation where;
};

enum class ShaderStage { Vertex, Fragment };

// The language a shader is written in. rmfx's own workspaces use Glsl; the others come from
// RenderMonkey (.rfx) imports.
enum class ShaderDialect {
    Glsl,        // GLSL 4.50 core; "#version 450 core" is put first when the code has no #version
    GlslLegacy,  // desktop GLSL 1.10/1.20 with compatibility built-ins (gl_Vertex, ftransform(),
                 // gl_ModelViewProjectionMatrix, gl_LightSource…); runs in a compatibility-profile
                 // context; no #version is added
    GlslEs100,   // GLSL ES 1.00 (precision qualifiers, attribute/varying), run as "#version 100"
    Hlsl,        // Direct3D 9 HLSL, compiled through glslang's HLSL front end (entryPoint, profile)
};

// How an HLSL shader multiplies the matrices rmfx computes for semantics (World, ViewProjection…),
// which are OpenGL's column-vector matrices. Direct3D code wrote either order, and what worked
// depended on how the application passed the matrix.
enum class HlslMatrixOrder {
    RowVector,     // mul(v, M): D3DX's convention, and RenderMonkey's from version 1.6 on
    ColumnVector,  // mul(M, v): RenderMonkey 1.5 and before, and every assembly shader (m4x4)
};
// "row-vector", "column-vector": the workspace's <shader matrices> and rmfx's --rfx-matrices.
const char* hlslMatrixOrderName(HlslMatrixOrder order);
std::optional<HlslMatrixOrder> parseHlslMatrixOrder(std::string_view name);

// Shader code kept in the workspace file itself, which `#include "NAME"` finds before any file.
struct CodeSnippet {
    std::string name;
    std::string code;
    int codeLine = 0;  // line of the workspace file where the code starts
    SourceLocation where;
};

struct ShaderSource {
    ShaderStage stage = ShaderStage::Fragment;
    ShaderDialect dialect = ShaderDialect::Glsl;
    std::string entryPoint;  // Hlsl: the function to compile ("main" when empty)
    std::string profile;     // Hlsl: the D3D target it was written for ("vs_2_0", "ps_2_0"…)
    HlslMatrixOrder matrixOrder = HlslMatrixOrder::RowVector;  // Hlsl: of its semantic matrices
    std::string file;    // relative to the workspace folder; empty for inline code
    std::string code;    // inline code (CDATA or text)
    int codeLine = 0;    // line of the workspace file where inline code starts
    // Direct3D (an .rfx RmHLSLShader): the constants its compiled code kept, as RenderMonkey listed
    // them (RmShaderConstant); a constant only dead code reads is not among them. Empty: unknown.
    std::vector<std::string> constantTable;
    SourceLocation where;
};

enum class BlendFactor {
    Zero, One, SrcColor, OneMinusSrcColor, DstColor, OneMinusDstColor,
    SrcAlpha, OneMinusSrcAlpha, DstAlpha, OneMinusDstAlpha, ConstantColor, OneMinusConstantColor, SrcAlphaSaturate
};
enum class BlendOp { Add, Subtract, ReverseSubtract, Min, Max };

struct BlendState {
    bool enabled = false;
    BlendFactor srcColor = BlendFactor::One, dstColor = BlendFactor::Zero;
    BlendFactor srcAlpha = BlendFactor::One, dstAlpha = BlendFactor::Zero;
    BlendOp colorOp = BlendOp::Add, alphaOp = BlendOp::Add;
    glm::vec4 constant{0.0f};
};

enum class CompareFunc { Never, Less, Equal, LessEqual, Greater, NotEqual, GreaterEqual, Always };

struct DepthState {
    bool test = false;
    bool write = false;
    CompareFunc func = CompareFunc::Less;
};

enum class CullFace { None, Back, Front };

enum class PolygonMode { Fill, Line, Point };

struct RasterState {
    CullFace cull = CullFace::None;
    bool frontCounterClockwise = true;
    // How front- and back-facing polygons are drawn (glPolygonMode): filled, as outlines (the
    // silhouette effects that draw back faces as thick lines) or as points. A core-profile
    // workspace draws both faces one way.
    PolygonMode frontMode = PolygonMode::Fill, backMode = PolygonMode::Fill;
    float lineWidth = 1.0f;  // of lines and outlines, in pixels
    SourceLocation polygonModeWhere;  // the element that set the modes, for errors
};

struct ClearState {
    std::optional<glm::vec4> color;
    std::optional<float> depth;
};

struct DrawCall {
    std::optional<BuiltinMesh> mesh;  // a built-in mesh, or
    std::string file;                 // a model file relative to the workspace folder
    glm::vec3 translate{0.0f};
    glm::vec3 rotateDegrees{0.0f};    // applied X, then Y, then Z
    glm::vec3 scale{1.0f};
    // The built-in mesh stands in for a model file that was not found (io/media's stock models
    // and placeholders): an imported effect sizes it to its camera (frontend/rfx/RfxCameraFraming)
    // by scaling its vertex positions, as the model file's own coordinates would be, since
    // RenderMonkey's shaders often apply no World matrix.
    bool standIn = false;
    float meshScale = 1.0f;
    glm::vec3 meshOffset{0.0f};  // added to the vertex positions after meshScale
    // The stand-in has the measured size of the RenderMonkey stock model it stands for
    // (io/mesh/StockModels), which the file's shaders and camera were made for: not sized to the camera.
    bool stockSize = false;
    std::string standsInFor;  // the missing file's reference as the workspace wrote it
    // Its texture coordinates' u turned round (1 - u), as the stock model has them (Sphere.3ds's u
    // runs from +z through -x, the built-in sphere's through +x).
    bool mirrorU = false;
    SourceLocation where;
};

// Which mesh data feeds which vertex attribute of a pass (RenderMonkey's RmStreamMap).
enum class VertexUsage { Position, Normal, TexCoord, Tangent, Binormal, Color };

struct VertexStream {
    VertexUsage usage = VertexUsage::Position;
    int usageIndex = 0;     // TEXCOORD1 → 1
    std::string attribute;  // the attribute it feeds (rm_Vertex, a_position…); empty: the
                            // compatibility built-in (gl_Vertex, gl_Normal, gl_MultiTexCoordN, gl_Color)
    // From a stream map every pass shares (RenderMonkey's RmStreamMap): a pass whose shaders do
    // not read it is normal, and not warned about.
    bool shared = false;
    SourceLocation where;
};

// Direct3D 9's fixed-function pixel fog (D3DRS_FOGTABLEMODE), which blends a ps_1_x or ps_2_x
// pixel shader's colour toward the fog colour by the pixel's depth d (its eye-space w):
// factor f = (end − d) / (end − start), exp(−density·d) or exp(−(density·d)²), clamped to [0, 1];
// colour = f·shader + (1 − f)·fog. Imported Direct3D passes only; ps_3_0 shaders fog themselves.
enum class FogMode { Linear, Exp, Exp2 };

struct FixedFunctionFog {
    bool enabled = false;                 // D3DRS_FOGENABLE
    std::optional<FogMode> mode;          // D3DRS_FOGTABLEMODE; none: no pixel fog
    bool vertexFog = false;               // D3DRS_FOGVERTEXMODE set (not applied: see the importer)
    float start = 0.0f, end = 1.0f, density = 1.0f;  // Direct3D's defaults
    glm::vec3 color{0.0f};
    SourceLocation where;  // the D3DRS_FOGENABLE state
    bool applies() const { return enabled && mode.has_value(); }
};

// Direct3D 9's alpha test (D3DRS_ALPHATESTENABLE, ALPHAFUNC, ALPHAREF): a pixel whose colour-0
// alpha fails `alpha FUNC ref` is discarded. Imported Direct3D passes only.
struct AlphaTest {
    bool enabled = false;
    CompareFunc func = CompareFunc::Always;  // Direct3D's default
    float ref = 0.0f;                        // ALPHAREF / 255
};

struct Pass {
    std::string name;
    std::string target;  // empty: the output
    bool enabled = true;
    ClearState clear;
    BlendState blend;
    DepthState depth;
    RasterState raster;
    FixedFunctionFog fog;
    AlphaTest alphaTest;
    std::vector<ShaderSource> shaders;  // at most one per stage; no vertex shader: the built-in one
    std::vector<Sampler> samplers;
    std::vector<Variable> constants;    // pass-local values, shadowing workspace variables
    DrawCall draw;                      // default: the full-screen triangle
    std::string camera;                 // a NamedCamera; empty: the workspace's camera
    SourceLocation cameraWhere;
    // Empty: rmfx's layout (locations 0 position, 1 normal, 2 texcoord). Else these streams,
    // by attribute name or compatibility built-in.
    std::vector<VertexStream> streams;
    SourceLocation where;
};

// A named group of passes that a scene asks for or leaves out (<effect>). Shaders see
// RMFX_EFFECT_<name>: false when the effect is left out, else true, or a uniform bool that follows
// its switch variables when it has any.
struct Effect {
    std::string name;
    std::vector<std::string> passes;
    // Variables that switch it off at run time: it runs while any of them is true or non-zero.
    std::vector<std::string> switches;
    // What makes it contribute (<effect source="bright" source-channels="rgb">): when no pixel of
    // this target, written before the effect by passes outside it, holds a non-zero value in
    // these channels, the effect's passes give zero everywhere, so they are skipped on the GPU and
    // the targets they hand to later passes are cleared to zero. Empty: always run.
    std::string source;
    glm::bvec4 sourceChannels{true, true, true, false};
    // A cheaper test of the same (<effect source="bright" gate="glare_gate" gate-channels="r">): a
    // target written before the source that is zero in these channels everywhere only where the
    // source will be. Content skip then counts the gate's pixels instead of the source's, so the
    // passes that write the source are skipped with the effect when only the effects read them.
    // Empty: the source is counted.
    std::string gate;
    glm::bvec4 gateChannels{true, true, true, false};
    std::string description;
    SourceLocation where;

    bool hasPass(std::string_view passName) const;
};

struct Output {
    std::string target;  // empty: the implicit target named "output"
    // The effects this workspace asks for (<output effects="…">); nullopt: every declared effect.
    std::optional<std::vector<std::string>> effects;
    TargetFormat format = TargetFormat::RGBA16F;  // of the implicit target
    DisplayTransform transform = DisplayTransform::Srgb;
    SourceLocation where;
};

// The matrices a camera gives (View, Projection and every semantic made from them).
enum class CameraConvention {
    OpenGL,    // right-handed view looking down -z, clip depth -w…w (gluLookAt, gluPerspective)
    // Left-handed view looking down +z, clip depth 0…w (D3DXMatrixLookAtLH, PerspectiveFovLH):
    // what RenderMonkey gave Direct3D effects, whose shaders may rely on view-space z growing away
    // from the eye. For one eye, target and up the picture is OpenGL's mirrored left to right.
    Direct3D,
};

struct OrbitCameraSettings {
    glm::vec3 target{0.0f};
    float distance = 4.0f;
    float yawDegrees = 30.0f;     // about +Y, 0 looks down -Z
    float pitchDegrees = 15.0f;   // above the horizon
    float fovYDegrees = 60.0f;
    float nearPlane = 0.05f, farPlane = 100.0f;
    // About the viewing direction: positive turns the camera's up from +Y's direction toward its
    // right (the picture turns the other way).
    float rollDegrees = 0.0f;
    CameraConvention convention = CameraConvention::OpenGL;
    SourceLocation where;
};

// A fixed camera a pass may look through instead of the workspace's (<camera name="…">,
// RenderMonkey's RmCameraReference): a light's view for a shadow map, a second viewpoint.
struct NamedCamera {
    std::string name;
    OrbitCameraSettings settings;
};

// Which way up images and render targets are and where pixel centres lie: the convention of the
// API an effect was written for, which its shaders' arithmetic assumes.
enum class TextureSpace {
    // OpenGL: texture coordinate t = 0 at an image's bottom row, window y up, pixel centres at
    // half-integers. rmfx's own workspaces and RenderMonkey's OpenGL effects.
    OpenGL,
    // Direct3D 9: v = 0 at an image's and a render target's top row, window y down, pixel centres
    // at whole numbers (D3D9's half-pixel offset) and VPOS the pixel's whole-number position.
    // RenderMonkey's Direct3D effects.
    Direct3D9,
    // Direct3D 10 and later: as Direct3D 9 with pixel centres at half-integers (ReShade FX).
    Direct3D10,
};
// "opengl", "direct3d9", "direct3d10": the workspace's texture-space attribute.
const char* textureSpaceName(TextureSpace space);
std::optional<TextureSpace> parseTextureSpace(std::string_view name);
// Direct3D's spaces: the passes draw with clip-space y turned over (and the winding with it), so
// that an image's top row, uploaded first, is at v = 0 and a target's row 0 is its top row.
inline bool rowsTopFirst(TextureSpace space) { return space != TextureSpace::OpenGL; }

struct Workspace {
    GlProfile profile = GlProfile::Core;
    TextureSpace textureSpace = TextureSpace::OpenGL;
    std::filesystem::path path;  // the file it came from ("<built-in>" for embedded text)
    std::filesystem::path folder;  // shader, texture and model paths are relative to it
    std::filesystem::path includeRoot;  // #include may not leave it; empty: `folder` (see includeFolder)
    SourceLocation includeRootWhere;    // where includeRoot was declared
    std::string name;
    std::string description;
    int width = 512, height = 512;  // default viewport size
    std::vector<Variable> variables;
    std::vector<CodeSnippet> snippets;
    std::vector<Texture> textures;
    std::vector<ImageInput> inputs;  // each with a texture of its name in `textures`
    std::vector<RenderTarget> targets;
    std::vector<Pass> passes;  // run in this order
    std::vector<Effect> effects;
    Output output;
    OrbitCameraSettings camera;
    std::vector<NamedCamera> cameras;  // the named ones passes may look through

    const NamedCamera* findCamera(const std::string& name) const {
        for (const NamedCamera& c : cameras)
            if (c.name == name) return &c;
        return nullptr;
    }

    static constexpr const char* implicitOutputName = "output";

    const Variable* findVariable(std::string_view name) const;
    Variable* findVariable(std::string_view name);
    const Texture* findTexture(std::string_view name) const;
    Texture* findTexture(std::string_view name);
    const ImageInput* findInput(std::string_view name) const;
    const RenderTarget* findTarget(std::string_view name) const;
    const Pass* findPass(std::string_view name) const;
    const Effect* findEffect(std::string_view name) const;
    const Effect* effectOfPass(std::string_view passName) const;  // null: the pass belongs to no effect
    // The name of the target the output comes from: output.target or the implicit one.
    std::string outputTargetName() const;
    // The target a pass writes, resolved: "" → the output target.
    std::string passTargetName(const Pass& pass) const;
    // Whether GlExecutor::readTarget can read `name`: a declared target or the output.
    bool canReadTarget(std::string_view name) const;
    // For messages about a target that is not there: "it has: a, b; the output is 'output'".
    std::string describeTargets() const;

    // The folder #include may not leave: the workspace folder, or the ancestor <workspace include-root> names.
    const std::filesystem::path& includeFolder() const { return includeRoot.empty() ? folder : includeRoot; }
};

const char* targetFormatName(TargetFormat format);
std::optional<TargetFormat> targetFormatFromName(std::string_view name);
int targetFormatBytesPerPixel(TargetFormat format);
// The format a target is allocated with when its format variable (if any) has `value`; nullopt
// when the value picks none of its formats.
std::optional<TargetFormat> selectTargetFormat(const RenderTarget& target, const Value* value);
// "variable 'V' = 7 picks none of the 6 formats of target 'T'": why selectTargetFormat gave none.
std::string formatChoiceError(const RenderTarget& target, const Value* value);

// The size a target is allocated with when its scale variable (if any) has `value`; nullopt when
// the value picks none of its scales.
std::optional<TargetSize> selectTargetSize(const RenderTarget& target, const Value* value);
// "variable 'V' = 7 picks none of the 3 scales of target 'T'": why selectTargetSize gave none.
std::string scaleChoiceError(const RenderTarget& target, const Value* value);

// Viewport-relative sizes round up, never below 1: ceil(viewport × scale), so a chain of
// half-size targets covers every source pixel (5 → 3 → 2 → 1).
glm::ivec2 resolveTargetSize(const TargetSize& size, glm::ivec2 viewport);

}  // namespace rmfx
