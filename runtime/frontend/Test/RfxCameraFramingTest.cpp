// An imported effect without an RmCamera gets rmfx's default camera moved back so that the models
// its passes draw fill the view (runtime/RfxCameraFraming.h): RenderMonkey's ~100-unit models
// would otherwise swallow a camera 4 units from the origin and render nothing.

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "io/mesh/BuiltinMeshes.h"
#include "model/OrbitCamera.h"

#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx {
namespace {

// A cube of half-size 50 about (10, 20, 30): bounding sphere radius 50·√3.
const char* kBigCube = R"(v -40 -30 -20
v 60 -30 -20
v 60 70 -20
v -40 70 -20
v -40 -30 80
v 60 -30 80
v 60 70 80
v -40 70 80
f 1 2 3
f 1 3 4
f 5 6 7
f 5 7 8
)";

std::string effectDrawing(const std::string& model, const std::string& camera = "") {
    return "<RENDER_MONKEY>\n<RmEffectWorkspace NAME=\"W\" ACTIVE_EFFECT=\"W.E\">\n"
           "<RmModelData NAME=\"M\" FILE_NAME=\"" + model + "\"/>\n"
           "<RmOpenGLEffect NAME=\"E\" API=\"OpenGL\">\n" + camera +
           "<RmGLPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n<RmModelReference NAME=\"M\"/>\n"
           "<RmGLShader NAME=\"F\" PIXEL_SHADER=\"TRUE\"><RmShaderCode><![CDATA[void main() { gl_FragColor = vec4(1.0); }]]>"
           "</RmShaderCode></RmGLShader>\n</RmGLPass>\n</RmOpenGLEffect>\n</RmEffectWorkspace>\n</RENDER_MONKEY>\n";
}

// A matrix variable as RenderMonkey stored it: row by row, column-vector convention.
std::string stored(const std::string& name, const std::string& semantic, const glm::dmat4& m) {
    std::string text = "<RmMatrixVariable NAME=\"" + name + "\" VARIABLE_SEMANTIC=\"" + semantic + "\"";
    for (int i = 0; i < 16; ++i) text += " VALUE_" + std::to_string(i) + "=\"" + std::to_string(m[i % 4][i / 4]) + "\"";
    return text + "/>\n";
}

// The same as a Direct3D effect, saved by RenderMonkey 1.71.
std::string direct3dEffectDrawing(const std::string& model, const std::string& camera = "") {
    return "<RENDER_MONKEY>\n<RmEffectWorkspace NAME=\"W\" ACTIVE_EFFECT=\"W.E\" XML_VERSION=\"RenderMonkey 1.71\">\n"
           "<RmModelData NAME=\"M\" FILE_NAME=\"" + model + "\"/>\n"
           "<RmDirectXEffect NAME=\"E\" API=\"D3D\">\n" + camera +
           "<RmPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n<RmModelReference NAME=\"M\"/>\n"
           "<RmHLSLShader NAME=\"F\" PIXEL_SHADER=\"TRUE\" TARGET=\"ps_2_0\" ENTRY_POINT=\"main\"><RmShaderCode><![CDATA["
           "float4 main() : COLOR { return 1; }]]></RmShaderCode></RmHLSLShader>\n</RmPass>\n</RmDirectXEffect>\n"
           "</RmEffectWorkspace>\n</RENDER_MONKEY>\n";
}

Workspace load(const test::ScratchDir& dir, const std::string& text) {
    Result<Workspace> loaded = loadWorkspace(dir.write("effect.rfx", text));
    EXPECT_TRUE(loaded.ok()) << formatAll(loaded.diagnostics());
    return loaded.ok() ? *loaded : Workspace{};
}

TEST(RfxCameraFraming, WithoutAnRmCameraTheDrawnModelFillsTheView) {
    test::ScratchDir dir;
    dir.write("big.obj", kBigCube);
    Workspace ws = load(dir, effectDrawing("big.obj"));
    const OrbitCameraSettings defaults;
    const double radius = 50.0 * std::sqrt(3.0);
    const double distance = radius / std::sin(defaults.fovYDegrees * 0.5 * M_PI / 180.0) * 1.05;
    EXPECT_FLOAT_EQ(ws.camera.target.x, 10.0f);
    EXPECT_FLOAT_EQ(ws.camera.target.y, 20.0f);
    EXPECT_FLOAT_EQ(ws.camera.target.z, 30.0f);
    EXPECT_NEAR(ws.camera.distance, distance, 1e-3 * distance);
    EXPECT_LT(ws.camera.nearPlane, distance - radius);
    EXPECT_GT(ws.camera.farPlane, distance + radius);
    EXPECT_EQ(ws.camera.yawDegrees, defaults.yawDegrees);  // the direction stays rmfx's default
    EXPECT_EQ(ws.camera.pitchDegrees, defaults.pitchDegrees);
}

