// RenderMonkey effects that draw a model, rendered headless and compared pixel by pixel with a
// float64 ray cast of the same model (tests/reference/MeshRayCast.h): the camera, the
// fixed-function matrices and light, the vertex streams, depth testing, samplers and the effect's
// own maths, each worked out here from the file's values and docs/rendermonkey.md's defaults.
//
// RfxModelRenderGLTest runs tests/rfx/lit_teapot.rfx (written for it). PublicRfxGLTest runs public
// RenderMonkey files that cannot be kept in this repository: set RMFX_PUBLIC_RFX_DIR to a folder
// holding them (docs/rendermonkey.md says where they come from); without it those tests are skipped.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/common.hpp>
#include <glm/mat3x3.hpp>
#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "io/mesh/BuiltinMeshes.h"
#include "io/mesh/StockModels.h"
#include "reference/CameraRays.h"
#include "reference/RayCastImage.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/ModelFiles.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::test {
namespace {

// docs/rendermonkey.md: light 0 is directional from the camera, position (0, 0, 1, 0) in eye space,
// diffuse (1, 1, 1); the front material's diffuse is (0.8, 0.8, 0.8); gl_Color is white.
const glm::dvec3 kLightPositionEye(0.0, 0.0, 1.0);
const glm::dvec3 kLightDiffuse(1.0);
const glm::dvec3 kMaterialDiffuse(0.8);

std::unique_ptr<Workspace> loadRfxWithMedia(const std::filesystem::path& file, const std::filesystem::path& media) {
    WorkspaceLoadOptions load;
    load.media.searchPath = {media};
    Result<Workspace> loaded = loadWorkspace(file, {}, load);
    if (!loaded.ok()) {
        ADD_FAILURE() << formatAll(loaded.diagnostics());
        return nullptr;
    }
    EXPECT_EQ(loaded->profile, GlProfile::Compatibility) << file;
    return std::make_unique<Workspace>(std::move(*loaded));
}

// An 8-bit image file whose texel (i, j) (j from the bottom) is texel(i, j) / 255; returned as the
// float64 image the texture holds.
RefImage writeTexture(const std::filesystem::path& file, int width, int height,
                      const std::function<glm::ivec4(int i, int j)>& texel) {
    Image image;
    image.width = width, image.height = height, image.channels = 4;
    image.pixels.resize(size_t(width) * height * 4);
    RefImage held(width, height);
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            glm::ivec4 v = texel(i, j);
            for (int c = 0; c < 4; ++c) image.at(i, height - 1 - j, c) = float(v[c] / 255.0);
            held.at(i, j) = glm::dvec4(v) / 255.0;
        }
    auto written = writeImage(file, image);
    EXPECT_TRUE(written) << (written ? "" : written.error());
    return held;
}

// A sphere about the origin, counter-clockwise seen from outside, its texture coordinates spread
// over [uvMin, uvMax] (u around from −z, v from the south pole up): the seam where u jumps back
// faces −z, away from a camera on the +z side (rmfx's default camera is).
Mesh uvSphere(double radius, int segments, int rings, glm::dvec2 uvMin, glm::dvec2 uvMax) {
    Mesh mesh;
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s <= segments; ++s) {
            const double u = double(s) / segments, v = double(r) / rings;
            const double phi = 2.0 * std::numbers::pi * u + std::numbers::pi, theta = std::numbers::pi * (1.0 - v);
            const glm::dvec3 n(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
            mesh.positions.emplace_back(n * radius);
            mesh.normals.emplace_back(n);
            mesh.texcoords.emplace_back(uvMin + (uvMax - uvMin) * glm::dvec2(u, v));
        }
    auto index = [&](int r, int s) { return static_cast<uint32_t>(r * (segments + 1) + s); };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const uint32_t a = index(r, s), b = index(r, s + 1), c = index(r + 1, s + 1), d = index(r + 1, s);
            if (r > 0) mesh.indices.insert(mesh.indices.end(), {a, b, c});
            if (r < rings - 1) mesh.indices.insert(mesh.indices.end(), {a, c, d});
        }
    return mesh;
}

glm::dmat3 normalMatrix(const glm::dmat4& modelView) { return glm::transpose(glm::inverse(glm::dmat3(modelView))); }

