// The replay manifest parser: the model of a valid manifest, and every error with its exact
// text and line.

#include "frontend/replay/ReplayManifest.h"

#include <gtest/gtest.h>

#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

const std::string kPath = "ci/replay.xml";
const std::string at = kPath + ":";
using Lines = std::vector<std::string>;
using test::lines;

Result<ReplayManifest> parse(const std::string& text) { return parseReplayManifestText(text, kPath, "ci"); }

// A manifest whose body starts on line 2.
std::string manifest(std::initializer_list<std::string> body) {
    std::string out = "<replay version=\"1\">\n";
    for (const std::string& l : body) out += l + "\n";
    return out + "</replay>\n";
}

std::vector<std::string> errorsOf(const std::string& text) {
    Result<ReplayManifest> p = parse(text);
    EXPECT_FALSE(p.ok());
    std::vector<std::string> out;
    for (const Diagnostic& d : p.diagnostics()) out.push_back(d.format());
    return out;
}

ReplayManifest parsedOk(const std::string& text) {
    Result<ReplayManifest> p = parse(text);
    EXPECT_EQ(formatAll(p.diagnostics()), "");
    EXPECT_TRUE(p.ok());
    return (p ? *p : ReplayManifest{});
}

// A case with one valid compare, for tests about other elements (lines: case, compare, </case>).
const std::string kCompare = "    <compare reference=\"refs/a.exr\"/>";

TEST(ReplayManifest, FullManifest) {
    ReplayManifest m = parsedOk(manifest({
        "  <defaults size=\"64x32\" frames=\"3\" dt=\"0.5\" error=\"relative\" floor=\"0.25\" mean=\"0.125\" store=\"half\"/>",
        "  <case name=\"glare-1.a\" workspace=\"../effects/glare.xml\" size=\"16x8\">",
        "    <set name=\"Exposure_Level\" value=\"0.5\"/>",
        "    <set name=\"Sun_Direction\" value=\"0 1 0\"/>",
        "    <compare reference=\"refs/glare.exr\" error=\"absolute\" max=\"0.02\" pixel=\"0.01\" fail-fraction=\"0.001\"/>",
        "    <compare target=\"bloom\" reference=\"refs/../refs/bloom.exr\" store=\"float\"/>",
        "  </case>",
        "  <case name=\"plain\" workspace=\"/abs/plain.xml\" frames=\"1\" dt=\"0\">",
        "    <compare reference=\"plain.exr\" pixel=\"0.5\"/>",
        "  </case>",
    }));
    EXPECT_EQ(m.path, kPath);
    ASSERT_EQ(m.cases.size(), 2u);

    const ReplayCase& a = m.cases[0];
    EXPECT_EQ(a.name, "glare-1.a");
    EXPECT_EQ(a.where.line, 3);
    EXPECT_EQ(a.workspaceText, "../effects/glare.xml");
    EXPECT_EQ(a.workspace, std::filesystem::path("effects/glare.xml"));  // ci/../effects/glare.xml, normalised
    EXPECT_EQ(a.run.size, glm::ivec2(16, 8));  // its own size over the default
    EXPECT_EQ(a.run.frames, 3);                // the defaults'
    EXPECT_EQ(a.run.deltaTime, 0.5f);
    ASSERT_EQ(a.sets.size(), 2u);
    EXPECT_EQ(a.sets[1].name, "Sun_Direction");
    EXPECT_EQ(a.sets[1].value, "0 1 0");
    EXPECT_EQ(a.sets[1].where.line, 5);
    EXPECT_EQ(a.overrides(), (std::vector<std::pair<std::string, std::string>>{{"Exposure_Level", "0.5"},
                                                                                {"Sun_Direction", "0 1 0"}}));
    ASSERT_EQ(a.compares.size(), 2u);

    const ReplayCompare& output = a.compares[0];
    EXPECT_EQ(output.target, "");
    EXPECT_EQ(output.label(), "output");
    EXPECT_EQ(output.reference, std::filesystem::path("ci/refs/glare.exr"));
    EXPECT_EQ(output.limits.metric, ErrorMetric::Absolute);
    EXPECT_EQ(output.limits.max, 0.02f);
    EXPECT_EQ(output.limits.mean, 0.125f);  // the defaults'
    EXPECT_EQ(output.limits.pixel, 0.01f);
    EXPECT_EQ(output.limits.failFraction, 0.001f);
    EXPECT_TRUE(output.storeHalf);

    const ReplayCompare& bloom = a.compares[1];
    EXPECT_EQ(bloom.label(), "bloom");
    EXPECT_EQ(bloom.referenceText, "refs/../refs/bloom.exr");
    EXPECT_EQ(bloom.reference, std::filesystem::path("ci/refs/bloom.exr"));  // normalised
    EXPECT_EQ(bloom.limits.metric, ErrorMetric::Relative);
    EXPECT_EQ(bloom.limits.floor, 0.25f);
    EXPECT_EQ(bloom.limits.max, std::nullopt);
    EXPECT_EQ(bloom.limits.mean, 0.125f);
    EXPECT_FALSE(bloom.storeHalf);

    const ReplayCase& plain = m.cases[1];
    EXPECT_EQ(plain.workspace, std::filesystem::path("/abs/plain.xml"));
    EXPECT_EQ(plain.run.size, glm::ivec2(64, 32));
    EXPECT_EQ(plain.run.frames, 1);
    EXPECT_EQ(plain.run.deltaTime, 0.0f);
    EXPECT_EQ(plain.compares[0].limits.pixel, 0.5f);
    EXPECT_EQ(plain.compares[0].limits.failFraction, 0.0);
    EXPECT_EQ(m.findCase("plain"), &m.cases[1]);
    EXPECT_EQ(m.findCase("glare"), nullptr);
}