// RenderMonkey kept its viewer's last View (and Projection) matrix in variables it fills by
// semantic: the camera is recovered from them, here a look-at from (120, 80, 300) toward the
// cube's centre with a 30° field of view, written as RenderMonkey stored it (row by row,
// column-vector convention).
TEST(RfxCameraFraming, TheViewerCameraIsRecoveredFromAStoredViewMatrix) {
    test::ScratchDir dir;
    dir.write("big.obj", kBigCube);
    const glm::dvec3 eye(120, 80, 300), centre(10, 20, 30);
    const glm::dmat4 view = glm::lookAt(eye, centre, glm::dvec3(0, 1, 0));
    const glm::dmat4 projection = glm::perspective(glm::radians(30.0), 1.0, 1.0, 1000.0);
    Workspace ws = load(dir, effectDrawing("big.obj", stored("view_matrix", "View", view) + stored("proj", "Projection", projection)));
    const OrbitCamera camera(ws.camera);
    const glm::dvec3 position = camera.position();
    EXPECT_NEAR(glm::length(position - eye), 0.0, 1e-2) << position.x << " " << position.y << " " << position.z;
    EXPECT_NEAR(glm::length(glm::dvec3(ws.camera.target) - centre), 0.0, 1e-2);
    EXPECT_NEAR(ws.camera.fovYDegrees, 30.0, 1e-3);
    EXPECT_NEAR(ws.camera.rollDegrees, 0.0, 1e-3);
    EXPECT_GT(ws.camera.farPlane, glm::length(eye - centre) + 50.0 * std::sqrt(3.0));

    // A Projection saved past 180 degrees (y scale cot(100°) < 0) keeps its angle.
    glm::dmat4 wide = projection;
    wide[1][1] = 1.0 / std::tan(glm::radians(100.0));
    wide[0][0] = wide[1][1];
    Workspace turned = load(dir, effectDrawing("big.obj", stored("view_matrix", "View", view) + stored("proj", "Projection", wide)));
    EXPECT_NEAR(turned.camera.fovYDegrees, 200.0, 1e-3);
}

// The clip planes are the stored projection's (RenderMonkey's viewer: near 1, far 1000), from a
// Projection, or a ViewProjection or WorldViewProjection without one, in either convention: a light
// 866 units away is inside them, where planes set to hold the models would clip it.
TEST(RfxCameraFraming, TheClipPlanesAreTheStoredProjections) {
    test::ScratchDir dir;
    dir.write("big.obj", kBigCube);
    const glm::dvec3 eye(120, 80, 300), centre(10, 20, 30);
    for (const bool direct3d : {false, true}) {
        SCOPED_TRACE(direct3d ? "Direct3D" : "OpenGL");
        const glm::dmat4 view = direct3d ? glm::lookAtLH(eye, centre, glm::dvec3(0, 1, 0)) : glm::lookAt(eye, centre, glm::dvec3(0, 1, 0));
        const glm::dmat4 projection = direct3d ? glm::perspectiveLH_ZO(glm::radians(30.0), 1.0, 1.0, 1000.0)
                                               : glm::perspectiveRH_NO(glm::radians(30.0), 1.0, 1.0, 1000.0);
        auto drawing = [&](const std::string& matrices) {
            return direct3d ? direct3dEffectDrawing("big.obj", matrices) : effectDrawing("big.obj", matrices);
        };
        for (const std::string& matrices : {stored("v", "View", view) + stored("p", "Projection", projection),
                                            stored("vp", "ViewProjection", projection * view),
                                            stored("wvp", "WorldViewProjection", projection * view)}) {
            Workspace ws = load(dir, drawing(matrices));
            EXPECT_NEAR(ws.camera.nearPlane, 1.0, 1e-3);
            EXPECT_NEAR(ws.camera.farPlane, 1000.0, 0.5);
        }
    }
}

// A View left at the identity (alexey-malov/cg-course's NPR-optimized.rfx keeps one no shader
// reads) was never filled by RenderMonkey's viewer, which stands away from the models: it would put
// the eye at the origin, inside them. It is passed over, and the models are framed as without it;
// the ViewProjection after it is still used.
TEST(RfxCameraFraming, AViewLeftAtTheIdentityIsPassedOver) {
    test::ScratchDir dir;
    dir.write("big.obj", kBigCube);
    const Workspace framed = load(dir, effectDrawing("big.obj"));
    Workspace ws = load(dir, effectDrawing("big.obj", stored("view_matrix", "View", glm::dmat4(1.0))));
    EXPECT_FLOAT_EQ(ws.camera.distance, framed.camera.distance);
    EXPECT_EQ(ws.camera.target, framed.camera.target);
    const glm::dvec3 eye(120, 80, 300), centre(10, 20, 30);
    const glm::dmat4 viewProjection =
        glm::perspective(glm::radians(30.0), 1.0, 1.0, 1000.0) * glm::lookAt(eye, centre, glm::dvec3(0, 1, 0));
    ws = load(dir, effectDrawing("big.obj", stored("view_matrix", "View", glm::dmat4(1.0)) +
                                                stored("view_proj", "ViewProjection", viewProjection)));
    EXPECT_NEAR(glm::length(glm::dvec3(OrbitCamera(ws.camera).position()) - eye), 0.0, 1e-2);
}

