// `rmfx bench` end to end on a tiny stand-in stage (a copy and a 3x3 box "bloom" of a 32x32
// rendered scene and a 24x16 EXR with NaN and negative texels): the result files exist and
// parse, every number is finite, the copy variant's error is the CPU's error of the sanitised
// input against the float64 bloom ideal, and bad inputs are errors naming what is wrong.

#include <cmath>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>

#include "bench/accuracy/AccuracyMetrics.h"
#include "io/image/ImageIO.h"
#include "reference/IdealBloom.h"
#include "reference/StageInput.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/JsonValue.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

class CliBenchGLTest : public GlTest {};

const char* kStage = R"(<?xml version="1.0" encoding="UTF-8"?>
<workspace version="1" name="standin_bloom">
  <float name="Bloom_Threshold" value="1"/>
  <float name="Bloom_Strength" value="0.5"/>
  <float name="Bloom_Sigma" value="0.03125"/>
  <float name="Gain" value="1"/>
  <texture name="Input" file="placeholder.exr" mipmaps="false"/>
  <target name="result" format="rgba32f" scale="1"/>
  <code name="clean.glsl"><![CDATA[
uniform sampler2D Input;
vec3 clean(ivec2 p) {
    vec3 v = texelFetch(Input, clamp(p, ivec2(0), textureSize(Input, 0) - 1), 0).rgb;
    bvec3 bad = bvec3(isnan(v.r) || isinf(v.r), isnan(v.g) || isinf(v.g), isnan(v.b) || isinf(v.b));
    vec3 inside = vec3(all(greaterThanEqual(p, ivec2(0))) && all(lessThan(p, textureSize(Input, 0))));
    return mix(max(v, 0.0), vec3(0.0), vec3(bad)) * inside;
}
]]></code>
  <pass name="copy" target="result">
    <sampler name="Input" texture="Input"/>
    <shader stage="fragment"><![CDATA[
#include "clean.glsl"
out vec4 color;
void main() { color = vec4(clean(ivec2(gl_FragCoord.xy)), 1.0); }
]]></shader>
  </pass>
  <pass name="box" target="result">
    <sampler name="Input" texture="Input"/>
    <shader stage="fragment"><![CDATA[
#include "clean.glsl"
uniform float Bloom_Threshold, Bloom_Strength, Gain;
out vec4 color;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 sum = vec3(0.0);
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) sum += max(clean(p + ivec2(x, y)) - Bloom_Threshold, 0.0);
    color = vec4(clean(p) + Bloom_Strength * Gain * sum / 9.0, 1.0);
}
]]></shader>
  </pass>
  <effect name="copy" passes="copy"/>
  <effect name="box" passes="box"/>
  <output target="result" transform="none" effects="box"/>
</workspace>
)";

const char* kScene = R"(<?xml version="1.0" encoding="UTF-8"?>
<workspace version="1" name="tiny_scene">
  <target name="scene" format="rgba32f" scale="1"/>
  <pass name="draw" target="scene">
    <shader stage="fragment"><![CDATA[
out vec4 color;
void main() {
    vec2 p = gl_FragCoord.xy;
    color = vec4(0.02 * p.x, 0.03 * p.y, 0.2, 1.0) + (p.x < 6.0 && p.y < 4.0 ? vec4(20.0) : vec4(0.0));
}
]]></shader>
  </pass>
  <output target="scene" transform="none"/>
</workspace>
)";

const char* kManifest = R"(<bench-variants>
  <scene name="tiny" workspace="scene.xml" target="scene"/>
  <stage name="bloom" workspace="stage.xml" ideal="bloom" output="result">
    <axis effects="copy box" default="box" crossed="true"/>
    <axis variable="Gain" values="1 2" default="1"/>
  </stage>
</bench-variants>
)";

// What the stage workspace names as its input: the bench must replace it.
Image placeholder() { return Image{4, 4, 4, true, 32, std::vector<float>(4 * 4 * 4, 0.5f)}; }

Image testInput() {
    Image image{24, 16, 4, true, 32, std::vector<float>(24 * 16 * 4, 1.0f)};
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 24; ++x) {
            image.at(x, y, 0) = 0.05f * static_cast<float>(x);
            image.at(x, y, 1) = 0.1f * static_cast<float>(y);
            image.at(x, y, 2) = (x + y) % 5 == 0 ? 6.0f : 0.3f;
        }
    image.at(3, 2, 0) = std::numeric_limits<float>::quiet_NaN();
    image.at(5, 7, 1) = -2.0f;
    image.at(20, 12, 0) = 1000.0f;
    return image;
}