TEST(ReplayManifest, WithoutDefaultsOrLimitsTheImagesMustBeEqual) {
    ReplayManifest m = parsedOk(manifest({"  <case name=\"a\" workspace=\"a.xml\">", kCompare, "  </case>"}));
    const ReplayCase& c = m.cases.at(0);
    EXPECT_EQ(c.run.size, glm::ivec2(0, 0));  // the workspace's own size
    EXPECT_EQ(c.run.frames, 1);
    EXPECT_EQ(c.run.deltaTime, 1.0f / 60.0f);
    const CompareLimits& l = c.compares.at(0).limits;
    EXPECT_EQ(l.metric, ErrorMetric::Absolute);
    EXPECT_EQ(l.max, 0.0);
    EXPECT_EQ(l.mean, std::nullopt);
    EXPECT_EQ(l.pixel, std::nullopt);
    EXPECT_EQ(l.floor, 1e-3);
    EXPECT_FALSE(c.compares[0].storeHalf);
    // A mean limit alone is the only limit.
    ReplayManifest mean = parsedOk(manifest(
        {"  <case name=\"a\" workspace=\"a.xml\">", "    <compare reference=\"a.exr\" mean=\"0.5\"/>", "  </case>"}));
    EXPECT_EQ(mean.cases.at(0).compares.at(0).limits.max, std::nullopt);
    EXPECT_EQ(mean.cases.at(0).compares.at(0).limits.mean, 0.5);
}

TEST(ReplayManifest, DefaultsMayFollowTheCases) {
    ReplayManifest m = parsedOk(manifest({"  <case name=\"a\" workspace=\"a.xml\">", kCompare, "  </case>",
                                          "  <defaults frames=\"7\" max=\"0.25\"/>"}));
    EXPECT_EQ(m.cases.at(0).run.frames, 7);
    EXPECT_EQ(m.cases.at(0).compares.at(0).limits.max, 0.25);
}

// ---- the document ----