// The same file keeps the viewer's eye in a ViewPosition (198.5, -23.8, -4.0 there): the camera
// stands there and looks at the models. One inside the models' bounds, or at the origin where
// nothing filled it, is passed over like the identity View.
TEST(RfxCameraFraming, AStoredViewPositionAloneGivesTheEyeLookingAtTheModels) {
    test::ScratchDir dir;
    dir.write("big.obj", kBigCube);
    auto position = [](glm::dvec3 p) {
        return "<RmVectorVariable NAME=\"view_position\" VARIABLE_SEMANTIC=\"ViewPosition\" VALUE_0=\"" + std::to_string(p.x) +
               "\" VALUE_1=\"" + std::to_string(p.y) + "\" VALUE_2=\"" + std::to_string(p.z) + "\" VALUE_3=\"1\"/>\n";
    };
    const glm::dvec3 eye(198.5, -23.8, -4.0), centre(10, 20, 30);
    Workspace ws = load(dir, effectDrawing("big.obj", stored("view_matrix", "View", glm::dmat4(1.0)) + position(eye)));
    EXPECT_NEAR(glm::length(glm::dvec3(OrbitCamera(ws.camera).position()) - eye), 0.0, 1e-2);
    EXPECT_NEAR(glm::length(glm::dvec3(ws.camera.target) - centre), 0.0, 1e-2);
    EXPECT_GT(ws.camera.farPlane, glm::length(eye - centre) + 50.0 * std::sqrt(3.0));
    const Workspace framed = load(dir, effectDrawing("big.obj"));
    for (glm::dvec3 inside : {glm::dvec3(0.0), glm::dvec3(20, 30, 40)}) {
        ws = load(dir, effectDrawing("big.obj", position(inside)));
        EXPECT_FLOAT_EQ(ws.camera.distance, framed.camera.distance) << inside.x;
    }
}

// A dome around the scene (an octahedron reaching 5000 from the origin) is not framed: the
// camera fits the cube inside it, not the dome.
TEST(RfxCameraFraming, ADomeAroundTheSceneIsLeftOutOfTheFraming) {
    test::ScratchDir dir;
    dir.write("big.obj", kBigCube);
    dir.write("dome.obj", "v 5000 0 0\nv -5000 0 0\nv 0 5000 0\nv 0 -5000 0\nv 0 0 5000\nv 0 0 -5000\nf 1 3 5\nf 2 4 6\n");
    std::string text = effectDrawing("big.obj");
    const std::string domePass =
        "<RmModelData NAME=\"D\" FILE_NAME=\"dome.obj\"/>\n<RmGLPass NAME=\"Sky\" PASS_INDEX=\"1\" ENABLED=\"TRUE\">\n"
        "<RmModelReference NAME=\"D\"/>\n</RmGLPass>\n";
    text.insert(text.find("</RmOpenGLEffect>"), domePass);
    Workspace ws = load(dir, text);
    const double radius = 50.0 * std::sqrt(3.0);
    const double distance = radius / std::sin(OrbitCameraSettings{}.fovYDegrees * 0.5 * M_PI / 180.0) * 1.05;
    EXPECT_NEAR(ws.camera.distance, distance, 1e-3 * distance);
    EXPECT_FLOAT_EQ(ws.camera.target.x, 10.0f);
}

