// Volume (3D) textures (<volume>, RenderMonkey's Rm3DTextureVariable): a DDS volume written here
// byte by byte, sampled with texture(sampler3D, uvw) at texel centres and between slices, against
// the file's bytes; the sampler type check; the placeholder volume of --missing-media placeholder.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "frontend/workspace/WorkspaceParser.h"
#include "io/image/PlaceholderImage.h"
#include "io/media/MediaResolver.h"
#include "validation/Validation.h"
#include "tests/support/DdsBytes.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

class VolumeTextureGLTest : public GlTest {};

constexpr int kW = 4, kH = 2, kD = 3;

// The bytes (R, G, B, A) of texel (x, y, z) of the volume below, y = 0 the file's top row.
glm::dvec4 texelBytes(int x, int y, int z) { return {x * 60 + 10, y * 100 + 20, z * 100 + 30, 255 - 40 * z}; }

std::filesystem::path writeVolume(const ScratchDir& dir) {
    dds::Bytes bytes = dds::uncompressedVolumeHeader(kW, kH, kD);
    for (int z = 0; z < kD; ++z)
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                const glm::dvec4 t = texelBytes(x, y, z);
                bytes.insert(bytes.end(), {static_cast<uint8_t>(t.b), static_cast<uint8_t>(t.g), static_cast<uint8_t>(t.r),
                                           static_cast<uint8_t>(t.a)});
            }
    return dds::writeBytes(dir, "volume.dds", bytes);
}

// One pass writing, for output pixel (i, 0), texture(v, uvw[i]).
std::string samplingWorkspace(const std::string& volume, const std::string& sampler, const std::vector<glm::dvec3>& uvw,
                              const std::string& samplerType = "sampler3D", const std::string& swizzle = "") {
    std::string points;
    for (size_t i = 0; i < uvw.size(); ++i)
        points += (i ? ", " : "") + std::string("vec3(") + std::to_string(uvw[i].x) + ", " + std::to_string(uvw[i].y) + ", " +
                  std::to_string(uvw[i].z) + ")";
    return R"(<workspace version="1" name="volume">
  )" + volume + R"(
  <target name="out" format="rgba32f" size=")" +
           std::to_string(uvw.size()) + R"(x1"/>
  <pass name="sample" target="out">
    )" + sampler + R"(
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform )" + samplerType + R"( v;
const vec3 points[)" + std::to_string(uvw.size()) + "] = vec3[](" + points + R"();
out vec4 fragColor;
void main() { fragColor = texture(v, points[int(gl_FragCoord.x)])" + swizzle + R"(); }
]]></shader>
  </pass>
</workspace>)";
}

// The texture coordinate of texel (x, y, z)'s centre: row 0 of a slice is its top (t = 1), as for
// 2D textures; slice 0 is at r = 0, Direct3D's w = 0.
glm::dvec3 centre(int x, int y, int z) { return {(x + 0.5) / kW, 1.0 - (y + 0.5) / kH, (z + 0.5) / kD}; }

}  // namespace