TEST(ReplayManifest, MalformedXmlWrongRootAndVersion) {
    EXPECT_EQ(errorsOf(lines({"<replay version=\"1\">", "  <case name=\"a\" workspace=\"a.xml\">", "</replay>"})),
              (Lines{at + "2: error: malformed XML: <case> is not closed (its end tag is missing, misspelled or out "
                          "of order)"}));
    EXPECT_EQ(errorsOf(lines({"<?xml version=\"1.0\"?>", "<workspace version=\"1\"/>"})),
              (Lines{at + "2: error: the root element must be <replay>, not <workspace>"}));
    EXPECT_EQ(errorsOf(lines({"<replay version=\"2\">", "  <case name=\"a\" workspace=\"a.xml\">", kCompare,
                              "  </case>", "</replay>"})),
              (Lines{at + "1: error: <replay>: unsupported version '2': this rmfx reads version 1"}));
    EXPECT_EQ(errorsOf(lines({"<replay>", "  <case name=\"a\" workspace=\"a.xml\">", kCompare, "  </case>", "</replay>"})),
              (Lines{at + "1: error: <replay>: missing attribute 'version'"}));
    EXPECT_EQ(errorsOf(lines({"<replay version=\"1\"/>", "<replay version=\"1\"/>"})),
              (Lines{at + "2: error: <replay> after </replay>: a file holds one <replay>"}));
}

TEST(ReplayManifest, NothingToReplay) {
    EXPECT_EQ(errorsOf(manifest({"  <defaults frames=\"2\"/>"})),
              (Lines{at + "1: error: <replay>: no <case>: nothing to replay"}));
    EXPECT_EQ(errorsOf(manifest({"  <case name=\"a\" workspace=\"a.xml\">", "    <set name=\"x\" value=\"1\"/>",
                                 "  </case>"})),
              (Lines{at + "2: error: <case name=\"a\">: no <compare>: the case checks nothing"}));
}

TEST(ReplayManifest, UnknownElements) {
    EXPECT_EQ(errorsOf(manifest({"  <case name=\"a\" workspace=\"a.xml\">", kCompare, "  </case>", "  <cases/>"})),
              (Lines{at + "5: error: unknown element <cases> in <replay> (expected defaults, media, case)"}));
    EXPECT_EQ(errorsOf(manifest({"  <case name=\"a\" workspace=\"a.xml\">", "    <sett name=\"x\" value=\"1\"/>",
                                 kCompare, "  </case>"})),
              (Lines{at + "3: error: unknown element <sett> in <case name=\"a\"> (expected set, input, compare)"}));
    EXPECT_EQ(errorsOf(manifest({"  <defaults>", "    <case/>", "  </defaults>", "  <case name=\"a\" workspace=\"a.xml\">",
                                 "    <compare reference=\"a.exr\">", "      <limit/>", "    </compare>",
                                 "    <set name=\"x\" value=\"1\"><value/></set>", "  </case>"})),
              (Lines{at + "3: error: unknown element <case> in <defaults> (it takes no child elements)",
                     at + "7: error: unknown element <limit> in <compare> (it takes no child elements)",
                     at + "9: error: unknown element <value> in <set> (it takes no child elements)"}));
}