TEST(RfxCameraFraming, AnRmCameraOrOnlyAScreenAlignedQuadLeavesTheCameraAlone) {
    test::ScratchDir dir;
    dir.write("big.obj", kBigCube);
    Workspace placed = load(dir, effectDrawing("big.obj", "<RmCamera NAME=\"C\" CAMERA_POSITION_X=\"0\" "
                                                          "CAMERA_POSITION_Y=\"0\" CAMERA_POSITION_Z=\"300\" "
                                                          "LOOK_AT_VECTOR_X=\"0\" LOOK_AT_VECTOR_Y=\"0\" "
                                                          "LOOK_AT_VECTOR_Z=\"0\" UP_VECTOR_X=\"0\" UP_VECTOR_Y=\"1\" "
                                                          "UP_VECTOR_Z=\"0\" FOV=\"45\" NEAR_CLIP_PLANE=\"1\" "
                                                          "FAR_CLIP_PLANE=\"1000\"/>\n"));
    EXPECT_FLOAT_EQ(placed.camera.distance, 300.0f);
    EXPECT_EQ(placed.camera.rollDegrees, 0.0f);
    // UP_VECTOR +X, looking down -Z: rolled 90° (the camera's right is +X); −X: −90°.
    for (const auto& [x, roll] : {std::pair{"1", 90.0f}, std::pair{"-1", -90.0f}}) {
        Workspace rolled = load(dir, effectDrawing("big.obj", std::string("<RmCamera NAME=\"C\" CAMERA_POSITION_X=\"0\" "
                                                                          "CAMERA_POSITION_Y=\"0\" CAMERA_POSITION_Z=\"300\" "
                                                                          "LOOK_AT_VECTOR_X=\"0\" LOOK_AT_VECTOR_Y=\"0\" "
                                                                          "LOOK_AT_VECTOR_Z=\"0\" UP_VECTOR_X=\"") +
                                                                  x + "\" UP_VECTOR_Y=\"0\" UP_VECTOR_Z=\"0\" FOV=\"45\" "
                                                                      "NEAR_CLIP_PLANE=\"1\" FAR_CLIP_PLANE=\"1000\"/>\n"));
        EXPECT_NEAR(rolled.camera.rollDegrees, roll, 1e-4) << x;
    }
    Workspace quad = load(dir, effectDrawing("C:\\Program Files\\RenderMonkey\\Media\\ScreenAlignedQuad.3ds"));
    EXPECT_FLOAT_EQ(quad.camera.distance, OrbitCameraSettings{}.distance);
}

// A Direct3D effect's viewer is left-handed and looks down +z (D3DXMatrixLookAtLH): its stored
// View's third row is the forward direction, and the camera recovered from it is a Direct3D one.
TEST(RfxCameraFraming, ADirect3DViewerCameraIsRecoveredFromItsLeftHandedView) {
    test::ScratchDir dir;
    dir.write("big.obj", kBigCube);
    const glm::dvec3 eye(120, 80, -300), centre(10, 20, 30);
    const glm::dmat4 view = glm::lookAtLH(eye, centre, glm::dvec3(0, 1, 0));
    const glm::dmat4 projection = glm::perspectiveLH_ZO(glm::radians(30.0), 1.0, 1.0, 1000.0);
    Workspace ws = load(dir, direct3dEffectDrawing("big.obj", stored("view", "View", view) + stored("proj", "Projection", projection)));
    EXPECT_EQ(ws.camera.convention, CameraConvention::Direct3D);
    const OrbitCamera camera(ws.camera);
    EXPECT_NEAR(glm::length(glm::dvec3(camera.position()) - eye), 0.0, 1e-2);
    EXPECT_NEAR(glm::length(glm::dvec3(ws.camera.target) - centre), 0.0, 1e-2);
    EXPECT_NEAR(ws.camera.fovYDegrees, 30.0, 1e-3);
    // The matrices rmfx gives the effect are the ones RenderMonkey stored.
    const glm::dmat4 rebuilt = glm::dmat4(camera.view());
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(rebuilt[c][r], view[c][r], 1e-3) << "view column " << c << " row " << r;

    // Without a stored camera a Direct3D effect looks from -z, as RenderMonkey's viewer did.
    Workspace plain = load(dir, direct3dEffectDrawing("big.obj"));
    EXPECT_EQ(plain.camera.convention, CameraConvention::Direct3D);
    EXPECT_EQ(plain.camera.yawDegrees, 180.0f);
    EXPECT_EQ(plain.camera.pitchDegrees, 0.0f);
    EXPECT_LT(OrbitCamera(plain.camera).position().z, 30.0f - 50.0f * std::sqrt(3.0f));
    EXPECT_EQ(load(dir, effectDrawing("big.obj")).camera.convention, CameraConvention::OpenGL);
}