// The range of `shade(texel)` when the texel filtered from an 8-bit texture comes back rounded to
// 8 bits, as a GPU may (llvmpipe filters 8-bit textures in 8-bit fixed point): every rgb channel
// of the texel one step down, unchanged or one step up; each result clamped to [0, 1] as the
// 8-bit output keeps it.
ExpectedRange overTexelRounding(glm::dvec4 texel, const std::function<glm::dvec4(glm::dvec4)>& shade) {
    ExpectedRange range(glm::dvec4(std::numeric_limits<double>::infinity()),
                        glm::dvec4(-std::numeric_limits<double>::infinity()));
    for (int dr = -1; dr <= 1; ++dr)
        for (int dg = -1; dg <= 1; ++dg)
            for (int db = -1; db <= 1; ++db) {
                glm::dvec4 v = shade(texel + glm::dvec4(dr, dg, db, 0) * kUnorm8Step);
                v = glm::clamp(v, 0.0, 1.0);
                range.lower = glm::min(range.lower, v);
                range.upper = glm::max(range.upper, v);
            }
    return range;
}

// Renders a model effect at the cast's size and compares it with the cast shaded by `shade`, on
// the clear colour, opaque black.
struct ModelCheck {
    const MeshRayCast& cast;
    SurfaceShading shade;
    int minComparedPixels;
    SurfaceFilter comparable = {};
};

void renderAndCompare(std::unique_ptr<Workspace> ws, const ModelCheck& check) {
    ASSERT_TRUE(ws);
    GlRun run = runWorkspace(std::move(ws), RunSettings{check.cast.size()});
    ASSERT_TRUE(run.exec);
    RefImage image = readRef(run, run.ws->outputTargetName());
    RayCastImage reference = rayCastImage(check.cast, check.shade, glm::dvec4(0.0, 0.0, 0.0, 1.0), check.comparable);
    EXPECT_GE(reference.comparedSurfacePixels, check.minComparedPixels)
        << "too few pixels of the model to compare (" << reference.surfacePixels << " on the surface)";
    // The 8-bit output's conversion, and float arithmetic on the GPU.
    const double tolerance = kUnorm8Conversion + 1e-4;
    RayCastDifference d = worstExcess(image, reference);
    expectWithin("max distance outside the float64 ray cast's range", d.worst, tolerance);
    if (d.worst > tolerance) ADD_FAILURE() << d.describe(image, reference);
}

// Texture coordinates jump where two faces meet (each face of a box spans its box's range): only
// pixels whose centre and corners see one face (two triangles in a row) are compared.
SurfaceFilter onOneFace(const MeshRayCast& cast) {
    return [&cast](const SurfaceHit& hit, int i, int j) {
        for (double dx : {-0.35, 0.35})
            for (double dy : {-0.35, 0.35}) {
                const std::optional<SurfaceHit> corner = cast.at(cast.centre(i, j).x + dx, cast.centre(i, j).y + dy);
                if (!corner || corner->triangle / 2 != hit.triangle / 2) return false;
            }
        return true;
    };
}

class RfxModelRenderGLTest : public CompatibilityGlTest {};

TEST_F(RfxModelRenderGLTest, LitTeapotMatchesAFloat64RayCastOfTheModel) {
    ScratchDir media;
    // Ramp.png, 128 x 1: r = 2i, g = 254 - 2i, b = 60.
    RefImage ramp = writeTexture(media / "Ramp.png", 128, 1, [](int i, int) { return glm::ivec4(2 * i, 254 - 2 * i, 60, 255); });
    auto ws = loadRfxWithMedia(sourceDir() / "tests" / "rfx" / "lit_teapot.rfx", media.path());
    ASSERT_TRUE(ws);

    // The RmCamera "Side": position, look-at and up as given, FOV 50° (vertical), clip planes 8 and 1600.
    const int size = 128;
    const glm::dmat4 view = glm::lookAt(glm::dvec3(128.0, 80.0, 160.0), glm::dvec3(0.0, 24.0, 0.0), glm::dvec3(0, 1, 0));
    const glm::dmat4 projection = glm::perspective(50.0 * std::numbers::pi / 180.0, 1.0, 8.0, 1600.0);
    const glm::dmat3 normals = normalMatrix(view);
    const glm::dvec3 paint(0.9, 0.6, 0.3);
    const double rimPower = 3.0;
    // The stand-in for the missing Teapot.3ds, at the stock teapot's size (its own test:
    // MediaResolver.MissingStockModelsStandInAtTheirMeasuredSize).
    Mesh teapot = makeMesh(BuiltinMesh::Teapot);
    const MeshPlacement placement = stockModelPlacement(*findStockModel("Teapot"));
    for (glm::vec3& p : teapot.positions) p = p * placement.scale + placement.offset;

    auto shade = [&](const SurfaceHit& hit) {
        const glm::dvec3 n = glm::normalize(normals * hit.normal);
        const glm::dvec3 toEye = glm::normalize(-glm::dvec3(view * glm::dvec4(hit.position, 1.0)));
        const glm::dvec3 toLight = glm::normalize(kLightPositionEye);
        const double diffuse = std::max(glm::dot(n, toLight), 0.0);
        const double rim = std::pow(1.0 - std::abs(glm::dot(n, toEye)), rimPower);
        const glm::dvec4 band = sampleBilinear(ramp, {diffuse, 0.5});  // GL_LINEAR, clamp to edge
        return overTexelRounding(band, [&](glm::dvec4 texel) {
            return glm::dvec4(glm::dvec3(texel) * paint * kMaterialDiffuse * kLightDiffuse + glm::dvec3(0.25 * rim), 1.0);
        });
    };
    const MeshRayCast cast(teapot, glm::dmat4(1.0), view, projection, {size, size});
    renderAndCompare(std::move(ws), {cast, shade, 2000});
}