std::vector<std::string> csvLines(const std::filesystem::path& file) {
    std::vector<std::string> out;
    std::istringstream in(readText(file));
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

// The stand-in stage, scene, manifest, placeholder and input.exr (testInput) in `dir`.
void writeStandIn(const ScratchDir& dir) {
    dir.write("stage.xml", kStage);
    dir.write("scene.xml", kScene);
    dir.write("m.xml", kManifest);
    ASSERT_TRUE(writeImage(dir / "placeholder.exr", placeholder()));
    ASSERT_TRUE(writeImage(dir / "input.exr", testInput()));
}

TEST_F(CliBenchGLTest, MeasuresEveryVariantOnEveryInputAndWritesTheResultFiles) {
    ScratchDir dir;
    writeStandIn(dir);
    Image input = testInput();

    CommandResult cli =
        runRmfx("bench m.xml --input input.exr --size 32x32 --frames 2 --warmup 1 --time wall --out out", dir.path());
    ASSERT_EQ(cli.status, 0) << cli.err << cli.out;
    EXPECT_NE(cli.out.find("[6/6] input bloom box Gain=2: "), std::string::npos) << cli.out;
    EXPECT_TRUE(std::filesystem::exists(dir / "out/inputs/tiny.exr"));
    for (const char* f : {"accuracy.svg", "accuracy.md"}) EXPECT_GT(readText(dir / "out" / f).size(), 100u) << f;

    // CSV: a header, 2 inputs × 3 variants, and the 3 summary rows.
    std::vector<std::string> csv = csvLines(dir / "out/accuracy.csv");
    ASSERT_EQ(csv.size(), 10u);
    EXPECT_EQ(csv[0].rfind("input,stage,variant,effects,settings,frames,median_ms", 0), 0u);

    auto json = JsonReader::parse(readText(dir / "out/accuracy.json"));
    ASSERT_TRUE(json) << readText(dir / "out/accuracy.json");
    EXPECT_NE((*json)["device"].string.find("4.5"), std::string::npos);
    EXPECT_EQ((*json)["frames"].number, 2);
    EXPECT_EQ((*json)["warmup"].number, 1);
    EXPECT_EQ((*json)["ranked_time"].string, "wall");
    const auto& rows = (*json)["rows"].array;
    ASSERT_EQ(rows.size(), 9u);
    const JsonValue* copyOnInput = nullptr;
    for (const JsonValue& row : rows) {
        for (const char* key : {"median_ms", "p10_ms", "p90_ms", "min_ms", "max_ms", "max_rel_error", "mean_rel_error",
                                "wall_median_ms", "wall_p10_ms", "wall_p90_ms"}) {
            ASSERT_EQ(row[key].kind, JsonValue::Kind::Number) << key << " of " << row["variant"].string;
            EXPECT_TRUE(std::isfinite(row[key].number)) << key;
        }
        EXPECT_GT(row["median_ms"].number, 0.0);
        EXPECT_GT(row["wall_median_ms"].number, 0.0);
        EXPECT_LE(row["p10_ms"].number, row["p90_ms"].number);
        EXPECT_EQ(row["frames"].number, 2);
        EXPECT_TRUE(row["psnr_db"].kind == JsonValue::Kind::Null || std::isfinite(row["psnr_db"].number));
        if (row["input"].string == "input" && row["variant"].string == "copy") copyOnInput = &row;
    }
    ASSERT_NE(copyOnInput, nullptr);
    EXPECT_EQ((*copyOnInput)["settings"].string, "Gain=1");

    // The copy variant outputs the sanitised input: its error is that of S against S + ½ G*B.
    RefImage s = sanitisedInput(input);
    accuracy::ErrorMetrics expected = accuracy::imageStageMetrics(s, idealBloom(s, {1.0, 0.5, 0.03125}));
    EXPECT_GT(expected.meanRelative, 1e-3);
    EXPECT_NEAR((*copyOnInput)["mean_rel_error"].number, expected.meanRelative, 1e-7 * expected.meanRelative);
    EXPECT_NEAR((*copyOnInput)["max_rel_error"].number, expected.maxRelative, 1e-7 * expected.maxRelative);
    EXPECT_NEAR((*copyOnInput)["psnr_db"].number, expected.psnrDb, 1e-6);
}

TEST_F(CliBenchGLTest, BadInputsAndStagesAreErrorsNamingThem) {
    ScratchDir dir;
    writeStandIn(dir);

    CommandResult missing = runRmfx("bench m.xml --no-scenes --input nothing.exr --frames 1", dir.path());
    EXPECT_EQ(missing.status, 1);
    EXPECT_NE(missing.err.find("rmfx bench: input 'nothing': nothing.exr: no such file"), std::string::npos) << missing.err;

    CommandResult stage = runRmfx("bench m.xml --no-scenes --input input.exr --stage glow", dir.path());
    EXPECT_EQ(stage.status, 1);
    EXPECT_NE(stage.err.find("--stage glow: m.xml has no such stage (it has: bloom)"), std::string::npos) << stage.err;

    // A stage workspace without the texture the bench replaces.
    std::string noInput = kStage;
    noInput.replace(noInput.find("name=\"Input\""), 12, "name=\"Other\"");
    dir.write("stage.xml", noInput);
    CommandResult broken = runRmfx("bench m.xml --no-scenes --input input.exr --frames 1 --variant copy", dir.path());
    EXPECT_NE(broken.status, 0);
    EXPECT_NE(broken.err.find("stage.xml"), std::string::npos) << broken.err;
}

}  // namespace
}  // namespace rmfx::test