// Files that kept only ViewProjection (P·V): the camera comes back from it, in either convention,
// with the field of view; an orthographic one (no perspective row) is left to the framing.
TEST(RfxCameraFraming, TheViewerCameraIsRecoveredFromAStoredViewProjectionAlone) {
    test::ScratchDir dir;
    dir.write("big.obj", kBigCube);
    const glm::dvec3 centre(10, 20, 30);
    for (const bool direct3d : {false, true}) {
        SCOPED_TRACE(direct3d ? "Direct3D" : "OpenGL");
        const glm::dvec3 eye(-150, 90, direct3d ? -260 : 260);
        const glm::dmat4 viewProjection =
            direct3d ? glm::perspectiveLH_ZO(glm::radians(50.0), 1.0, 1.0, 1000.0) * glm::lookAtLH(eye, centre, glm::dvec3(0, 1, 0))
                     : glm::perspectiveRH_NO(glm::radians(50.0), 1.0, 1.0, 1000.0) * glm::lookAtRH(eye, centre, glm::dvec3(0, 1, 0));
        const std::string variable = stored("view_proj_matrix", "ViewProjection", viewProjection);
        Workspace ws = load(dir, direct3d ? direct3dEffectDrawing("big.obj", variable) : effectDrawing("big.obj", variable));
        // RenderMonkey 1.0 saved no semantics: its examples' name for the same constant says it.
        std::string unnamed = variable;
        unnamed.erase(unnamed.find(" VARIABLE_SEMANTIC=\"ViewProjection\""), std::string(" VARIABLE_SEMANTIC=\"ViewProjection\"").size());
        Workspace rm10 = load(dir, direct3d ? direct3dEffectDrawing("big.obj", unnamed) : effectDrawing("big.obj", unnamed));
        EXPECT_NEAR(glm::length(glm::dvec3(OrbitCamera(rm10.camera).position()) - eye), 0.0, 0.05) << "without a semantic";
        const OrbitCamera camera(ws.camera);
        EXPECT_NEAR(glm::length(glm::dvec3(camera.position()) - eye), 0.0, 0.05);
        EXPECT_NEAR(glm::length(glm::dvec3(ws.camera.target) - centre), 0.0, 0.05);
        EXPECT_NEAR(ws.camera.fovYDegrees, 50.0, 1e-3);
        EXPECT_NEAR(ws.camera.rollDegrees, 0.0, 1e-3);
        const glm::dmat4 rebuilt = glm::dmat4(camera.projection(1.0f)) * glm::dmat4(camera.view());
        const glm::dvec4 corner = rebuilt * glm::dvec4(60, 70, 80, 1), want = viewProjection * glm::dvec4(60, 70, 80, 1);
        EXPECT_NEAR(corner.x / corner.w, want.x / want.w, 1e-4);
        EXPECT_NEAR(corner.y / corner.w, want.y / want.w, 1e-4);
    }
    Workspace ortho = load(dir, effectDrawing("big.obj", stored("vp", "ViewProjection", glm::orthoRH_NO(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0))));
    EXPECT_FLOAT_EQ(ortho.camera.target.x, 10.0f);  // framed instead
}

