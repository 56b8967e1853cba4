// <pass camera="NAME">: a pass looks through a named, fixed camera (RenderMonkey's
// RmCameraReference), rolled as its roll says, while the others keep the workspace's camera.
// rm_View is read back and compared with glm::lookAt built here from the camera's numbers.

#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "frontend/workspace/WorkspaceParser.h"
#include "tests/support/GlTestSupport.h"
#include "validation/Validation.h"

namespace rmfx::test {
namespace {

class PassCameraGLTest : public GlTest {};

// The view of a camera at `distance` from `target`, turned `yaw` about +Y from +Z and raised
// `pitch`, its up turned `roll` from the vertical toward its right.
glm::dmat4 expectedView(glm::dvec3 target, double distance, double yaw, double pitch, double roll) {
    yaw = glm::radians(yaw), pitch = glm::radians(pitch), roll = glm::radians(roll);
    const glm::dvec3 eye = target + distance * glm::dvec3(std::sin(yaw) * std::cos(pitch), std::sin(pitch),
                                                          std::cos(yaw) * std::cos(pitch));
    const glm::dvec3 forward = glm::normalize(target - eye);
    const glm::dvec3 up = glm::normalize(glm::dvec3(0, 1, 0) - forward * forward.y);
    const glm::dvec3 right = glm::cross(forward, up);
    return glm::lookAt(eye, target, up * std::cos(roll) + right * std::sin(roll));
}

// A pass that writes rm_View's column i into pixel i of a 4x1 target.
std::string viewPass(const std::string& name, const std::string& camera) {
    return R"(  <target name=")" + name + R"(" format="rgba32f" size="4x1"/>
  <pass name=")" + name + R"(" target=")" + name + "\"" + (camera.empty() ? "" : " camera=\"" + camera + "\"") + R"(>
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform mat4 rm_View;
out vec4 fragColor;
void main() { fragColor = rm_View[int(gl_FragCoord.x)]; }
]]></shader>
  </pass>
)";
}

void expectView(const Image& image, const glm::dmat4& expected, const std::string& what) {
    ASSERT_EQ(image.width, 4) << what;
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 4; ++row)
            EXPECT_NEAR(image.at(column, 0, row), expected[column][row], 1e-5) << what << ": column " << column << " row " << row;
}

}  // namespace

TEST_F(PassCameraGLTest, APassLooksThroughItsNamedCameraAndTheOthersThroughTheWorkspaces) {
    const std::string xml = R"(<workspace version="1" name="cameras" size="4x1">
  <camera target="0 1 0" distance="5" yaw="30" pitch="15"/>
  <camera name="light" target="1 0 -2" distance="3" yaw="-100" pitch="40" roll="25"/>
)" + viewPass("main", "") + viewPass("fromLight", "light") +
                            "</workspace>";
    GlRun run = runWorkspace(xml, RunSettings{{4, 1}});
    ASSERT_TRUE(run.exec);
    expectView(readBack(*run.exec, "main"), expectedView({0, 1, 0}, 5, 30, 15, 0), "the workspace's camera");
    expectView(readBack(*run.exec, "fromLight"), expectedView({1, 0, -2}, 3, -100, 40, 25), "camera 'light'");
}

TEST_F(PassCameraGLTest, ACameraNoCameraDeclaresIsAnError) {
    const std::string xml = R"(<workspace version="1" name="cameras" size="4x1">
  <camera name="light" target="1 0 -2"/>
)" + viewPass("fromSun", "sun") + "</workspace>";
    Result<Workspace> ws = parseWorkspaceText(xml, "cameras.xml", ".");
    ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
    const std::string errors = formatAll(validateWorkspace(*ws).diagnostics());
    EXPECT_NE(errors.find("cameras.xml:4: error: <pass name=\"fromSun\">: camera 'sun' is not declared (named cameras: light)"),
              std::string::npos)
        << errors;
}

}  // namespace rmfx::test