// An OpenGL effect drawing FILE_NAME through an RmCamera, back faces culled, coloured by its
// texture coordinates: (u, v, 0.5).
std::string texcoordEffect(const std::string& modelFile) {
    return lines({
        R"(<?xml version="1.0" encoding="UTF-8" standalone="yes"?>)",
        "<RENDER_MONKEY>",
        R"( <RmEffectWorkspace NAME="Tests" API="" ACTIVE_EFFECT="Tests.Model" VALIDATION_STRING="" XML_VERSION="RenderMonkey 1.71">)",
        R"(  <RmModelData NAME="Shape" API="" FILE_NAME="C:\Media\Models\)" + modelFile + R"(" ORIENTATION="0"/>)",
        R"(  <RmOpenGLEffect NAME="Model" API="OpenGL" ACTIVE_CAMERA="Side">)",
        R"(   <RmCamera NAME="Side" API="" CAMERA_POSITION_X="1.6" CAMERA_POSITION_Y="1.2" CAMERA_POSITION_Z="2.0" LOOK_AT_VECTOR_X="0.3" LOOK_AT_VECTOR_Y="0.2" LOOK_AT_VECTOR_Z="0.1" UP_VECTOR_X="0.0" UP_VECTOR_Y="1.0" UP_VECTOR_Z="0.0" FOV="40.0" NEAR_CLIP_PLANE="0.1" FAR_CLIP_PLANE="20.0"/>)",
        R"(   <RmGLPass NAME="Shade" API="OpenGL" PASS_INDEX="0" ENABLED="TRUE">)",
        R"(    <RmModelReference NAME="Shape" API=""/>)",
        R"(    <RmRenderStateBlock NAME="Render State Block" API="OpenGL">)",
        R"(     <RmState NAME="GL_CullMode" API="OpenGL" STATE="8" VALUE="3" USAGE="RENDER_STATE"/>)",
        R"(    </RmRenderStateBlock>)",
        R"(    <RmGLShader NAME="Vertex Program" API="OpenGL" PIXEL_SHADER="FALSE"><RmShaderCode TYPE="TEXT"><![CDATA[)",
        "void main(void) { gl_Position = ftransform(); gl_TexCoord[0] = gl_MultiTexCoord0; }]]></RmShaderCode></RmGLShader>",
        R"(    <RmGLShader NAME="Fragment Program" API="OpenGL" PIXEL_SHADER="TRUE"><RmShaderCode TYPE="TEXT"><![CDATA[)",
        "void main(void) { gl_FragColor = vec4(gl_TexCoord[0].xy, 0.5, 1.0); }]]></RmShaderCode></RmGLShader>",
        "   </RmGLPass>",
        "  </RmOpenGLEffect>",
        " </RmEffectWorkspace>",
        "</RENDER_MONKEY>",
    });
}