// The matrices the passes read decide. Many Direct3D files keep RenderMonkey's last View (often its
// default, 200 units down -z: the identity turned into a translation) beside the ViewProjection or
// ViewInverse their shaders read; the camera comes from what the shaders read.
TEST(RfxCameraFraming, TheMatricesTheShadersReadDecideOverAStaleView) {
    test::ScratchDir dir;
    dir.write("big.obj", kBigCube);
    const glm::dvec3 centre(10, 20, 30), eye(-150, 90, -260);
    const glm::dmat4 staleView = glm::lookAtLH(glm::dvec3(0, 0, -200), glm::dvec3(0), glm::dvec3(0, 1, 0));
    const glm::dmat4 view = glm::lookAtLH(eye, centre, glm::dvec3(0, 1, 0));
    const glm::dmat4 viewProjection = glm::perspectiveLH_ZO(glm::radians(50.0), 1.0, 1.0, 1000.0) * view;
    auto effect = [](const std::string& variables, const std::string& matrix) {
        return "<RENDER_MONKEY>\n<RmEffectWorkspace NAME=\"W\" ACTIVE_EFFECT=\"W.E\" XML_VERSION=\"RenderMonkey 1.71\">\n"
               "<RmModelData NAME=\"M\" FILE_NAME=\"big.obj\"/>\n<RmDirectXEffect NAME=\"E\" API=\"D3D\">\n" + variables +
               "<RmPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n<RmModelReference NAME=\"M\"/>\n"
               "<RmHLSLShader NAME=\"V\" PIXEL_SHADER=\"FALSE\" TARGET=\"vs_2_0\" ENTRY_POINT=\"main\"><RmShaderCode><![CDATA["
               "float4x4 " + matrix + "; float4 main(float4 p : POSITION) : POSITION { return mul(p, " + matrix + "); }"
               "]]></RmShaderCode></RmHLSLShader>\n"
               "<RmHLSLShader NAME=\"F\" PIXEL_SHADER=\"TRUE\" TARGET=\"ps_2_0\" ENTRY_POINT=\"main\"><RmShaderCode><![CDATA["
               "float4 main() : COLOR { return 1; }]]></RmShaderCode></RmHLSLShader>\n</RmPass>\n</RmDirectXEffect>\n"
               "</RmEffectWorkspace>\n</RENDER_MONKEY>\n";
    };
    const std::string stale = stored("matView", "View", staleView);
    for (const auto& [matrix, variable] :
         {std::pair{std::string("matViewProjection"), stored("matViewProjection", "ViewProjection", viewProjection)},
          std::pair{std::string("matViewInverse"), stored("matViewInverse", "ViewInverse", glm::inverse(view)) +
                                                       stored("matProjection", "Projection",
                                                              glm::perspectiveLH_ZO(glm::radians(50.0), 1.0, 1.0, 1000.0))}}) {
        SCOPED_TRACE(matrix);
        Workspace ws = load(dir, effect(stale + variable, matrix));
        const OrbitCamera camera(ws.camera);
        EXPECT_NEAR(glm::length(glm::dvec3(camera.position()) - eye), 0.0, 0.05);
        EXPECT_NEAR(glm::length(glm::dvec3(ws.camera.target) - centre), 0.0, 0.05);
    }
    // When the shaders read the View itself, the View decides, stale or not; with no Projection
    // stored, the field of view is the ViewProjection's (50 degrees), not rmfx's default.
    Workspace readsView = load(dir, effect(stale + stored("matViewProjection", "ViewProjection", viewProjection), "matView"));
    EXPECT_NEAR(glm::length(glm::dvec3(OrbitCamera(readsView.camera).position()) - glm::dvec3(0, 0, -200)), 0.0, 0.05);
    EXPECT_NEAR(readsView.camera.fovYDegrees, 50.0, 1e-3);
    // A matrix the shader declares and never uses is not read (Nebula.rfx: a ViewInverse left at
    // the identity beside the WorldViewProjection it multiplies by), nor is an identity ViewInverse
    // a camera: the WorldViewProjection decides.
    const std::string declaredOnly =
        "<RENDER_MONKEY>\n<RmEffectWorkspace NAME=\"W\" ACTIVE_EFFECT=\"W.E\" XML_VERSION=\"RenderMonkey 1.71\">\n"
        "<RmModelData NAME=\"M\" FILE_NAME=\"big.obj\"/>\n<RmDirectXEffect NAME=\"E\" API=\"D3D\">\n" +
        stored("matViewInverse", "ViewInverse", glm::dmat4(1.0)) + stored("matWvp", "WorldViewProjection", viewProjection) +
        "<RmPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n<RmModelReference NAME=\"M\"/>\n"
        "<RmHLSLShader NAME=\"V\" PIXEL_SHADER=\"FALSE\" TARGET=\"vs_2_0\" ENTRY_POINT=\"main\"><RmShaderCode><![CDATA["
        "float4x4 matViewInverse; float4x4 matWvp; float4 main(float4 p : POSITION) : POSITION { return mul(p, matWvp); }"
        "]]></RmShaderCode></RmHLSLShader>\n"
        "<RmHLSLShader NAME=\"F\" PIXEL_SHADER=\"TRUE\" TARGET=\"ps_2_0\" ENTRY_POINT=\"main\"><RmShaderCode><![CDATA["
        "float4 main() : COLOR { return 1; }]]></RmShaderCode></RmHLSLShader>\n</RmPass>\n</RmDirectXEffect>\n"
        "</RmEffectWorkspace>\n</RENDER_MONKEY>\n";
    Workspace unused = load(dir, declaredOnly);
    EXPECT_NEAR(glm::length(glm::dvec3(OrbitCamera(unused.camera).position()) - eye), 0.0, 0.05);
    EXPECT_NEAR(unused.camera.fovYDegrees, 50.0, 1e-3);

    // A View read only by dead code (its result never reaches an output) is not in the constant
    // table RenderMonkey kept for the compiled shader (RmShaderConstant); the ViewProjection there
    // decides (myMater's прикольнвй эффект.rfx: a stale View under a reflection overwritten later).
    const std::string deadCode =
        "<RENDER_MONKEY>\n<RmEffectWorkspace NAME=\"W\" ACTIVE_EFFECT=\"W.E\" XML_VERSION=\"RenderMonkey 1.71\">\n"
        "<RmModelData NAME=\"M\" FILE_NAME=\"big.obj\"/>\n<RmDirectXEffect NAME=\"E\" API=\"D3D\">\n" +
        stale + stored("matViewProjection", "ViewProjection", viewProjection) +
        "<RmPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n<RmModelReference NAME=\"M\"/>\n"
        "<RmHLSLShader NAME=\"V\" PIXEL_SHADER=\"FALSE\" TARGET=\"vs_2_0\" ENTRY_POINT=\"main\"><RmShaderCode><![CDATA["
        "float4x4 matView; float4x4 matViewProjection; float4 main(float4 p : POSITION) : POSITION {"
        " float4 unused = mul(p, matView); return mul(p, matViewProjection); }"
        "]]></RmShaderCode><RmShaderConstant NAME=\"matViewProjection\" REGISTER=\"0\"/></RmHLSLShader>\n"
        "<RmHLSLShader NAME=\"F\" PIXEL_SHADER=\"TRUE\" TARGET=\"ps_2_0\" ENTRY_POINT=\"main\"><RmShaderCode><![CDATA["
        "float4 main() : COLOR { return 1; }]]></RmShaderCode></RmHLSLShader>\n</RmPass>\n</RmDirectXEffect>\n"
        "</RmEffectWorkspace>\n</RENDER_MONKEY>\n";
    Workspace dead = load(dir, deadCode);
    EXPECT_NEAR(glm::length(glm::dvec3(OrbitCamera(dead.camera).position()) - eye), 0.0, 0.05);
}

