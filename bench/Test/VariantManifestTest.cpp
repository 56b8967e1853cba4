// The bench's manifest of variants (bench/accuracy/VariantManifest.h): parse errors name the file,
// line and element; variants are the cross product of the crossed axes plus each value of every
// other axis, without duplicates; and the repository's bench/variants.xml expands as documented.

#include <map>

#include <gtest/gtest.h>

#include "bench/accuracy/VariantManifest.h"
#include "tests/support/TestSupport.h"

namespace rmfx::accuracy {
namespace {

using test::lines;

std::string errorsOf(const std::string& text) {
    Result<VariantManifest> p = parseVariantManifestText(text, "m.xml");
    EXPECT_FALSE(p.ok());
    return formatAll(p.diagnostics());
}

const char* kStageOpen = R"(  <stage name="bloom" workspace="bloom.xml" ideal="bloom" output="result">)";

TEST(VariantManifest, ParsesScenesStagesAndAxes) {
    Result<VariantManifest> p = parseVariantManifestText(
        lines({"<bench-variants>",
               R"(  <scene name="a" file="in/a.exr"/>)",
               R"(  <scene name="b" workspace="w.xml" target="scene"/>)",
               kStageOpen,
               R"(    <axis effects="blur9 blur49" default="blur49" crossed="true"/>)",
               R"(    <axis variable="Downsample" values="0 1 2" labels="1/2 1/4 1/8" default="1/4"/>)",
               R"(    <axis name="pct" variables="Low High" values="0 1, 0.05 0.95" default="0 1" with="blur9"/>)",
               "  </stage>",
               "</bench-variants>"}),
        "dir/m.xml");
    ASSERT_TRUE(p.ok()) << formatAll(p.diagnostics());
    const VariantManifest& m = *p;
    ASSERT_EQ(m.scenes.size(), 2u);
    EXPECT_EQ(m.scenes[0].file, std::filesystem::path("dir/in/a.exr"));
    EXPECT_EQ(m.scenes[1].workspace, std::filesystem::path("dir/w.xml"));
    EXPECT_EQ(m.scenes[1].target, "scene");
    ASSERT_EQ(m.stages.size(), 1u);
    const StageSpec& s = m.stages[0];
    EXPECT_EQ(s.workspace, std::filesystem::path("dir/bloom.xml"));
    EXPECT_EQ(s.ideal, IdealKind::Bloom);
    ASSERT_EQ(s.axes.size(), 3u);
    EXPECT_EQ(s.axes[0].defaultIndex, 1u);
    EXPECT_EQ(s.axes[1].defaultIndex, 1u);  // by label
    EXPECT_EQ(s.axes[2].name, "pct");
    EXPECT_EQ(s.axes[2].values[1].words, (std::vector<std::string>{"0.05", "0.95"}));
    EXPECT_EQ(s.axes[2].values[1].label, "0.05 0.95");
}

TEST(VariantManifest, ErrorsNameFileLineAndElement) {
    EXPECT_EQ(errorsOf(lines({"<bench-variants>", R"(  <stage name="s" workspace="w.xml" output="o">)",
                              R"(    <axis effects="a"/>)", "  </stage>", "</bench-variants>"})),
              "m.xml:2: error: <stage name=\"s\">: missing attribute 'ideal' (bloom, streak, luminance or tonemap)\n"
              "m.xml:3: error: <axis>: missing attribute 'default'\n");
    EXPECT_NE(errorsOf(lines({"<bench-variants>", R"(  <stage name="s" workspace="w" ideal="glow" output="o">)",
                              R"(    <axis effects="a" default="a"/>)", "  </stage>", "</bench-variants>"}))
                  .find("m.xml:2: error: <stage name=\"s\">: attribute 'ideal': 'glow' is not one of: bloom, streak, "
                        "luminance, tonemap"),
              std::string::npos);
    EXPECT_EQ(errorsOf(lines({"<bench-variants>", kStageOpen, R"(    <axis effects="a b" default="c"/>)", "  </stage>",
                              "</bench-variants>"})),
              "m.xml:3: error: <axis>: attribute 'default': 'c' is not one of its values\n");
    EXPECT_EQ(errorsOf(lines({"<bench-variants>", kStageOpen, R"(    <axis effects="a" default="a"/>)",
                              R"(    <axis variables="Low High" values="0 1 2" default="0 1"/>)", "  </stage>",
                              "</bench-variants>"})),
              "m.xml:4: error: <axis>: value '0' has 1 words for 2 variables (Low High); separate values by commas\n");
    EXPECT_EQ(errorsOf(lines({"<bench-variants>", kStageOpen, R"(    <axis effects="a" default="a" colour="red"/>)",
                              "  </stage>", "</bench-variants>"})),
              "m.xml:3: error: <axis>: unknown attribute 'colour' (expected one of: name, effects, variable, "
              "variables, values, labels, default, crossed, with)\n");
    EXPECT_EQ(errorsOf(lines({"<bench-variants>", kStageOpen, R"(    <axis variable="X" values="1 2" default="1"/>)",
                              "  </stage>", "</bench-variants>"})),
              "m.xml:2: error: <stage name=\"bloom\">: needs exactly one <axis effects=\"…\"> (the stage's "
              "algorithms), found 0\n");
    EXPECT_EQ(errorsOf(lines({"<bench-variants>", kStageOpen, R"(    <axis effects="a b" default="a"/>)",
                              R"(    <axis variable="X" values="1 2" default="1" with="c"/>)", "  </stage>",
                              "</bench-variants>"})),
              "m.xml:4: error: <axis name=\"X\">: attribute 'with': 'c' is not one of the stage's effects (a, b)\n");
    EXPECT_EQ(errorsOf(lines({"<bench-variants>", R"(  <scene name="s" file="a.exr" workspace="w.xml"/>)", kStageOpen,
                              R"(    <axis effects="a" default="a"/>)", "  </stage>", "</bench-variants>"})),
              "m.xml:2: error: <scene name=\"s\">: give either file=\"IMAGE.exr\" or workspace=\"WORKSPACE.xml\" "
              "with target=\"TARGET\"\n");
    EXPECT_EQ(errorsOf(lines({"<bench-variants>", "  <stages/>", "</bench-variants>"})),
              "m.xml:2: error: unknown element <stages> in <bench-variants> (expected <scene> or <stage>)\n"
              "m.xml:1: error: <bench-variants>: no <stage>: the manifest names nothing to measure\n");
    EXPECT_EQ(formatAll(parseVariantManifestFile("no/such/variants.xml").diagnostics()),
              "no/such/variants.xml: error: the file does not exist\n");
}

StageSpec stageOf(const std::string& axes) {
    Result<VariantManifest> p = parseVariantManifestText(
        lines({"<bench-variants>", kStageOpen, axes, "  </stage>", "</bench-variants>"}), "m.xml");
    EXPECT_TRUE(p.ok()) << formatAll(p.diagnostics());
    return p ? p->stages[0] : StageSpec{};
}

std::vector<std::string> namesOf(const std::vector<Variant>& variants) {
    std::vector<std::string> names;
    for (const Variant& v : variants) names.push_back(v.name);
    return names;
}

TEST(VariantManifest, CrossedAxesMultiplyAndTheOthersAddTheirNonDefaultValues) {
    StageSpec s = stageOf(R"(<axis effects="g9 g49 kawase" default="kawase" crossed="true"/>
        <axis variable="Downsample" values="0 1" labels="1/2 1/4" default="1" crossed="true"/>
        <axis variable="Format" values="0 1 2" labels="f32 f16 rgbe" default="1"/>)");
    std::vector<Variant> v = expandVariants(s);
    ASSERT_EQ(v.size(), 3u * 2u + 2u);
    EXPECT_EQ(namesOf(v), (std::vector<std::string>{
                              "g9 Downsample=1/2", "g9 Downsample=1/4", "g49 Downsample=1/2", "g49 Downsample=1/4",
                              "kawase Downsample=1/2", "kawase Downsample=1/4", "kawase Downsample=1/4 Format=f32",
                              "kawase Downsample=1/4 Format=rgbe"}));
    EXPECT_EQ(v[0].effect, "g9");
    EXPECT_EQ(v[0].settingsText(), "Downsample=0 Format=1");
    EXPECT_EQ(v[7].settingsText(), "Downsample=1 Format=2");
}

TEST(VariantManifest, WithoutCrossedAxesEachValueOfEachAxisOnce) {
    StageSpec s = stageOf(R"(<axis effects="exact sampled histogram" default="exact"/>
        <axis name="pct" variables="Low High" values="0 1, 0.05 0.95" default="0 1" with="histogram"/>
        <axis variable="Bins" values="32 64" default="64" with="histogram"/>)");
    std::vector<Variant> v = expandVariants(s);
    EXPECT_EQ(namesOf(v), (std::vector<std::string>{"exact", "sampled", "histogram", "histogram pct=0.05 0.95",
                                                    "histogram Bins=32"}));
    EXPECT_EQ(v[3].settingsText(), "Low=0.05 High=0.95 Bins=64");
}

TEST(VariantManifest, TheRepositorysManifestParsesAndExpandsAsDocumented) {
    Result<VariantManifest> p = parseVariantManifestFile(test::sourceDir() / "bench/variants.xml");
    ASSERT_TRUE(p.ok()) << formatAll(p.diagnostics());
    std::map<std::string, size_t> counts;
    for (const StageSpec& s : p->stages) counts[s.name] = expandVariants(s).size();
    // bloom: 8 blurs × 3 downsample factors + 5 other formats; streak: 3 × 3 + 5; luminance:
    // 3 algorithms + 2 percentile pairs of the histogram; tone map: 4 curves + 5 formats.
    EXPECT_EQ(counts, (std::map<std::string, size_t>{{"bloom", 29}, {"streak", 14}, {"luminance", 5}, {"tonemap", 9}}));
    EXPECT_EQ(p->scenes.size(), 3u);
}

}  // namespace
}  // namespace rmfx::accuracy