// Docs: RenderMonkey drew a model file's own coordinates. Assimp's 3DS importer stands the model
// up from Z up to Y up and its .x importer mirrors z, flips v and reverses the winding; a model
// that is asymmetric along every axis, with back faces culled and coloured by its texture
// coordinates, shows each of those as a different picture.
TEST_F(RfxModelRenderGLTest, ModelFilesDrawWithTheirOwnCoordinatesTexcoordsAndWinding) {
    const Mesh boxes = asymmetricBoxes();
    const int size = 96;
    const glm::dmat4 view = glm::lookAt(glm::dvec3(1.6, 1.2, 2.0), glm::dvec3(0.3, 0.2, 0.1), glm::dvec3(0, 1, 0));
    const glm::dmat4 projection = glm::perspective(40.0 * std::numbers::pi / 180.0, 1.0, 0.1, 20.0);
    const MeshRayCast cast(boxes, glm::dmat4(1.0), view, projection, {size, size});
    auto shade = [](const SurfaceHit& hit) { return ExpectedRange(glm::dvec4(hit.texcoord, 0.5, 1.0)); };
    const SurfaceFilter oneFace = onOneFace(cast);
    for (const std::string model : {"Shape.3ds", "Shape.x", "Shape.obj"}) {
        SCOPED_TRACE(model);
        ScratchDir media;
        if (model.ends_with(".3ds")) write3ds(media / model, boxes);
        if (model.ends_with(".x")) writeDirectX(media / model, boxes);
        if (model.ends_with(".obj")) writeObj(media / model, boxes);
        const std::filesystem::path file = media.write("model.rfx", texcoordEffect(model));
        renderAndCompare(loadRfxWithMedia(file, media.path()), {cast, shade, 1000, oneFace});
    }
}

// A Direct3D effect saved by RenderMonkey `version` drawing FILE_NAME through an RmCamera with
// World, View and Projection chained in the shader (the tutorial pattern), depth-tested, coloured
// by its texture coordinates: (u, v, 0.5).
std::string direct3dTexcoordEffect(const std::string& modelFile, const std::string& version) {
    const bool columnVector = version == "RenderMonkey 1.5";
    const std::string transform = columnVector ? "o.Pos = mul(matProjection, mul(matView, mul(matWorld, Pos)));"
                                               : "o.Pos = mul(mul(mul(Pos, matWorld), matView), matProjection);";
    auto matrix = [](const std::string& name, const std::string& semantic) {
        std::string text = R"(   <RmMatrixVariable NAME=")" + name + R"(" API="" ARTIST_EDITABLE="FALSE" VARIABLE_SEMANTIC=")" + semantic + "\"";
        for (int i = 0; i < 16; ++i) text += " VALUE_" + std::to_string(i) + "=\"" + (i % 5 == 0 ? "1" : "0") + "\"";
        return text + "/>";
    };
    return lines({
        R"(<?xml version="1.0" encoding="UTF-8" standalone="yes"?>)",
        "<RENDER_MONKEY>",
        R"( <RmEffectWorkspace NAME="Tests" API="" ACTIVE_EFFECT="Tests.Model" VALIDATION_STRING="" XML_VERSION=")" + version + "\">",
        R"(  <RmModelData NAME="Shape" API="" FILE_NAME="C:\Media\Models\)" + modelFile + R"(" ORIENTATION="0"/>)",
        R"(  <RmDirectXEffect NAME="Model" API="D3D" ACTIVE_CAMERA="Side">)",
        R"(   <RmCamera NAME="Side" API="" CAMERA_POSITION_X="1.6" CAMERA_POSITION_Y="1.2" CAMERA_POSITION_Z="2.0" LOOK_AT_VECTOR_X="0.3" LOOK_AT_VECTOR_Y="0.2" LOOK_AT_VECTOR_Z="0.1" UP_VECTOR_X="0.0" UP_VECTOR_Y="1.0" UP_VECTOR_Z="0.0" FOV="40.0" NEAR_CLIP_PLANE="0.1" FAR_CLIP_PLANE="20.0"/>)",
        matrix("matWorld", "World"),
        matrix("matView", "View"),
        matrix("matProjection", "Projection"),
        R"(   <RmPass NAME="Shade" API="D3D" PASS_INDEX="0" ENABLED="TRUE">)",
        R"(    <RmModelReference NAME="Shape" API=""/>)",
        R"(    <RmRenderStateBlock NAME="States" API="D3D">)",
        R"(     <RmState NAME="D3DRS_ZENABLE" API="D3D" STATE="7" VALUE="1" USAGE="0"/>)",
        R"(     <RmState NAME="D3DRS_ZWRITEENABLE" API="D3D" STATE="14" VALUE="1" USAGE="0"/>)",
        R"(     <RmState NAME="D3DRS_CULLMODE" API="D3D" STATE="22" VALUE="1" USAGE="0"/>)",
        R"(    </RmRenderStateBlock>)",
        R"(    <RmHLSLShader NAME="Vertex Shader" API="D3D" PIXEL_SHADER="FALSE" TARGET="vs_2_0" ENTRY_POINT="vs_main"><RmShaderCode TYPE="TEXT"><![CDATA[)",
        "float4x4 matWorld; float4x4 matView; float4x4 matProjection;",
        "struct VS_OUTPUT { float4 Pos : POSITION; float2 Tex : TEXCOORD0; };",
        "VS_OUTPUT vs_main(float4 Pos : POSITION, float2 Tex : TEXCOORD0) {",
        "   VS_OUTPUT o; " + transform + " o.Tex = Tex; return o;",
        "}]]></RmShaderCode></RmHLSLShader>",
        R"(    <RmHLSLShader NAME="Pixel Shader" API="D3D" PIXEL_SHADER="TRUE" TARGET="ps_2_0" ENTRY_POINT="ps_main"><RmShaderCode TYPE="TEXT"><![CDATA[)",
        "float4 ps_main(float2 Tex : TEXCOORD0) : COLOR0 { return float4(Tex, 0.5, 1.0); }]]></RmShaderCode></RmHLSLShader>",
        "   </RmPass>",
        "  </RmDirectXEffect>",
        " </RmEffectWorkspace>",
        "</RENDER_MONKEY>",
    });
}