// Files that kept only WorldViewProjection (P·V·W), with the World beside it or without one (the
// identity, as RenderMonkey's viewer leaves it): the camera comes back from P·V = P·V·W·W⁻¹.
TEST(RfxCameraFraming, TheViewerCameraIsRecoveredFromAStoredWorldViewProjection) {
    test::ScratchDir dir;
    dir.write("big.obj", kBigCube);
    const glm::dvec3 centre(10, 20, 30);
    const glm::dmat4 world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(5, -3, 7)), glm::radians(30.0), glm::dvec3(0, 1, 0));
    for (const bool direct3d : {false, true})
        for (const bool keptWorld : {true, false}) {
            SCOPED_TRACE(std::string(direct3d ? "Direct3D" : "OpenGL") + (keptWorld ? ", World kept" : ", no World"));
            const glm::dvec3 eye(-150, 90, direct3d ? -260 : 260);
            const glm::dmat4 viewProjection =
                direct3d ? glm::perspectiveLH_ZO(glm::radians(40.0), 1.0, 1.0, 1000.0) * glm::lookAtLH(eye, centre, glm::dvec3(0, 1, 0))
                         : glm::perspectiveRH_NO(glm::radians(40.0), 1.0, 1.0, 1000.0) * glm::lookAtRH(eye, centre, glm::dvec3(0, 1, 0));
            const std::string variables = keptWorld ? stored("wvp", "WorldViewProjection", viewProjection * world) + stored("w", "World", world)
                                                    : stored("wvp", "WorldViewProjection", viewProjection);
            Workspace ws = load(dir, direct3d ? direct3dEffectDrawing("big.obj", variables) : effectDrawing("big.obj", variables));
            const OrbitCamera camera(ws.camera);
            EXPECT_NEAR(glm::length(glm::dvec3(camera.position()) - eye), 0.0, 0.05);
            EXPECT_NEAR(ws.camera.fovYDegrees, 40.0, 1e-3);
            EXPECT_NEAR(ws.camera.rollDegrees, 0.0, 1e-3);
        }
    // A World that cannot be inverted gives nothing: the models are framed instead.
    const glm::dmat4 someView = glm::perspectiveRH_NO(glm::radians(40.0), 1.0, 1.0, 1000.0) *
                                glm::lookAtRH(glm::dvec3(0, 0, 300), centre, glm::dvec3(0, 1, 0));
    Workspace flat = load(dir, effectDrawing("big.obj", stored("wvp", "WorldViewProjection", someView) +
                                                            stored("w", "World", glm::scale(glm::dmat4(1.0), glm::dvec3(1, 0, 1)))));
    EXPECT_FLOAT_EQ(flat.camera.target.x, 10.0f);
}

// The view axis of a stored View is turned round only when the models lie behind an eye that
// stands outside them: from inside a model (a stand-in larger than what it stands for), the models'
// direction says nothing, and the View's own axis is kept.
TEST(RfxCameraFraming, AnEyeInsideTheModelsKeepsTheStoredViewsAxis) {
    test::ScratchDir dir;
    dir.write("big.obj", kBigCube);  // centre (10, 20, 30), radius 86.6
    const glm::dvec3 eye(5, 15, 10), lookAt(-20, 15, -15);  // looking away from the centre
    const glm::dmat4 view = glm::lookAtLH(eye, lookAt, glm::dvec3(0, 1, 0));
    Workspace ws = load(dir, direct3dEffectDrawing("big.obj", stored("view", "View", view)));
    const OrbitCamera camera(ws.camera);
    EXPECT_NEAR(glm::length(glm::dvec3(camera.position()) - eye), 0.0, 0.05);
    const glm::dvec3 axis = glm::normalize(glm::dvec3(ws.camera.target) - glm::dvec3(camera.position()));
    EXPECT_GT(glm::dot(axis, glm::normalize(lookAt - eye)), 0.999);
}