// <input>: the user's own image for a case, as rmfx render --input gives it.
TEST(ReplayManifest, InputsNameAFileBesideTheManifest) {
    ReplayManifest m = parsedOk(manifest({"  <case name=\"a\" workspace=\"a.xml\">",
                                          "    <input file=\"shots/one.exr\"/>",
                                          "    <input name=\"env\" file=\"../sky.exr:ViewLayer.Combined\"/>", kCompare,
                                          "  </case>"}));
    ASSERT_EQ(m.cases.size(), 1u);
    const std::vector<ReplayInput>& inputs = m.cases[0].inputs;
    ASSERT_EQ(inputs.size(), 2u);
    EXPECT_EQ(inputs[0].name, "");
    EXPECT_EQ(inputs[0].file, (m.folder / "shots/one.exr").lexically_normal());
    EXPECT_EQ(inputs[0].where.line, 3);
    EXPECT_EQ(inputs[0].label(), "<input file=\"shots/one.exr\">");
    EXPECT_EQ(inputs[1].name, "env");
    EXPECT_EQ(inputs[1].file, (m.folder / "../sky.exr:ViewLayer.Combined").lexically_normal());
    EXPECT_EQ(inputs[1].label(), "<input name=\"env\" file=\"../sky.exr:ViewLayer.Combined\">");

    EXPECT_EQ(errorsOf(manifest({"  <case name=\"a\" workspace=\"a.xml\">", "    <input name=\"scene\" file=\"a.exr\"/>",
                                 "    <input name=\"scene\" file=\"b.exr\"/>", "    <input/>", kCompare, "  </case>"})),
              (Lines{at + "4: error: <input name=\"scene\">: input 'scene' is already given at line 3",
                     at + "5: error: <input>: missing attribute 'file'"}));
}

TEST(ReplayManifest, CheckIsAYesOrNoOfTheCase) {
    ReplayManifest m = parsedOk(manifest({"  <case name=\"a\" workspace=\"a.xml\" check=\"true\">", kCompare, "  </case>",
                                          "  <case name=\"b\" workspace=\"a.xml\">", "    <compare reference=\"refs/b.exr\"/>", "  </case>"}));
    ASSERT_EQ(m.cases.size(), 2u);
    EXPECT_TRUE(m.cases[0].check);
    EXPECT_FALSE(m.cases[1].check);
    std::vector<std::string> errors = errorsOf(manifest({"  <case name=\"a\" workspace=\"a.xml\" check=\"maybe\">", kCompare, "  </case>"}));
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].rfind(at + "2: error: <case name=\"a\">: attribute 'check'", 0), 0u) << errors[0];
}

TEST(ReplayManifest, UnknownAttributesListTheKnownOnes) {
    EXPECT_EQ(
        errorsOf(manifest({"  <defaults size=\"8x8\" tolerance=\"1\"/>",
                           "  <case name=\"a\" workspace=\"a.xml\" frame=\"2\">",
                           "    <set name=\"x\" val=\"1\"/>", "    <compare reference=\"a.exr\" output=\"output\"/>",
                           "  </case>"})),
        (Lines{at + "2: error: <defaults>: unknown attribute 'tolerance' (expected one of: size, frames, dt, error, "
                    "floor, luminance, max, mean, percentile, percentile-max, pixel, fail-fraction, store)",
               at + "3: error: <case name=\"a\">: unknown attribute 'frame' (expected one of: name, workspace, size, "
                    "frames, dt, effects, check)",
               at + "4: error: <set name=\"x\">: unknown attribute 'val' (expected one of: name, value)",
               at + "4: error: <set name=\"x\">: missing attribute 'value'",
               at + "5: error: <compare>: unknown attribute 'output' (expected one of: target, reference, error, "
                    "floor, luminance, max, mean, percentile, percentile-max, pixel, fail-fraction, store)"}));
}

TEST(ReplayManifest, MissingRequiredAttributes) {
    EXPECT_EQ(errorsOf(manifest({"  <case workspace=\"a.xml\">", kCompare, "  </case>", "  <case name=\"b\">",
                                 "    <compare reference=\"b.exr\"/>",
                                 "  </case>", "  <case name=\"c\" workspace=\"c.xml\">", "    <compare/>",
                                 "    <set value=\"1\"/>", "  </case>"})),
              (Lines{at + "2: error: <case>: missing attribute 'name'",
                     at + "5: error: <case name=\"b\">: missing attribute 'workspace'",
                     at + "9: error: <compare>: missing attribute 'reference'",
                     at + "10: error: <set>: missing attribute 'name'"}));
}