class RfxDirect3DModelGLTest : public GlTest {};

// RenderMonkey gave Direct3D effects D3DX's matrices: a left-handed view looking down +z
// (D3DXMatrixLookAtLH) and a projection to depth 0…w (D3DXMatrixPerspectiveFovLH), written out
// here from their definitions in float64. The picture is the mirror image of OpenGL's for the same
// camera, so the asymmetric boxes, coloured by texture coordinates, show a wrong handedness, a
// wrong multiplication order (the file's version says which) or a wrong depth range.
TEST_F(RfxDirect3DModelGLTest, ADirect3DEffectSeesItsModelThroughD3DXsLeftHandedMatrices) {
    const Mesh boxes = asymmetricBoxes();
    const int size = 96;
    const glm::dvec3 eye(1.6, 1.2, 2.0), at(0.3, 0.2, 0.1), up(0, 1, 0);
    const glm::dvec3 zAxis = glm::normalize(at - eye), xAxis = glm::normalize(glm::cross(up, zAxis)),
                     yAxis = glm::cross(zAxis, xAxis);
    glm::dmat4 view(1.0);  // rows: the axes, each with -axis·eye
    for (int c = 0; c < 3; ++c) {
        view[c][0] = xAxis[c];
        view[c][1] = yAxis[c];
        view[c][2] = zAxis[c];
    }
    view[3] = glm::dvec4(-glm::dot(xAxis, eye), -glm::dot(yAxis, eye), -glm::dot(zAxis, eye), 1.0);
    const double yScale = 1.0 / std::tan(40.0 * std::numbers::pi / 360.0), zn = 0.1, zf = 20.0;
    glm::dmat4 projection(0.0);
    projection[0][0] = yScale;  // aspect 1
    projection[1][1] = yScale;
    projection[2][2] = zf / (zf - zn);
    projection[3][2] = -zn * zf / (zf - zn);
    projection[2][3] = 1.0;
    MeshRayCast cast(boxes, glm::dmat4(1.0), view, projection, {size, size});
    cast.setPixelCentre({0.0, 1.0});  // Direct3D 9's, at whole-number window coordinates from the top
    auto shade = [](const SurfaceHit& hit) { return ExpectedRange(glm::dvec4(hit.texcoord, 0.5, 1.0)); };
    const SurfaceFilter oneFace = onOneFace(cast);
    for (const std::string version : {"RenderMonkey 1.71", "RenderMonkey 1.5"}) {
        SCOPED_TRACE(version);
        ScratchDir media;
        write3ds(media / "Shape.3ds", boxes);
        const std::filesystem::path file = media.write("model.rfx", direct3dTexcoordEffect("Shape.3ds", version));
        WorkspaceLoadOptions load;
        load.media.searchPath = {media.path()};
        Result<Workspace> loaded = loadWorkspace(file, {}, load);
        ASSERT_TRUE(loaded.ok()) << formatAll(loaded.diagnostics());
        EXPECT_EQ(loaded->camera.convention, CameraConvention::Direct3D);
        renderAndCompare(std::make_unique<Workspace>(std::move(*loaded)), {cast, shade, 1000, oneFace});
    }
}

