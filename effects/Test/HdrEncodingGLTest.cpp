// effects/hdr_encoding_roundtrip.xml on llvmpipe: a ramp (0, tiny, a log sweep past every
// encoding's maximum, NaN, ±Inf, negatives) encoded by glsl/hdr_encoding.glsl into a target whose
// format follows HDR_Encoding, and decoded in a second pass. The codes GL stored must be the C++
// twin's bit for bit, the decoded values the twin's decode of them to the bit, and the round-trip
// error within the format's bound (tests/reference/HdrEncodingReference.h).

#include <algorithm>
#include <bit>
#include <cmath>
#include <sstream>

#include <glm/common.hpp>
#include <gtest/gtest.h>

#include "model/HdrEncoding.h"
#include "reference/HdrEncodingReference.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::test {
namespace {

constexpr int kWidth = 64, kHeight = 32;

std::unique_ptr<Workspace> roundTripWorkspace(int encoding) {
    Result<Workspace> loaded = loadWorkspace(sourceDir() / "effects" / "hdr_encoding_roundtrip.xml");
    if (!loaded) {
        ADD_FAILURE() << formatAll(loaded.diagnostics());
        return nullptr;
    }
    auto ws = std::make_unique<Workspace>(std::move(*loaded));
    if (Result<void> set = applyOverrides(*ws, {{"HDR_Encoding", std::to_string(encoding)}}); !set) {
        ADD_FAILURE() << formatAll(set.diagnostics());
        return nullptr;
    }
    return ws;
}

bool sameBits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }

// Compares what the executor's targets hold with the C++ twin, pixel by pixel; returns the number
// of pixels that differ (the first few are reported).
int compareWithTwin(const GlExecutor& exec, HdrEncoding e) {
    Image input = readBack(exec, "input"), encoded = readBack(exec, "encoded"), decoded = readBack(exec, "decoded");
    if (input.empty() || encoded.empty() || decoded.empty()) return -1;
    int bad = 0;
    std::ostringstream report;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            glm::vec3 in(atGl(input, x, y, 0), atGl(input, x, y, 1), atGl(input, x, y, 2));
            glm::vec4 texel(atGl(encoded, x, y, 0), atGl(encoded, x, y, 1), atGl(encoded, x, y, 2), atGl(encoded, x, y, 3));
            glm::vec3 out(atGl(decoded, x, y, 0), atGl(decoded, x, y, 1), atGl(decoded, x, y, 2));
            glm::uvec4 glCodes = hdrTexelCodes(e, texel), twinCodes = encodeHdrCodes(e, in);
            glm::vec3 twinDecoded = decodeHdrCodes(e, glCodes);
            bool ok = true;
            for (int k = 0; k < 3; ++k) {
                if (e == HdrEncoding::Float) {
                    // Passed through; llvmpipe may flush a subnormal input to zero.
                    bool flushed = std::fpclassify(in[k]) == FP_SUBNORMAL && out[k] == 0.0f;
                    ok = ok && (sameBits(out[k], in[k]) || (std::isnan(in[k]) && std::isnan(out[k])) || flushed);
                    continue;
                }
                ok = ok && glCodes[k] == twinCodes[k] && sameBits(out[k], twinDecoded[k]);
                if (std::isfinite(in[k]) && std::isfinite(out[k]) && in[k] >= 0.0f) {
                    glm::vec3 clean = glm::max(glm::vec3(0.0f), in);  // sanitised, in range: the bound holds
                    float max = std::max({clean.r, clean.g, clean.b});
                    if (max <= hdrEncodingMax(e) && !glm::any(glm::isnan(in)))
                        ok = ok && std::fabs(double(out[k]) - in[k]) <=
                                       referenceErrorBound(e, glm::dvec3(clean)) + std::ldexp(std::fabs(double(in[k])), -21);
                }
            }
            if (e != HdrEncoding::Float) ok = ok && glCodes.w == twinCodes.w;
            if (!ok && ++bad <= 5)
                report << "pixel " << x << "," << y << ": in " << in.r << " " << in.g << " " << in.b << "; GL codes "
                       << glCodes.x << " " << glCodes.y << " " << glCodes.z << " " << glCodes.w << " decoded " << out.r
                       << " " << out.g << " " << out.b << "; twin codes " << twinCodes.x << " " << twinCodes.y << " "
                       << twinCodes.z << " " << twinCodes.w << " decoded " << twinDecoded.r << " " << twinDecoded.g
                       << " " << twinDecoded.b << "\n";
        }
    if (bad) ADD_FAILURE() << hdrEncodingName(e) << ": " << bad << " pixels differ from the C++ twin\n" << report.str();
    return bad;
}

class HdrEncodingGLTest : public GlTest, public ::testing::WithParamInterface<HdrEncoding> {};

TEST_P(HdrEncodingGLTest, ShaderCodesAndDecodesMatchTheTwin) {
    HdrEncoding e = GetParam();
    GlRun run = runWorkspace(roundTripWorkspace(static_cast<int>(e)), {{kWidth, kHeight}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    EXPECT_EQ(compareWithTwin(*run.exec, e), 0);
}

INSTANTIATE_TEST_SUITE_P(Encodings, HdrEncodingGLTest,
                         ::testing::Values(HdrEncoding::Float, HdrEncoding::Rgb16, HdrEncoding::Rgb32, HdrEncoding::Rgb9e5,
                                           HdrEncoding::Rgbe8, HdrEncoding::Rgba8x64),
                         [](const auto& info) { return std::string(hdrEncodingName(info.param)); });

class HdrEncodingSwitchGLTest : public GlTest {};

// setVariable on a format-by variable allocates the target anew in the format it now picks.
TEST_F(HdrEncodingSwitchGLTest, SettingTheVariableReallocatesTheTarget) {
    GlRun run = runWorkspace(roundTripWorkspace(0), {{kWidth, kHeight}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    for (HdrEncoding e : {HdrEncoding::Rgb9e5, HdrEncoding::Rgb16, HdrEncoding::Rgbe8}) {
        EXPECT_EQ(run.exec->setVariable("HDR_Encoding", Value::ofInt(static_cast<int>(e))).error(), "");
        Diagnostics d = run.exec->renderFrame({}).takeDiagnostics();
        EXPECT_TRUE(d.empty()) << formatAll(d);
        EXPECT_EQ(compareWithTwin(*run.exec, e), 0);
    }
    EXPECT_EQ(run.exec->setVariable("HDR_Encoding", Value::ofInt(6)).error(),
              "variable 'HDR_Encoding' = 6 picks none of the 6 formats of target 'encoded'");
    EXPECT_EQ(run.exec->variable("HDR_Encoding")->asInt(), static_cast<int>(HdrEncoding::Rgbe8));  // unchanged
}

TEST_F(HdrEncodingSwitchGLTest, SetOutOfRangeFailsAtCreationNamingTheTarget) {
    auto ws = roundTripWorkspace(7);
    ASSERT_TRUE(ws);
    auto exec = runHeadless(*ws, {{kWidth, kHeight}, 1, 1.0f / 60.0f});
    EXPECT_FALSE(exec);
    const Diagnostics& d = exec.diagnostics();
    ASSERT_FALSE(d.empty());
    EXPECT_EQ(d.front().element, "<target name=\"encoded\">");
    EXPECT_EQ(d.front().message, "variable 'HDR_Encoding' = 7 picks none of the 6 formats of target 'encoded'");
}

}  // namespace
}  // namespace rmfx::test
