// The compatibility-profile context and the vertex arrays of a program that reads the built-ins,
// checked as GL state: llvmpipe does not alias generic attributes with the built-ins, so a
// render there cannot show what an NVIDIA H200 did (gl_Normal read rmfx's texture coordinates).

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "gl/GlContext.h"
#include "tests/support/GlTestSupport.h"

namespace rmfx::test {
namespace {

class CompatibilityArraysGLTest : public CompatibilityGlTest {};

TEST_F(CompatibilityArraysGLTest, TheContextIsACompatibilityProfileAndItsDescriptionSaysSo) {
    auto compatibility = GlContext::createHeadless(GlProfile::Compatibility);
    ASSERT_TRUE(compatibility) << compatibility.error();
    GLint mask = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
    EXPECT_TRUE(mask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT) << mask;
    // Mesa's version string names the profile; NVIDIA's does not, and rmfx adds it.
    EXPECT_NE((*compatibility)->description().find("Compatibility Profile"), std::string::npos)
        << (*compatibility)->description();
}

// NVIDIA reads generic attribute 0 as gl_Vertex, 2 as gl_Normal, 3 as gl_Color and 8 as
// gl_MultiTexCoord0: a program that reads the built-ins must draw with none of those enabled.
TEST_F(CompatibilityArraysGLTest, BuiltinArraysAreNotShadowedByGenericArraysThatAliasThem) {
    GlRun run = runWorkspace(R"(<workspace version="1" name="legacy" size="16x16" profile="compatibility">
  <target name="out" format="rgba32f" scale="1"/>
  <pass name="mesh" target="out">
    <draw mesh="plane"/>
    <shader stage="vertex" dialect="glsl110"><![CDATA[
varying vec3 normal;
void main() { gl_Position = ftransform(); normal = gl_Normal + vec3(gl_MultiTexCoord0.xy, 0.0); }
]]></shader>
    <shader stage="fragment" dialect="glsl110"><![CDATA[
varying vec3 normal;
void main() { gl_FragColor = vec4(normal, 1.0); }
]]></shader>
  </pass>
</workspace>)",
                             RunSettings{{16, 16}});
    ASSERT_TRUE(run.exec);
    GLint array = 0;
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &array);
    ASSERT_NE(array, 0) << "the pass's vertex array is no longer bound after the frame";
    EXPECT_TRUE(glIsEnabled(GL_VERTEX_ARRAY));
    EXPECT_TRUE(glIsEnabled(GL_NORMAL_ARRAY));
    glClientActiveTexture(GL_TEXTURE0);
    EXPECT_TRUE(glIsEnabled(GL_TEXTURE_COORD_ARRAY));
    for (GLuint generic : {0u, 1u, 2u, 3u, 8u}) {
        GLint enabled = 1;
        glGetVertexAttribiv(generic, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &enabled);
        EXPECT_EQ(enabled, 0) << "generic attribute " << generic;
    }
}

}  // namespace
}  // namespace rmfx::test
