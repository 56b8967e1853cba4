// An imported effect without an RmCamera gets rmfx's default camera moved back so that the models
// its passes draw fill the view (runtime/RfxCameraFraming.h): RenderMonkey's ~100-unit models
// would otherwise swallow a camera 4 units from the origin and render nothing.

#include <cmath>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace rmfx