TEST(ReplayManifest, CaseNamesAreFolderNamesAndUnique) {
    EXPECT_EQ(errorsOf(manifest({"  <case name=\"a/b\" workspace=\"a.xml\">", kCompare, "  </case>"})),
              (Lines{at + "2: error: <case name=\"a/b\">: attribute 'name': 'a/b' is not a valid case name (letters, "
                          "digits, '_', '-' and '.', not starting with '.' or '-': it names a folder of the output)"}));
    EXPECT_EQ(errorsOf(manifest({"  <case name=\"..\" workspace=\"a.xml\">", kCompare, "  </case>"})).size(), 1u);
    EXPECT_EQ(errorsOf(manifest({"  <case name=\"a\" workspace=\"a.xml\">", kCompare, "  </case>",
                                 "  <case name=\"a\" workspace=\"b.xml\">", "    <compare reference=\"b.exr\"/>",
                                 "  </case>"})),
              (Lines{at + "5: error: <case name=\"a\">: case 'a' is already defined at line 2"}));
}

TEST(ReplayManifest, RunSettings) {
    EXPECT_EQ(errorsOf(manifest({"  <defaults size=\"64\" dt=\"-1\"/>",
                                 "  <case name=\"a\" workspace=\"a.xml\" frames=\"0\" size=\"0x4\">", kCompare,
                                 "  </case>", "  <case name=\"b\" workspace=\"b.xml\" frames=\"2000000\" dt=\"x\">",
                                 "    <compare reference=\"b.exr\"/>", "  </case>"})),
              (Lines{at + "2: error: <defaults>: attribute 'size': expected WIDTHxHEIGHT such as 128x128, got '64'",
                     at + "2: error: <defaults>: attribute 'dt' must be ≥ 0, got '-1'",
                     at + "3: error: <case name=\"a\">: attribute 'size': expected WIDTHxHEIGHT such as 128x128, got "
                          "'0x4'",
                     at + "3: error: <case name=\"a\">: attribute 'frames': expected an integer ≥ 1, got '0'",
                     at + "6: error: <case name=\"b\">: attribute 'frames': expected a count from 1 to 1000000, got "
                          "'2000000'",
                     at + "6: error: <case name=\"b\">: attribute 'dt': expected a number, got 'x'"}));
}

TEST(ReplayManifest, Limits) {
    EXPECT_EQ(
        errorsOf(manifest({"  <case name=\"a\" workspace=\"a.xml\">",
                           "    <compare reference=\"1.exr\" error=\"squared\" max=\"-0.5\" mean=\"x\"/>",
                           "    <compare target=\"t2\" reference=\"2.exr\" floor=\"0.1\"/>",
                           "    <compare target=\"t3\" reference=\"3.exr\" error=\"relative\" floor=\"0\"/>",
                           "    <compare target=\"t4\" reference=\"4.exr\" pixel=\"0.1\" fail-fraction=\"1.5\"/>",
                           "    <compare target=\"t5\" reference=\"5.exr\" fail-fraction=\"0.5\"/>",
                           "    <compare target=\"t6\" reference=\"6.exr\" store=\"double\"/>", "  </case>"})),
        (Lines{at + "3: error: <compare>: attribute 'error': 'squared' is not one of: absolute, relative, itp",
               at + "3: error: <compare>: attribute 'max' must be ≥ 0, got '-0.5'",
               at + "3: error: <compare>: attribute 'mean': expected a number, got 'x'",
               at + "4: error: <compare>: attribute 'floor' applies to error=\"relative\"",
               at + "5: error: <compare>: attribute 'floor' must be greater than 0, got '0'",
               at + "6: error: <compare>: attribute 'fail-fraction' must lie in [0, 1], got '1.5'",
               at + "7: error: <compare>: 'fail-fraction' needs a 'pixel' threshold (on the <compare> or in <defaults>)",
               at + "8: error: <compare>: attribute 'store': 'double' is not one of: float, half"}));
    // fail-fraction in <defaults> with pixel on the compare is fine; a floor there applies only
    // to relative compares.
    parsedOk(manifest({"  <defaults fail-fraction=\"0.5\" floor=\"0.5\"/>", "  <case name=\"a\" workspace=\"a.xml\">",
                       "    <compare reference=\"a.exr\" pixel=\"0.1\"/>", "  </case>"}));
}