// A missing model no measured stock model (Cube.3ds: no public copy was found to measure) is drawn
// as rmfx's unit cube; through the file's camera 300 units away it would be a dot, so it is scaled
// to half the view's height there. A measured stock model's stand-in (Sphere.3ds) keeps the stock
// size whatever the camera (io/mesh/StockModels), a screen-aligned quad keeps its size, and so does
// a stand-in the camera is framed to.
TEST(RfxCameraFraming, AStandInForAnUnmeasuredMissingModelIsSizedToTheFilesCamera) {
    test::ScratchDir dir;
    const glm::dvec3 eye(120, 80, 300);
    const glm::dmat4 view = glm::lookAt(eye, glm::dvec3(0.0), glm::dvec3(0, 1, 0));
    const glm::dmat4 projection = glm::perspective(glm::radians(30.0), 1.0, 1.0, 1000.0);
    const std::string matrices = stored("view", "View", view) + stored("projection", "Projection", projection);
    std::string text = effectDrawing("C:\\RenderMonkey\\Media\\Models\\Cube.3ds", matrices);
    const std::string quadPass =
        "<RmModelData NAME=\"Q\" FILE_NAME=\"C:\\RenderMonkey\\Media\\Models\\ScreenAlignedQuad.3ds\"/>\n"
        "<RmGLPass NAME=\"Quad\" PASS_INDEX=\"1\" ENABLED=\"TRUE\">\n<RmModelReference NAME=\"Q\"/>\n</RmGLPass>\n";
    text.insert(text.find("</RmOpenGLEffect>"), quadPass);
    Workspace ws = load(dir, text);
    ASSERT_EQ(ws.passes.size(), 2u);
    double unitRadius = 0.0;
    for (const glm::vec3& p : makeMesh(BuiltinMesh::Cube).positions) unitRadius = std::max(unitRadius, glm::length(glm::dvec3(p)));
    const DrawCall& cube = ws.passes[0].draw;
    ASSERT_EQ(cube.mesh, BuiltinMesh::Cube);
    EXPECT_TRUE(cube.standIn);
    EXPECT_FALSE(cube.stockSize);
    const double wanted = 0.5 * glm::length(eye) * std::tan(glm::radians(15.0));
    EXPECT_NEAR(cube.meshScale * unitRadius, wanted, 1e-3 * wanted);
    EXPECT_EQ(cube.scale, glm::vec3(1.0f));  // the vertices, not World: shaders may apply none
    EXPECT_EQ(ws.passes[1].draw.mesh, BuiltinMesh::Quad);
    EXPECT_EQ(ws.passes[1].draw.meshScale, 1.0f);

    Workspace sphere = load(dir, effectDrawing("C:\\RenderMonkey\\Media\\Models\\Sphere.3ds", matrices));
    EXPECT_TRUE(sphere.passes[0].draw.stockSize);
    EXPECT_NEAR(sphere.passes[0].draw.meshScale, 52.0016f, 1e-3f);  // the stock sphere's radius, for a unit sphere

    // An author's own "teapot.X" seen from 3.5 units away: the stock teapot (161 units long) would
    // hold the camera, so the stand-in is sized to the camera as an unmeasured model is (never below
    // the built-in mesh's own size).
    const glm::dvec3 near(1.5, 1.0, 3.0);
    const std::string nearMatrices = stored("view", "View", glm::lookAt(near, glm::dvec3(0.0), glm::dvec3(0, 1, 0))) +
                                     stored("projection", "Projection", projection);
    Workspace own = load(dir, effectDrawing("C:\\_KSW\\Media\\primit\\teapot.X", nearMatrices));
    const DrawCall& teapot = own.passes[0].draw;
    ASSERT_EQ(teapot.mesh, BuiltinMesh::Teapot);
    EXPECT_FALSE(teapot.stockSize);
    EXPECT_EQ(teapot.meshOffset, glm::vec3(0.0f));
    const Mesh teapotMesh = makeMesh(BuiltinMesh::Teapot);
    double teapotRadius = 0.0;
    glm::dvec3 low(1e9), high(-1e9);
    for (const glm::vec3& p : teapotMesh.positions) {
        low = glm::min(low, glm::dvec3(p));
        high = glm::max(high, glm::dvec3(p));
    }
    const glm::dvec3 teapotCentre = 0.5 * (low + high);
    for (const glm::vec3& p : teapotMesh.positions) teapotRadius = std::max(teapotRadius, glm::length(glm::dvec3(p) - teapotCentre));
    const double nearWanted = 0.5 * glm::length(near - teapotCentre) * std::tan(glm::radians(15.0));
    const double nearExpected = std::max(teapotRadius, nearWanted);
    EXPECT_NEAR(teapot.meshScale * teapotRadius, nearExpected, 1e-3 * nearExpected);
    EXPECT_LT(teapot.meshScale * teapotRadius, glm::length(near - teapotCentre));  // the camera outside it
    // Seen from 300 units, the same name keeps the stock teapot's size.
    Workspace far = load(dir, effectDrawing("C:\\_KSW\\Media\\primit\\teapot.X", matrices));
    EXPECT_TRUE(far.passes[0].draw.stockSize);

    Workspace framed = load(dir, effectDrawing("C:\\RenderMonkey\\Media\\Models\\Cube.3ds"));
    EXPECT_EQ(framed.passes[0].draw.meshScale, 1.0f);
    EXPECT_LT(framed.camera.distance, 10.0f);
}

}  // namespace
}  // namespace rmfx