// RenderMonkey's default Direct3D viewer, as a file saved without moving it keeps it: View with an
// identity rotation and the eye 200 units down -z, a 45° Projection. The stock Sphere.3ds is
// missing and rmfx's unit sphere stands in at the stock sphere's measured size (the shader
// applies no World matrix, as many of RenderMonkey's do not): radius 52.0016 about
// (0.001, 0.001, 0.001) (io/mesh/StockModels.h), not sized to the camera.
TEST_F(RfxDirect3DModelGLTest, AMissingStockModelIsDrawnAtTheStockModelsSize) {
    auto matrix = [](const std::string& name, const std::string& semantic, const std::array<double, 16>& rows) {
        std::string text = R"(   <RmMatrixVariable NAME=")" + name + R"(" API="" ARTIST_EDITABLE="FALSE" VARIABLE_SEMANTIC=")" + semantic + "\"";
        for (int i = 0; i < 16; ++i) text += " VALUE_" + std::to_string(i) + "=\"" + std::to_string(rows[size_t(i)]) + "\"";
        return text + "/>";
    };
    const double yScale = 1.0 / std::tan(std::numbers::pi / 8.0), zn = 1.0, zf = 1000.0;
    const std::string effect = lines({
        "<RENDER_MONKEY>",
        R"( <RmEffectWorkspace NAME="Tests" API="" ACTIVE_EFFECT="Tests.Model" XML_VERSION="RenderMonkey 1.71">)",
        R"(  <RmModelData NAME="Shape" API="" FILE_NAME="C:\Program Files (x86)\AMD\RenderMonkey 1.82\Examples\Media\Models\Sphere.3ds"/>)",
        R"(  <RmDirectXEffect NAME="Model" API="D3D">)",
        matrix("matView", "View", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 200, 0, 0, 0, 1}),
        matrix("matProjection", "Projection", {yScale, 0, 0, 0, 0, yScale, 0, 0, 0, 0, zf / (zf - zn), -zn * zf / (zf - zn), 0, 0, 1, 0}),
        matrix("matViewProjection", "ViewProjection", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}),
        R"(   <RmPass NAME="Shade" API="D3D" PASS_INDEX="0" ENABLED="TRUE">)",
        R"(    <RmModelReference NAME="Shape" API=""/>)",
        R"(    <RmHLSLShader NAME="Vertex Shader" API="D3D" PIXEL_SHADER="FALSE" TARGET="vs_2_0" ENTRY_POINT="vs_main"><RmShaderCode TYPE="TEXT"><![CDATA[)",
        "float4x4 matViewProjection;",
        "float4 vs_main(float4 Pos : POSITION) : POSITION { return mul(Pos, matViewProjection); }]]></RmShaderCode></RmHLSLShader>",
        R"(    <RmHLSLShader NAME="Pixel Shader" API="D3D" PIXEL_SHADER="TRUE" TARGET="ps_2_0" ENTRY_POINT="ps_main"><RmShaderCode TYPE="TEXT"><![CDATA[)",
        "float4 ps_main() : COLOR0 { return float4(1.0, 0.5, 0.25, 1.0); }]]></RmShaderCode></RmHLSLShader>",
        "   </RmPass>",
        "  </RmDirectXEffect>",
        " </RmEffectWorkspace>",
        "</RENDER_MONKEY>",
    });
    ScratchDir media;
    Result<Workspace> loaded = loadWorkspace(media.write("sphere.rfx", effect));
    ASSERT_TRUE(loaded.ok()) << formatAll(loaded.diagnostics());
    const std::string warnings = formatAll(loaded.diagnostics());
    EXPECT_NE(warnings.find("drawing rmfx's built-in 'sphere' in its place"), std::string::npos) << warnings;

    Mesh sphere = makeMesh(BuiltinMesh::Sphere);
    double unitRadius = 0.0;
    for (const glm::vec3& p : sphere.positions) unitRadius = std::max(unitRadius, glm::length(glm::dvec3(p)));
    const double scale = 52.0016 / unitRadius;
    for (glm::vec3& p : sphere.positions) p = glm::vec3(glm::dvec3(p) * scale + glm::dvec3(0.001));
    glm::dmat4 view(1.0), projection(0.0);
    view[3][2] = 200.0;  // the eye at (0, 0, -200), looking down +z
    projection[0][0] = projection[1][1] = yScale;
    projection[2][2] = zf / (zf - zn);
    projection[3][2] = -zn * zf / (zf - zn);
    projection[2][3] = 1.0;
    const int size = 64;
    MeshRayCast cast(sphere, glm::dmat4(1.0), view, projection, {size, size});
    cast.setPixelCentre({0.0, 1.0});  // Direct3D 9's, at whole-number window coordinates from the top
    auto shade = [](const SurfaceHit&) { return ExpectedRange(glm::dvec4(1.0, 0.5, 0.25, 1.0)); };
    renderAndCompare(std::make_unique<Workspace>(std::move(*loaded)), {cast, shade, 600});
}