TEST(ReplayManifest, ItpComparesWithLuminanceAndPercentile) {
    ReplayManifest m = parsedOk(manifest({
        "  <defaults error=\"itp\" luminance=\"203\" percentile=\"99\"/>",
        "  <case name=\"a\" workspace=\"a.xml\">",
        "    <compare reference=\"a.exr\" percentile-max=\"1.5\" mean=\"0.5\"/>",
        "    <compare target=\"t\" reference=\"t.exr\" luminance=\"1000\" percentile=\"99.9\" percentile-max=\"2\"/>",
        "    <compare target=\"u\" reference=\"u.exr\" error=\"absolute\" max=\"0.1\"/>",
        "    <compare target=\"v\" reference=\"v.exr\" error=\"relative\" percentile-max=\"0.25\"/>",
        "  </case>",
    }));
    const ReplayCase& c = m.cases.at(0);
    const CompareLimits& a = c.compares.at(0).limits;
    EXPECT_EQ(a.metric, ErrorMetric::Itp);
    EXPECT_EQ(a.luminance, 203.0);
    ASSERT_TRUE(a.percentile);
    EXPECT_EQ(a.percentile->percentile, 99.0);
    EXPECT_EQ(a.percentile->max, 1.5);
    EXPECT_EQ(a.mean, 0.5);
    EXPECT_EQ(a.max, std::nullopt);  // a percentile is a limit: not "equal images"
    const CompareLimits& t = c.compares.at(1).limits;
    EXPECT_EQ(t.luminance, 1000.0);
    ASSERT_TRUE(t.percentile);
    EXPECT_EQ(t.percentile->percentile, 99.9f);
    EXPECT_EQ(t.percentile->max, 2.0);
    // The defaults' luminance is for itp compares; their percentile alone limits nothing, and
    // with a percentile-max it limits any metric.
    const CompareLimits& u = c.compares.at(2).limits;
    EXPECT_EQ(u.metric, ErrorMetric::Absolute);
    EXPECT_EQ(u.max, 0.1f);
    EXPECT_EQ(u.percentile, std::nullopt);
    const CompareLimits& v = c.compares.at(3).limits;
    EXPECT_EQ(v.metric, ErrorMetric::Relative);
    ASSERT_TRUE(v.percentile);
    EXPECT_EQ(v.percentile->percentile, 99.0);
    EXPECT_EQ(v.percentile->max, 0.25);
    EXPECT_EQ(v.max, std::nullopt);

    // Without a luminance, 1.0 is 100 cd/m².
    ReplayManifest plain = parsedOk(manifest(
        {"  <case name=\"a\" workspace=\"a.xml\">", "    <compare reference=\"a.exr\" error=\"itp\"/>", "  </case>"}));
    const CompareLimits& p = plain.cases.at(0).compares.at(0).limits;
    EXPECT_EQ(p.luminance, 100.0);
    EXPECT_EQ(p.max, 0.0);
    EXPECT_EQ(p.percentile, std::nullopt);
}

