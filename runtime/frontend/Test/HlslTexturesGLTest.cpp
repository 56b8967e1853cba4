// Direct3D 9 HLSL texture reads rendered through the translator: tex2D under the sampler's name, an
// untyped sampler read with texCUBE or tex1D.

#include <gtest/gtest.h>

#include "HlslGLTestSupport.h"

namespace rmfx::test {
namespace {

using namespace hlsl_gl;

class HlslTexturesGLTest : public GlTest {};

// A 4x4 float image read with tex2D at the texel centres comes back texel for texel, the same
// way up as a GLSL texture() read of it (row 0 at the bottom).
TEST_F(HlslTexturesGLTest, Tex2DReadsTheTextureBoundUnderTheHlslSamplerName) {
    ScratchDir dir;
    RefImage image(4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) image.at(x, y) = {0.25 * x + 0.0625 * y, 10.0 + y, -x - 0.5, 1.0 / (1 + x + y)};
    writeFloatExr(dir / "image.exr", image);
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <texture name="Image" file="image.exr"/>
  <float name="depth" value="0.5"/>
  <float name="w" value="1"/>
  <float name="gain" value="2"/>
  <target name="out" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    <sampler name="baseMap" texture="Image" filter="nearest"/>
    )" + vertexShaderXml(passThroughVertexShader) +
                            R"(    <shader stage="fragment"><![CDATA[
sampler2D baseMap;
float gain;
float4 main(float2 uv : TEXCOORD0) : COLOR { return tex2D(baseMap, uv) * gain; }
]]></shader>
  </pass>
</workspace>)";
    RefImage out = renderOut(xml, dir.path());
    ASSERT_EQ(out.width, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            expectNear(pixel(out, x, y), 2.0 * image.at(x, y), 1e-6, "texel " + std::to_string(x) + "," + std::to_string(y));
}

// Direct3D 9's untyped `sampler` read with texCUBE is a cube map (glslang alone makes it 2D and
// the pass fails): each axis direction reads its own face.
TEST_F(HlslTexturesGLTest, AnUntypedSamplerReadWithTexCubeSamplesTheCubeMap) {
    ScratchDir dir;
    const char* sides[6] = {"px", "nx", "py", "ny", "pz", "nz"};
    for (int face = 0; face < 6; ++face) {
        RefImage image(2, 2);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x) image.at(x, y) = {0.125 * (face + 1), 1.0, 0.0, 1.0};
        writeFloatExr(dir / (std::string(sides[face]) + ".exr"), image);
    }
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <cubemap name="Sky">
    <face side="+x" file="px.exr"/> <face side="-x" file="nx.exr"/> <face side="+y" file="py.exr"/>
    <face side="-y" file="ny.exr"/> <face side="+z" file="pz.exr"/> <face side="-z" file="nz.exr"/>
  </cubemap>
  <target name="out" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    <sampler name="Sky" texture="Sky" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
sampler Sky : register(s0);
float4 main(float2 uv : TEXCOORD0) : COLOR {
    // Column x looks along +x, -y, +z, -z.
    float3 directions[4] = { float3(1, 0.1, 0.2), float3(0.1, -1, 0.2), float3(0.2, 0.1, 1), float3(0.1, 0.2, -1) };
    return texCUBE(Sky, directions[int(uv.x * 4)]);
}
]]></shader>
  </pass>
</workspace>)";
    RefImage out = renderOut(xml, dir.path());
    ASSERT_EQ(out.width, 4);
    const int faceOfColumn[4] = {0, 3, 4, 5};  // +x, -y, +z, -z in OpenGL's face order
    for (int x = 0; x < 4; ++x)
        expectNear(pixel(out, x, 1), {0.125 * (faceOfColumn[x] + 1), 1.0, 0.0, 1.0}, 1e-6, "column " + std::to_string(x));
}

// tex1D on an untyped sampler bound to an image one texel high (Direct3D 9 has no 1D textures):
// the texel under u.
TEST_F(HlslTexturesGLTest, Tex1DOnAnUntypedSamplerReadsAnImageOneTexelHigh) {
    ScratchDir dir;
    RefImage ramp(4, 1);
    for (int x = 0; x < 4; ++x) ramp.at(x, 0) = {0.125 * (x + 1), 2.0 - x, 0.5, 1.0};
    writeFloatExr(dir / "ramp.exr", ramp);
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <texture name="Ramp" file="ramp.exr" mipmaps="false"/>
  <target name="out" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    <sampler name="Rainbow" texture="Ramp" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
sampler Rainbow : register(s0);
float4 main(float2 uv : TEXCOORD0) : COLOR { return tex1D(Rainbow, uv.x); }
]]></shader>
  </pass>
</workspace>)";
    RefImage out = renderOut(xml, dir.path());
    ASSERT_EQ(out.width, 4);
    for (int x = 0; x < 4; ++x) expectNear(pixel(out, x, 2), ramp.at(x, 0), 1e-6, "column " + std::to_string(x));
}

}  // namespace
}  // namespace rmfx::test