// RenderMonkey's ScreenAlignedQuad.3ds lies in its file's xy plane, and the full-screen passes
// that draw it place its corners with sign(gl_Vertex.xy): rotated to y = 0 it would draw nothing.
TEST_F(RfxModelRenderGLTest, AScreenAlignedQuadFromA3dsFileCoversTheScreen) {
    ScratchDir media;
    Mesh quad;
    quad.positions = {{-1.2f, -0.8f, 0.0f}, {1.2f, -0.8f, 0.0f}, {1.2f, 0.8f, 0.0f}, {-1.2f, 0.8f, 0.0f}};
    quad.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    write3ds(media / "ScreenAlignedQuad.3ds", quad);
    std::string effect = texcoordEffect("ScreenAlignedQuad.3ds");
    const std::string transform = "gl_Position = ftransform();";
    effect.replace(effect.find(transform), transform.size(), "gl_Position = vec4(sign(gl_Vertex.xy), 0.0, 1.0);");
    auto ws = loadRfxWithMedia(media.write("quad.rfx", effect), media.path());
    ASSERT_TRUE(ws);
    const int size = 32;
    GlRun run = runWorkspace(std::move(ws), RunSettings{{size, size}});
    ASSERT_TRUE(run.exec);
    RefImage image = readRef(run, run.ws->outputTargetName());
    double worst = 0.0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const glm::dvec4 expected((x + 0.5) / size, (y + 0.5) / size, 0.5, 1.0);  // y from the bottom
            const glm::dvec4 d = glm::abs(image.at(x, y) - expected);
            worst = std::max({worst, d.x, d.y, d.z, d.w});
        }
    expectWithin("max abs error against (u, v, 0.5) across the screen", worst, kUnorm8Conversion + 1e-4);
}

// Public RenderMonkey files, from RMFX_PUBLIC_RFX_DIR; the test is skipped without it.
class PublicRfxGLTest : public CompatibilityGlTest {
protected:
    std::filesystem::path publicFile(const std::string& name) {
        const char* folder = std::getenv("RMFX_PUBLIC_RFX_DIR");
        if (!folder || !*folder) return {};
        std::filesystem::path file = std::filesystem::path(folder) / name;
        return std::filesystem::is_regular_file(file) ? file : std::filesystem::path();
    }
};

// MeshLab's shaders/cartoon.rfx ("NPR Metallic Cartoon"): no RmCamera, so rmfx's default camera;
// the stock Teapot.3ds drawn as rmfx's teapot; the outline texture replaced by a ramp. Its shader:
// outline = texture2D(Outline, (1 − n·v, 0.5)), lighting = max(0, L·n · 0.5 + 0.5),
// colour = outline × lighting × Material, alpha lighting × Material.a.
TEST_F(PublicRfxGLTest, MeshLabCartoonShadesTheTeapotAsItsShaderSays) {
    const std::filesystem::path file = publicFile("cartoon.rfx");
    if (file.empty()) GTEST_SKIP() << "set RMFX_PUBLIC_RFX_DIR to a folder holding MeshLab's cartoon.rfx";
    ScratchDir media;
    RefImage ramp = writeTexture(media / "NPR Metallic Outline.tga", 128, 1,
                                 [](int i, int) { return glm::ivec4(2 * i, 254 - 2 * i, 60, 255); });
    auto ws = loadRfxWithMedia(file, media.path());
    ASSERT_TRUE(ws);
    const int size = 256;
    const CameraRays camera(ws->camera, size, size);
    const glm::dmat4 view = camera.view();
    const glm::dmat3 normals = normalMatrix(view);
    const glm::dvec4 material(0.260816, 0.666667, 0.274381, 1.0);  // RmColorVariable "Material"
    const Mesh teapot = makeMesh(BuiltinMesh::Teapot);
    auto outlineCoordinate = [&](const SurfaceHit& hit) {
        const glm::dvec3 n = glm::normalize(normals * hit.normal);
        const glm::dvec3 toEye = glm::normalize(-glm::dvec3(view * glm::dvec4(hit.position, 1.0)));
        return 1.0 - glm::dot(n, toEye);
    };
    auto shade = [&](const SurfaceHit& hit) {
        const glm::dvec3 n = glm::normalize(normals * hit.normal);
        const double lighting = std::max(0.0, glm::dot(kLightPositionEye, n) * 0.5 + 0.5);
        // The sampler clamps to the edge and, with no filter state, filters trilinearly across the
        // texture's mipmaps; every level of a linear ramp is the same ramp away from its ends.
        const glm::dvec4 outline = sampleBilinear(ramp, {outlineCoordinate(hit), 0.5});
        return overTexelRounding(outline, [&](glm::dvec4 texel) {
            return glm::dvec4(glm::dvec3(texel), 1.0) * lighting * material;
        });
    };
    // Pixels where the GPU may read a coarse mipmap level whose ends differ from the ramp are left
    // out: the coordinate within 0.1 of an end, or changing by more than 1/8 (16 texels) from a
    // neighbouring pixel (as far as neighbours on the same surface show; without one, left out).
    const MeshRayCast cast(teapot, glm::dmat4(1.0), view, camera.projection(), {size, size});
    auto onTheRampAtAFineLevel = [&](const SurfaceHit& hit, int i, int j) {
        const double s = outlineCoordinate(hit);
        if (!(s > 0.1 && s < 0.9)) return false;
        for (glm::ivec2 step : {glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1), glm::ivec2(0, -1)}) {
            const auto next = cast.at(i + step.x + 0.5, j + step.y + 0.5);
            if (!next || std::abs(next->depth - hit.depth) > 0.02 * hit.depth) return false;
            if (std::abs(outlineCoordinate(*next) - s) > 1.0 / 8.0) return false;
        }
        return true;
    };
    renderAndCompare(std::move(ws), {cast, shade, 1000, onTheRampAtAFineLevel});
}