TEST(ReplayManifest, ItpErrors) {
    EXPECT_EQ(
        errorsOf(manifest({"  <defaults luminance=\"-1\"/>",
                           "  <case name=\"a\" workspace=\"a.xml\">",
                           "    <compare reference=\"1.exr\" error=\"ITP\"/>",
                           "    <compare target=\"t2\" reference=\"2.exr\" error=\"itp\" floor=\"0.1\"/>",
                           "    <compare target=\"t3\" reference=\"3.exr\" luminance=\"100\"/>",
                           "    <compare target=\"t4\" reference=\"4.exr\" error=\"itp\" luminance=\"0\"/>",
                           "    <compare target=\"t5\" reference=\"5.exr\" percentile=\"0\" percentile-max=\"1\"/>",
                           "    <compare target=\"t6\" reference=\"6.exr\" percentile=\"100.5\" percentile-max=\"-1\"/>",
                           "    <compare target=\"t7\" reference=\"7.exr\" error=\"itp\" percentile=\"99\"/>",
                           "    <compare target=\"t8\" reference=\"8.exr\" error=\"itp\" percentile-max=\"1\"/>",
                           "  </case>"})),
        (Lines{at + "2: error: <defaults>: attribute 'luminance' must be greater than 0, got '-1'",
               at + "4: error: <compare>: attribute 'error': 'ITP' is not one of: absolute, relative, itp",
               at + "5: error: <compare>: attribute 'floor' applies to error=\"relative\"",
               at + "6: error: <compare>: attribute 'luminance' applies to error=\"itp\"",
               at + "7: error: <compare>: attribute 'luminance' must be greater than 0, got '0'",
               at + "8: error: <compare>: attribute 'percentile' must lie in (0, 100], got '0'",
               at + "9: error: <compare>: attribute 'percentile' must lie in (0, 100], got '100.5'",
               at + "9: error: <compare>: attribute 'percentile-max' must be ≥ 0, got '-1'",
               at + "10: error: <compare>: 'percentile' needs a 'percentile-max' limit (on the <compare> or in <defaults>)",
               at + "11: error: <compare>: 'percentile-max' needs a 'percentile' (on the <compare> or in <defaults>)"}));
}

TEST(ReplayManifest, CompareTargetsAndReferences) {
    EXPECT_EQ(errorsOf(manifest({"  <case name=\"a\" workspace=\"a.xml\">",
                                 "    <compare target=\"2x\" reference=\"a.exr\"/>",
                                 "    <compare reference=\"a.png\"/>", "    <compare reference=\"b.exr\"/>",
                                 "    <compare target=\"output\" reference=\"c.exr\"/>",
                                 "    <compare target=\"bloom\" reference=\"refs/../b.exr\"/>", "  </case>"})),
              (Lines{at + "3: error: <compare>: attribute 'target': '2x' is not a valid name (letters, digits and '_', "
                          "not starting with a digit)",
                     at + "4: error: <compare>: attribute 'reference': 'a.png' is not an OpenEXR file: references are "
                          ".exr files, which keep the render's float values",
                     at + "6: error: <compare>: a second <compare> of 'output' in case 'a' (the first is at line 5)",
                     at + "7: error: <compare>: reference 'refs/../b.exr' is already the reference of the <compare> at "
                          "line 5: --update would write one over the other"}));
}

TEST(ReplayManifest, SetsAndDefaults) {
    EXPECT_EQ(errorsOf(manifest({"  <defaults frames=\"2\"/>", "  <case name=\"a\" workspace=\"a.xml\">",
                                 "    <set name=\"x\" value=\"1\"/>", "    <set name=\"x\" value=\"2\"/>", kCompare,
                                 "  </case>", "  <defaults frames=\"3\"/>"})),
              (Lines{at + "5: error: <set name=\"x\">: variable 'x' is already set at line 4",
                     at + "8: error: <defaults>: a second <defaults> (the first is at line 2): a manifest has one"}));
}

TEST(ReplayManifest, ReadsFilesAndResolvesInTheirFolder) {
    test::ScratchDir dir;
    auto file = dir.write("sub/replay.xml", manifest({"  <case name=\"a\" workspace=\"fx/a.xml\">", kCompare, "  </case>"}));
    Result<ReplayManifest> p = parseReplayManifestFile(file);
    ASSERT_TRUE(p.ok()) << formatAll(p.diagnostics());
    EXPECT_EQ(p->folder, dir / "sub");
    EXPECT_EQ(p->cases.at(0).workspace, dir / "sub" / "fx/a.xml");
    EXPECT_EQ(p->cases.at(0).compares.at(0).reference, dir / "sub" / "refs/a.exr");

    Result<ReplayManifest> missing = parseReplayManifestFile(dir / "none.xml");
    EXPECT_FALSE(missing.ok());
    EXPECT_EQ(formatAll(missing.diagnostics()), (dir / "none.xml").string() + ": error: the file does not exist\n");
}

}  // namespace
}  // namespace rmfx

