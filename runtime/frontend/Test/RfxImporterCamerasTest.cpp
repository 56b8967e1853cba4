// The RenderMonkey importer's cameras: the active RmCamera becomes the orbit that sees the same, other
// cameras a pass names are fixed cameras of their own, and D3DX's field of view is kept.

#include "frontend/rfx/RfxImporter.h"

#include <cmath>

#include <gtest/gtest.h>

#include "model/OrbitCamera.h"
#include "RfxImporterTestSupport.h"

namespace rmfx {
namespace {

using namespace test;
using namespace test::rfx_importer;

TEST(RfxImporterCameras, CameraBecomesTheOrbitThatSeesTheSame) {
    Workspace ws = imported("gl_legacy.rfx");
    // Position (3, 4, 0) looking at the origin: distance 5, yaw atan2(3, 0) = 90°, pitch asin(4/5).
    EXPECT_FLOAT_EQ(ws.camera.distance, 5.0f);
    EXPECT_NEAR(ws.camera.yawDegrees, 90.0f, 1e-4);
    EXPECT_NEAR(ws.camera.pitchDegrees, std::asin(0.8) * 180.0 / M_PI, 1e-4);
    EXPECT_FLOAT_EQ(ws.camera.fovYDegrees, 45.0f);
    EXPECT_FLOAT_EQ(ws.camera.nearPlane, 0.5f);
    EXPECT_FLOAT_EQ(ws.camera.farPlane, 50.0f);
}

// An ACTIVE_CAMERA naming none of the effect's RmCameras is a warning; with no RmCamera at all it
// names RenderMonkey's viewer camera ("Camera" in most files), which the import recovers or frames
// (RfxCameraFraming): no warning.
TEST(RfxImporterCameras, ActiveCameraNamingNoCameraWarns) {
    auto warnings = [](const std::string& text) { return formatAll(importRfxText(text, "t.rfx", ".", {}).diagnostics()); };
    const std::string pass = "<RmGLPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n" + std::string(kFragment) + "\n</RmGLPass>\n";
    std::string none = glEffect(pass);
    none.replace(none.find("API=\"OpenGL\">"), 14, "API=\"OpenGL\" ACTIVE_CAMERA=\"Camera\">");
    EXPECT_EQ(warnings(none).find("ACTIVE_CAMERA"), std::string::npos) << warnings(none);
    std::string other = glEffect("<RmCamera NAME=\"Side\" CAMERA_POSITION_X=\"0\" CAMERA_POSITION_Y=\"0\" CAMERA_POSITION_Z=\"3\"/>\n" + pass);
    other.replace(other.find("API=\"OpenGL\">"), 14, "API=\"OpenGL\" ACTIVE_CAMERA=\"Main\">");
    EXPECT_TRUE(test::hasLine(warnings(other),
                              "t.rfx:3: warning: <RmOpenGLEffect NAME=\"E\">: ACTIVE_CAMERA 'Main' names no <RmCamera> of "
                              "the effect; using the first one, 'Side'"))
        << warnings(other);
    EXPECT_EQ(allWarnings("gl_legacy.rfx").find("ACTIVE_CAMERA"), std::string::npos);
}

// RmCameraReference: a pass names a camera of the effect; the active one is the camera the viewer
// moves, any other a fixed camera of its own; one the effect lacks is a warning.
TEST(RfxImporterCameras, CameraReferencesPickAPassesCamera) {
    auto camera = [](const std::string& name, const std::string& z, const std::string& upX) {
        return "<RmCamera NAME=\"" + name + "\" CAMERA_POSITION_X=\"0\" CAMERA_POSITION_Y=\"0\" CAMERA_POSITION_Z=\"" + z +
               "\" LOOK_AT_VECTOR_X=\"0\" LOOK_AT_VECTOR_Y=\"0\" LOOK_AT_VECTOR_Z=\"0\" UP_VECTOR_X=\"" + upX +
               "\" UP_VECTOR_Y=\"1\" UP_VECTOR_Z=\"0\" FOV=\"45\" NEAR_CLIP_PLANE=\"1\" FAR_CLIP_PLANE=\"100\"/>\n";
    };
    auto pass = [](int index, const std::string& reference) {
        return "<RmGLPass NAME=\"P" + std::to_string(index) + "\" PASS_INDEX=\"" + std::to_string(index) + "\" ENABLED=\"TRUE\">" +
               (reference.empty() ? "" : "<RmCameraReference NAME=\"" + reference + "\"/>") + std::string(kFragment) +
               "</RmGLPass>\n";
    };
    const std::string text = "<RENDER_MONKEY>\n<RmEffectWorkspace NAME=\"W\" ACTIVE_EFFECT=\"W.E\">\n"
                             "<RmOpenGLEffect NAME=\"E\" API=\"OpenGL\" ACTIVE_CAMERA=\"Viewer\">\n" +
                             camera("Viewer", "10", "0") + camera("Light", "20", "1") + pass(0, "Viewer") + pass(1, "Light") +
                             pass(2, "") + pass(3, "Nowhere") + "</RmOpenGLEffect>\n</RmEffectWorkspace>\n</RENDER_MONKEY>\n";
    Result<Workspace> ws = importRfxText(text, "t.rfx", ".", {""});
    ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
    EXPECT_FLOAT_EQ(ws->camera.distance, 10.0f);
    ASSERT_EQ(ws->cameras.size(), 1u);
    EXPECT_EQ(ws->cameras[0].name, "Light");
    EXPECT_FLOAT_EQ(ws->cameras[0].settings.distance, 20.0f);
    EXPECT_NEAR(ws->cameras[0].settings.rollDegrees, 45.0f, 1e-4);  // up (1, 1, 0) looking down -Z
    ASSERT_EQ(ws->passes.size(), 4u);
    EXPECT_EQ(ws->passes[0].camera, "");  // the active one
    EXPECT_EQ(ws->passes[1].camera, "Light");
    EXPECT_EQ(ws->passes[2].camera, "");
    EXPECT_EQ(ws->passes[3].camera, "");
    EXPECT_TRUE(test::hasLine(
        formatAll(ws.diagnostics()),
        "t.rfx:9: warning: <RmCameraReference NAME=\"Nowhere\">: the effect has no <RmCamera NAME=\"Nowhere\">; the "
        "pass uses the effect's camera"))
        << formatAll(ws.diagnostics());
}

// RenderMonkey's viewer stored FOVs past 180 degrees (its zoom went there) and D3DX's
// PerspectiveFovLH used them as they were: y scale cot(FOV / 2) < 0, so FOV 200 shows what FOV
// 160 shows, turned 180 degrees. Checked against that formula in double for a point in view.
TEST(RfxImporterCameras, AFovPast180DegreesTurnsThePictureAsD3dxDid) {
    auto effect = [](const std::string& fov) {
        return "<RENDER_MONKEY>\n<RmEffectWorkspace NAME=\"W\" ACTIVE_EFFECT=\"W.E\">\n<RmDirectXEffect NAME=\"E\" API=\"D3D\">\n"
               "<RmCamera NAME=\"C\" CAMERA_POSITION_X=\"0\" CAMERA_POSITION_Y=\"0\" CAMERA_POSITION_Z=\"-10\" "
               "LOOK_AT_VECTOR_X=\"0\" LOOK_AT_VECTOR_Y=\"0\" LOOK_AT_VECTOR_Z=\"0\" UP_VECTOR_X=\"0\" UP_VECTOR_Y=\"1\" "
               "UP_VECTOR_Z=\"0\" FOV=\"" + fov + "\" NEAR_CLIP_PLANE=\"1\" FAR_CLIP_PLANE=\"100\"/>\n" +
               d3dStatePass(0, "") + "</RmDirectXEffect>\n</RmEffectWorkspace>\n</RENDER_MONKEY>\n";
    };
    Result<Workspace> wide = importRfxText(effect("200"), "t.rfx", ".", {""});
    ASSERT_TRUE(wide) << formatAll(wide.diagnostics());
    EXPECT_FLOAT_EQ(wide->camera.fovYDegrees, 200.0f);
    const double aspect = 1.5, pi = std::acos(-1.0);
    const glm::mat4 projection = OrbitCamera(wide->camera).projection(static_cast<float>(aspect));
    const double yScale = 1.0 / std::tan(200.0 / 2.0 * pi / 180.0);  // D3DX: cot(fovY / 2)
    EXPECT_LT(yScale, 0.0);
    EXPECT_NEAR(projection[1][1], yScale, 1e-6 * std::abs(yScale));
    EXPECT_NEAR(projection[0][0], yScale / aspect, 1e-6 * std::abs(yScale));
    // The same point through FOV 160: x and y negated.
    Result<Workspace> narrow = importRfxText(effect("160"), "t.rfx", ".", {""});
    ASSERT_TRUE(narrow) << formatAll(narrow.diagnostics());
    const glm::vec4 point(1.0f, 0.5f, 0.0f, 1.0f);
    auto ndc = [&](const Workspace& ws) {
        const OrbitCamera camera(ws.camera);
        const glm::vec4 clip = camera.projection(static_cast<float>(aspect)) * camera.view() * point;
        return glm::vec2(clip) / clip.w;
    };
    EXPECT_NEAR(ndc(*wide).x, -ndc(*narrow).x, 1e-5);
    EXPECT_NEAR(ndc(*wide).y, -ndc(*narrow).y, 1e-5);
    EXPECT_GT(std::abs(ndc(*narrow).x), 0.01f);

    for (const auto& [bad, read] : {std::pair{"180", "180.000000"}, std::pair{"360", "360.000000"}, std::pair{"0", "0.000000"},
                                    std::pair{"-20", "-20.000000"}}) {
        Result<Workspace> refused = importRfxText(effect(bad), "t.rfx", ".", {""});
        EXPECT_FALSE(refused) << bad;
        EXPECT_TRUE(test::hasLine(formatAll(refused.diagnostics()), "t.rfx:4: error: <RmCamera NAME=\"C\">: FOV " +
                                                                        std::string(read) +
                                                                        " is not an angle in (0, 360) degrees other than 180"))
            << formatAll(refused.diagnostics());
    }
}

}  // namespace
}  // namespace rmfx