TEST_F(VolumeTextureGLTest, EveryTexelCentreReadsTheFilesTexel) {
    ScratchDir dir;
    writeVolume(dir);
    std::vector<glm::dvec3> uvw;
    std::vector<glm::ivec3> texels;
    for (int z = 0; z < kD; ++z)
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                uvw.push_back(centre(x, y, z));
                texels.push_back({x, y, z});
            }
    auto ws = workspaceFromText(samplingWorkspace(R"(<volume name="noise" file="volume.dds" mipmaps="false"/>)",
                                                  R"(<sampler name="v" texture="noise" filter="nearest"/>)", uvw),
                                dir.path());
    ASSERT_TRUE(ws);
    GlRun run = runWorkspace(std::move(ws), {{static_cast<int>(uvw.size()), 1}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    Image out = readBack(*run.exec, "out");
    ASSERT_EQ(out.width, static_cast<int>(uvw.size()));
    for (size_t i = 0; i < texels.size(); ++i) {
        const glm::dvec4 expected = texelBytes(texels[i].x, texels[i].y, texels[i].z) / 255.0;
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(out.at(static_cast<int>(i), 0, c), expected[c], 1e-6)
                << "texel " << texels[i].x << "," << texels[i].y << "," << texels[i].z << " channel " << c;
    }
}

TEST_F(VolumeTextureGLTest, LinearFilteringBlendsNeighbouringSlicesAndWrapRFollowsItsOwnMode) {
    ScratchDir dir;
    writeVolume(dir);
    // Halfway between slices 0 and 1 at texel (1, 0); a quarter of the way from slice 1 to 2 at
    // texel (2, 1); and r = -1/6 (half a slice below slice 0): with wrap-r repeat it blends
    // slice 0 with slice 2 (the last), with clamp it is slice 0.
    const glm::dvec3 half = {centre(1, 0, 0).x, centre(1, 0, 0).y, 1.0 / 3.0};
    const glm::dvec3 quarter = {centre(2, 1, 0).x, centre(2, 1, 0).y, 0.5 + 0.25 / kD};
    const glm::dvec3 below = {centre(3, 0, 0).x, centre(3, 0, 0).y, 0.0};
    const std::vector<glm::dvec3> uvw = {half, quarter, below};
    for (const char* wrapR : {"repeat", "clamp"}) {
        SCOPED_TRACE(wrapR);
        auto ws = workspaceFromText(
            samplingWorkspace(R"(<volume name="noise" file="volume.dds" mipmaps="false"/>)",
                              std::string(R"(<sampler name="v" texture="noise" filter="linear" wrap="clamp" wrap-r=")") + wrapR + "\"/>",
                              uvw),
            dir.path());
        ASSERT_TRUE(ws);
        GlRun run = runWorkspace(std::move(ws), {{3, 1}, 1, 1.0f / 60.0f});
        ASSERT_TRUE(run.exec);
        Image out = readBack(*run.exec, "out");
        ASSERT_EQ(out.width, 3);
        const bool repeat = std::string(wrapR) == "repeat";
        const glm::dvec4 expected[3] = {
            0.5 * (texelBytes(1, 0, 0) + texelBytes(1, 0, 1)) / 255.0,
            (0.75 * texelBytes(2, 1, 1) + 0.25 * texelBytes(2, 1, 2)) / 255.0,
            repeat ? 0.5 * (texelBytes(3, 0, 0) + texelBytes(3, 0, 2)) / 255.0 : texelBytes(3, 0, 0) / 255.0,
        };
        // 8-bit texels may be filtered in 8-bit fixed point (llvmpipe does): one step.
        for (int i = 0; i < 3; ++i)
            for (int c = 0; c < 4; ++c) EXPECT_NEAR(out.at(i, 0, c), expected[i][c], 1.0 / 255.0) << "sample " << i << " channel " << c;
    }
}

// Parsed with missing media as `missing` says, then validated: its diagnostics, and the workspace.
Result<Workspace> loaded(const std::string& xml, const ScratchDir& dir, MissingMedia missing) {
    Result<Workspace> parsed = parseWorkspaceText(xml, dir.path() / "volume.xml", dir.path());
    if (!parsed) return parsed;
    Diagnostics d = parsed.diagnostics();
    MediaOptions media;
    media.missing = missing;
    auto add = [&](const Diagnostics& more) { d.insert(d.end(), more.begin(), more.end()); };
    add(resolveWorkspaceMedia(*parsed, media).diagnostics());
    if (!hasErrors(d)) add(validateWorkspace(*parsed).diagnostics());
    if (hasErrors(d)) return Result<Workspace>::failure(std::move(d));
    return {std::move(*parsed), std::move(d)};
}

TEST_F(VolumeTextureGLTest, ASampler2DOnAVolumeIsAnErrorNamingBoth) {
    ScratchDir dir;
    writeVolume(dir);
    Result<Workspace> ws = loaded(samplingWorkspace(R"(<volume name="noise" file="volume.dds"/>)",
                                                    R"(<sampler name="v" texture="noise"/>)", {{0.5, 0.5, 0.0}}, "sampler2D", ".xy"),
                                  dir, MissingMedia::Error);
    ASSERT_FALSE(ws);
    const std::string errors = formatAll(ws.diagnostics());
    EXPECT_NE(errors.find("uniform 'v' is declared sampler2D, but <sampler name=\"v\">"), std::string::npos) << errors;
    EXPECT_NE(errors.find("binds a volume (3D) texture and needs sampler3D"), std::string::npos) << errors;
}

TEST_F(VolumeTextureGLTest, AMissingVolumeBecomesACheckeredPlaceholderVolume) {
    ScratchDir dir;
    // Texel centres of the 32x32x32 placeholder: (0,0,0) magenta, (8,0,0) grey, (8,0,8) magenta.
    auto at = [](int x, int y, int z) { return glm::dvec3((x + 0.5) / 32, 1.0 - (y + 0.5) / 32, (z + 0.5) / 32); };
    Result<Workspace> ws = loaded(samplingWorkspace(R"(<volume name="noise" file="NoiseVolume.dds"/>)",
                                                    R"(<sampler name="v" texture="noise" filter="nearest"/>)",
                                                    {at(0, 0, 0), at(8, 0, 0), at(8, 0, 8)}),
                                  dir, MissingMedia::Placeholder);
    ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
    const std::string warnings = formatAll(ws.diagnostics());
    EXPECT_NE(warnings.find("<volume name=\"noise\">"), std::string::npos) << warnings;
    EXPECT_NE(warnings.find("stands in for the volume texture"), std::string::npos) << warnings;
    GlRun run = runWorkspace(std::make_unique<Workspace>(std::move(*ws)), {{3, 1}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    Image out = readBack(*run.exec, "out");
    ASSERT_EQ(out.width, 3);
    const glm::dvec3 magenta(kPlaceholderMagenta[0], kPlaceholderMagenta[1], kPlaceholderMagenta[2]);
    const glm::dvec3 grey(kPlaceholderGrey);
    const glm::dvec3 expected[3] = {magenta, grey, magenta};
    for (int i = 0; i < 3; ++i)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(out.at(i, 0, c), expected[i][c], 1e-6) << "sample " << i << " channel " << c;
}

}  // namespace rmfx::test