namespace rmfx {
namespace {

TEST(ReplayManifest, EffectsOfACaseAreAList) {
    ReplayManifest m = parsedOk(manifest({
        "  <case name=\"some\" workspace=\"a.xml\" effects=\"glare, streak ghost\">",
        "    <compare reference=\"refs/some.exr\"/>",
        "  </case>",
        "  <case name=\"none\" workspace=\"a.xml\" effects=\"\">",
        "    <compare reference=\"refs/none.exr\"/>",
        "  </case>",
        "  <case name=\"default\" workspace=\"a.xml\">",
        kCompare,
        "  </case>",
    }));
    ASSERT_EQ(m.cases.size(), 3u);
    EXPECT_EQ(m.cases[0].effects, (std::vector<std::string>{"glare", "streak", "ghost"}));
    EXPECT_EQ(m.cases[1].effects, std::vector<std::string>{});
    EXPECT_FALSE(m.cases[2].effects.has_value());
}

TEST(ReplayManifest, SandboxIsOnUnlessTheManifestTurnsItOff) {
    ReplayManifest on = parsedOk(manifest({"  <case name=\"a\" workspace=\"a.xml\">", kCompare, "  </case>"}));
    EXPECT_TRUE(on.media.sandbox);
    EXPECT_TRUE(on.media.searchPath.empty());
    Result<ReplayManifest> off = parse("<replay version=\"1\" sandbox=\"false\">\n  <case name=\"a\" workspace=\"a.xml\">\n" +
                               kCompare + "\n  </case>\n</replay>\n");
    ASSERT_TRUE(off.ok()) << formatAll(off.diagnostics());
    EXPECT_FALSE(off->media.sandbox);
    EXPECT_EQ(formatAll(parse("<replay version=\"1\" sandbox=\"maybe\">\n  <case name=\"a\" workspace=\"a.xml\">\n" +
                              kCompare + "\n  </case>\n</replay>\n")
                            .diagnostics())
                  .find(at + "1: error: <replay>:"),
              0u);
}

TEST(ReplayManifest, MediaFoldersResolveInTheManifestFolderAndMustExist) {
    test::ScratchDir dir;
    std::filesystem::create_directories(dir / "samples/media");
    auto file = dir.write("ci/replay.xml", manifest({"  <media dir=\"../samples/media\"/>", "  <case name=\"a\" workspace=\"a.xml\">",
                                                     kCompare, "  </case>", "  <media dir=\".\"/>"}));
    Result<ReplayManifest> p = parseReplayManifestFile(file);
    ASSERT_TRUE(p.ok()) << formatAll(p.diagnostics());
    EXPECT_EQ(p->media.searchPath,
              (std::vector<std::filesystem::path>{dir / "samples/media", dir / "ci/"}));
    auto bad = dir.write("ci/bad.xml", manifest({"  <media dir=\"nowhere\"/>", "  <media/>", "  <case name=\"a\" workspace=\"a.xml\">",
                                                 kCompare, "  </case>"}));
    Result<ReplayManifest> q = parseReplayManifestFile(bad);
    EXPECT_FALSE(q.ok());
    EXPECT_EQ(formatAll(q.diagnostics()), bad.string() + ":2: error: <media>: media folder 'nowhere' is not a folder (looked for " +
                                            (dir / "ci/nowhere").string() + ")\n" + bad.string() +
                                            ":3: error: <media>: missing attribute 'dir'\n");
}

}  // namespace
}  // namespace rmfx