// MeshLab's shaders/NormalMapping.rfx: model laurana500.obj and texture TEXTURE0.PNG, both replaced
// by stand-ins written here (a sphere whose texture coordinates stay within 0.25…0.75, and a
// smooth normal map). Its shader: p = normalize(texel.rgb − 0.5), N = normalize(gl_NormalMatrix p),
// diffuse = clamp(L·N), specular = clamp(reflect(V, N)·(−L))^Ke,
// colour = (Kd · diffuse + Ks · specular) · gl_Color, on every channel alpha included.
TEST_F(PublicRfxGLTest, MeshLabNormalMappingLightsItsModelAsItsShaderSays) {
    const std::filesystem::path file = publicFile("NormalMapping.rfx");
    if (file.empty()) GTEST_SKIP() << "set RMFX_PUBLIC_RFX_DIR to a folder holding MeshLab's NormalMapping.rfx";
    ScratchDir media;
    RefImage bump = writeTexture(media / "TEXTURE0.PNG", 64, 64,
                                 [](int i, int j) { return glm::ivec4(64 + 2 * i, 80 + 2 * j, 230, 255); });
    const Mesh sphere = uvSphere(1.2, 48, 24, {0.25, 0.25}, {0.75, 0.75});
    writeObj(media / "laurana500.obj", sphere);
    auto ws = loadRfxWithMedia(file, media.path());
    ASSERT_TRUE(ws);
    const int size = 256;
    const CameraRays camera(ws->camera, size, size);
    const glm::dmat4 view = camera.view();
    const glm::dmat3 normals = normalMatrix(view);
    const double kd = 0.7, ks = 0.4, ke = 35.84;  // RmFloatVariables Kd, Ks, Ke
    auto shade = [&](const SurfaceHit& hit) {
        const glm::dvec3 toEye = glm::normalize(-glm::dvec3(view * glm::dvec4(hit.position, 1.0)));
        const glm::dvec3 toLight = glm::normalize(kLightPositionEye);
        // Default sampler: repeat, trilinear; the coordinates stay far from the texture's edges and
        // every mipmap level of this ramp (steps of 2) is the same ramp exactly.
        return overTexelRounding(sampleBilinear(bump, hit.texcoord), [&](glm::dvec4 texel) {
            const glm::dvec3 perturbed = glm::normalize(glm::dvec3(texel) - 0.5);
            const glm::dvec3 n = glm::normalize(normals * perturbed);
            const double diffuse = std::clamp(glm::dot(toLight, n), 0.0, 1.0);
            const glm::dvec3 reflected = toEye - 2.0 * glm::dot(n, toEye) * n;
            const double specular = std::pow(std::clamp(glm::dot(reflected, -toLight), 0.0, 1.0), ke);
            return glm::dvec4(kd * diffuse + ks * specular);  // × gl_Color, white
        });
    };
    const MeshRayCast cast(sphere, glm::dmat4(1.0), view, camera.projection(), {size, size});
    renderAndCompare(std::move(ws), {cast, shade, 10000});
}

}  // namespace
}  // namespace rmfx::test
