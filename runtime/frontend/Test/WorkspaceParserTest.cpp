#include "frontend/workspace/WorkspaceParser.h"

#include <gtest/gtest.h>

#include "io/mesh/BuiltinMeshes.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx {

namespace {

const std::string kPath = "fx/test.xml";

// A workspace whose body starts on line 2, followed by a pass (a workspace needs one).
std::string workspace(std::initializer_list<std::string> body) {
    std::string out = "<workspace version=\"1\">\n";
    for (const std::string& l : body) out += l + "\n";
    return out + "  <pass name=\"last\"/>\n</workspace>\n";
}

Result<Workspace> parse(const std::string& text) { return parseWorkspaceText(text, kPath, "fx"); }

std::vector<std::string> formatted(const Diagnostics& diagnostics) {
    std::vector<std::string> out;
    for (const Diagnostic& d : diagnostics) out.push_back(d.format());
    return out;
}

// The formatted diagnostics of text that must fail to parse.
std::vector<std::string> errorsOf(const std::string& text) {
    Result<Workspace> p = parse(text);
    EXPECT_FALSE(p.ok());
    return formatted(p.diagnostics());
}

// Text that must parse without any diagnostic.
Workspace parsedOk(const std::string& text) {
    Result<Workspace> p = parse(text);
    EXPECT_EQ(formatAll(p.diagnostics()), "");
    EXPECT_TRUE(p.ok());
    return (p ? *p : Workspace{});
}

using Lines = std::vector<std::string>;
using test::lines;
const std::string at = kPath + ":";

}  // namespace

// ---- the document ----

TEST(WorkspaceParser, MalformedXmlNamesTheLineOfTheError) {
    // tinyxml2 locates an unclosed element where it opens.
    auto d = errorsOf(lines({
        "<workspace version=\"1\">",
        "  <pass name=\"a\">",
        "    <shader stage=\"fragment\">",
        "  </pass>",
        "</workspace>",
    }));
    EXPECT_EQ(d, (Lines{at + "3: error: malformed XML: <shader> is not closed (its end tag is missing, misspelled or "
                             "out of order)"}));
}

TEST(WorkspaceParser, MalformedXmlSaysWhatIsWrong) {
    EXPECT_EQ(errorsOf(lines({"<workspace version=\"1\">", "", "  <float name=\"x\" value=0.5/>", "</workspace>"})),
              (Lines{at + "3: error: malformed XML: bad attribute in <float> (write name=\"value\", each name once)"}));
    EXPECT_EQ(errorsOf(lines({"<workspace version=\"1\">", "  <pass name=\"p\">", "  <!-- unfinished"})),
              (Lines{at + "3: error: malformed XML: <!-- without its closing -->"}));
    EXPECT_EQ(errorsOf(lines({"<workspace version=\"1\">", "  <code name=\"a\"><![CDATA[", "float x;"})),
              (Lines{at + "2: error: malformed XML: <![CDATA[ without its closing ]]>"}));
    EXPECT_EQ(errorsOf(lines({"<workspace version=\"1\">", "  <pass name=\"p\">"})),
              (Lines{at + "2: error: malformed XML: cannot read the document from here on (an element left open at "
                          "the end of the file?)"}));
    EXPECT_EQ(errorsOf(""), (Lines{kPath + ": error: malformed XML: the file has no element"}));
}

TEST(WorkspaceParser, OneWorkspacePerFile) {
    EXPECT_EQ(errorsOf(lines({"<workspace version=\"1\"><pass name=\"p\"/></workspace>", "", "<pass name=\"q\"/>"})),
              (Lines{at + "3: error: <pass> after </workspace>: a file holds one <workspace>"}));
}

TEST(WorkspaceParser, WrongRootElement) {
    auto d = errorsOf(lines({"<?xml version=\"1.0\"?>", "<effect version=\"1\"/>"}));
    EXPECT_EQ(d, (Lines{at + "2: error: the root element must be <workspace>, not <effect>"}));
}

TEST(WorkspaceParser, UnsupportedOrMissingVersion) {
    EXPECT_EQ(errorsOf(lines({"<?xml version=\"1.0\"?>", "<workspace version=\"2\">", "<pass name=\"p\"/>", "</workspace>"})),
              (Lines{at + "2: error: <workspace>: unsupported version '2': this rmfx reads version 1"}));
    EXPECT_EQ(errorsOf("<workspace name=\"x\"><pass name=\"p\"/></workspace>"),
              (Lines{at + "1: error: <workspace name=\"x\">: missing attribute 'version'"}));
}

TEST(WorkspaceParser, UnknownElementInWorkspace) {
    auto d = errorsOf(workspace({
        "  <float name=\"a\" value=\"1\"/>",
        "  <texure name=\"t\" file=\"t.png\"/>",
    }));
    EXPECT_EQ(d, (Lines{at + "3: error: unknown element <texure> in <workspace> (expected description, camera, code, "
                             "float, int, bool, vec2, vec3, vec4, color, mat4, texture, cubemap, volume, input, target, pass, effect, output)"}));
}

TEST(WorkspaceParser, AnEffectsSourceAndItsChannels) {
    Workspace ws = parsedOk(workspace({
        "  <effect name=\"glow\" passes=\"last\" source=\"bright\" source-channels=\"rg\"/>",
    }));
    ASSERT_EQ(ws.effects.size(), 1u);
    EXPECT_EQ(ws.effects[0].source, "bright");
    EXPECT_EQ(ws.effects[0].sourceChannels, glm::bvec4(true, true, false, false));
    Workspace plain = parsedOk(workspace({"  <effect name=\"glow\" passes=\"last\" source=\"bright\"/>"}));
    EXPECT_EQ(plain.effects[0].sourceChannels, glm::bvec4(true, true, true, false)) << "red, green and blue by default";
    EXPECT_EQ(errorsOf(workspace({"  <effect name=\"glow\" passes=\"last\" source-channels=\"rgb\"/>"})),
              (Lines{at + "2: error: <effect name=\"glow\">: attribute 'source-channels' applies with 'source'"}));
    EXPECT_EQ(errorsOf(workspace({"  <effect name=\"glow\" passes=\"last\" source=\"b\" source-channels=\"bgr\"/>"})),
              (Lines{at + "2: error: <effect name=\"glow\">: attribute 'source-channels': 'bgr' is not one of: r, rg, rgb, "
                          "rgba, a"}));
}

TEST(WorkspaceParser, AnEffectsGateAndItsChannels) {
    Workspace ws = parsedOk(workspace({
        "  <effect name=\"glow\" passes=\"last\" source=\"bright\" gate=\"bound\" gate-channels=\"r\"/>",
    }));
    ASSERT_EQ(ws.effects.size(), 1u);
    EXPECT_EQ(ws.effects[0].gate, "bound");
    EXPECT_EQ(ws.effects[0].gateChannels, glm::bvec4(true, false, false, false));
    EXPECT_EQ(ws.effects[0].sourceChannels, glm::bvec4(true, true, true, false)) << "the source's own channels are unchanged";
    Workspace plain = parsedOk(workspace({"  <effect name=\"glow\" passes=\"last\" source=\"bright\" gate=\"bound\"/>"}));
    EXPECT_EQ(plain.effects[0].gateChannels, glm::bvec4(true, true, true, false)) << "red, green and blue by default";
    EXPECT_TRUE(parsedOk(workspace({"  <effect name=\"glow\" passes=\"last\" source=\"bright\"/>"})).effects[0].gate.empty());
    EXPECT_EQ(errorsOf(workspace({"  <effect name=\"glow\" passes=\"last\" gate=\"bound\"/>"})),
              (Lines{at + "2: error: <effect name=\"glow\">: attribute 'gate' applies with 'source': it is a cheaper test of the source"}));
    EXPECT_EQ(errorsOf(workspace({"  <effect name=\"glow\" passes=\"last\" source=\"b\" gate=\"\"/>"})),
              (Lines{at + "2: error: <effect name=\"glow\">: attribute 'gate' names no target"}));
    EXPECT_EQ(errorsOf(workspace({"  <effect name=\"glow\" passes=\"last\" source=\"b\" gate-channels=\"r\"/>"})),
              (Lines{at + "2: error: <effect name=\"glow\">: attribute 'gate-channels' applies with 'gate'"}));
    EXPECT_EQ(errorsOf(workspace({"  <effect name=\"glow\" passes=\"last\" source=\"b\" gate=\"g\" gate-channels=\"x\"/>"})),
              (Lines{at + "2: error: <effect name=\"glow\">: attribute 'gate-channels': 'x' is not one of: r, rg, rgb, rgba, a"}));
}

TEST(WorkspaceParser, UnknownElementInPass) {
    auto d = errorsOf(workspace({
        "  <pass name=\"blur\">",
        "    <shader stage=\"fragment\" file=\"blur.frag\"/>",
        "    <blnd mode=\"add\"/>",
        "  </pass>",
    }));
    EXPECT_EQ(d, (Lines{at + "4: error: unknown element <blnd> in <pass name=\"blur\"> (expected clear, blend, depth, "
                             "cull, polygon-mode, shader, sampler, draw, stream, or a value element such as float)"}));
}

TEST(WorkspaceParser, UnknownElementInLeafElement) {
    auto d = errorsOf(workspace({
        "  <target name=\"t\" format=\"rgba8\">",
        "    <size w=\"1\"/>",
        "  </target>",
    }));
    EXPECT_EQ(d, (Lines{at + "3: error: unknown element <size> in <target> (it takes no child elements)"}));
}

TEST(WorkspaceParser, UnknownAttributeListsTheKnownOnes) {
    auto d = errorsOf(workspace({
        "  <description>x</description>",
        "",
        "  <pass name=\"blur\" blnd=\"add\">",
        "    <shader stage=\"fragment\" file=\"blur.frag\"/>",
        "  </pass>",
    }));
    EXPECT_EQ(d, (Lines{at + "4: error: <pass name=\"blur\">: unknown attribute 'blnd' (expected one of: name, target, enabled, camera)"}));

    EXPECT_EQ(errorsOf(workspace({"  <description lang=\"en\">x</description>"})),
              (Lines{at + "2: error: <description>: unknown attribute 'lang' (it takes none)"}));
}

TEST(WorkspaceParser, MissingRequiredAttribute) {
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"Gain\"/>"})),
              (Lines{at + "2: error: <float name=\"Gain\">: missing attribute 'value'"}));
    EXPECT_EQ(errorsOf(workspace({"", "  <target format=\"rgba8\"/>"})),
              (Lines{at + "3: error: <target>: missing attribute 'name'"}));
    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: missing attribute 'format'"}));
    EXPECT_EQ(errorsOf(workspace({"  <texture name=\"t\"/>"})),
              (Lines{at + "2: error: <texture name=\"t\">: missing attribute 'file'"}));
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <shader file=\"p.frag\"/>", "  </pass>"})),
              (Lines{at + "3: error: <shader>: missing attribute 'stage' (vertex or fragment)"}));
}

TEST(WorkspaceParser, InvalidName) {
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"2x\" value=\"1\"/>"})),
              (Lines{at + "2: error: <float name=\"2x\">: attribute 'name': '2x' is not a valid name (letters, "
                          "digits and '_', not starting with a digit)"}));
}

// ---- values ----

TEST(WorkspaceParser, BadNumber) {
    EXPECT_EQ(errorsOf(workspace({"  <camera distance=\"far\"/>"})),
              (Lines{at + "2: error: <camera>: attribute 'distance': expected a number, got 'far'"}));
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"g\" value=\"1\" min=\"low\"/>"})),
              (Lines{at + "2: error: <float name=\"g\">: attribute 'min': expected a number, got 'low'"}));
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"g\" value=\"1.5.2\"/>"})),
              (Lines{at + "2: error: <float name=\"g\">: attribute 'value': expected numbers, got '1.5.2'"}));
    EXPECT_EQ(errorsOf(workspace({"  <bool name=\"b\" value=\"yes\"/>"})),
              (Lines{at + "2: error: <bool name=\"b\">: attribute 'value': expected true or false, got 'yes'"}));
}

TEST(WorkspaceParser, BadEnumWordListsTheChoices) {
    auto d = errorsOf(workspace({
        "  <pass name=\"p\">",
        "    <blend mode=\"screen\"/>",
        "    <sampler name=\"s\" target=\"t\" wrap=\"wrap\"/>",
        "  </pass>",
    }));
    EXPECT_EQ(d, (Lines{
                     at + "3: error: <blend>: attribute 'mode': 'screen' is not one of: none, add, alpha, "
                          "premultiplied, multiply, custom",
                     at + "4: error: <sampler name=\"s\">: attribute 'wrap': 'wrap' is not one of: repeat, clamp, "
                          "mirror, border",
                 }));
    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\" format=\"rgb8\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: attribute 'format': unknown format 'rgb8' (expected "
                          "rgba8, rgba16f, rgba32f, r16f, r32f, rg16f, rg32f, rgba16, r11g11b10f, rgb10a2, r8, rg8)"}));
}

TEST(WorkspaceParser, FormatListFollowsTheFormatByVariable) {
    auto parsed = parse(workspace({"  <target name=\"t\" format=\"rgba16f, rgba16 rgba8\" format-by=\"Enc\"/>"}));
    ASSERT_TRUE(parsed.ok());
    const RenderTarget& t = parsed->targets.at(0);
    EXPECT_EQ(t.formatVariable, "Enc");
    EXPECT_EQ(t.formats, (std::vector<TargetFormat>{TargetFormat::RGBA16F, TargetFormat::RGBA16, TargetFormat::RGBA8}));
    EXPECT_EQ(t.format, TargetFormat::RGBA16F);
    EXPECT_EQ(selectTargetFormat(t, nullptr), std::nullopt);
    Value two = Value::ofInt(2);
    EXPECT_EQ(selectTargetFormat(t, &two), TargetFormat::RGBA8);
    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\" format=\"rgba16f rgba8\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: attribute 'format': a list of formats needs "
                          "format-by=\"VARIABLE\", the int variable whose value picks one"}));
}

TEST(WorkspaceParser, WrongComponentCount) {
    EXPECT_EQ(errorsOf(workspace({"  <vec3 name=\"v\" value=\"1 2\"/>"})),
              (Lines{at + "2: error: <vec3 name=\"v\">: attribute 'value': a vec3 takes 3 numbers, got 2"}));
    EXPECT_EQ(errorsOf(workspace({"  <color name=\"c\" value=\"1 0\"/>"})),
              (Lines{at + "2: error: <color name=\"c\">: attribute 'value': a color takes 3 (rgb) or 4 (rgba) "
                          "numbers, got 2"}));
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <clear color=\"0 0 0\"/>", "  </pass>"})),
              (Lines{at + "3: error: <clear>: attribute 'color': expected 4 numbers, got '0 0 0'"}));
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <draw mesh=\"cube\" scale=\"1 2\"/>", "  </pass>"})),
              (Lines{at + "3: error: <draw>: attribute 'scale': expected 1 or 3 numbers, got '1 2'"}));
}

TEST(WorkspaceParser, IntWithFraction) {
    EXPECT_EQ(errorsOf(workspace({"  <int name=\"n\" value=\"2.5\"/>"})),
              (Lines{at + "2: error: <int name=\"n\">: attribute 'value': expected an integer, got '2.5'"}));
    EXPECT_EQ(errorsOf(workspace({"  <cubemap name=\"e\" file=\"e.hdr\" layout=\"equirect\" face-size=\"0.5\"/>"})),
              (Lines{at + "2: error: <cubemap name=\"e\">: attribute 'face-size': expected an integer ≥ 1, got '0.5'"}));
}

TEST(WorkspaceParser, BadSizeOrScale) {
    EXPECT_EQ(errorsOf("<workspace version=\"1\" size=\"512\"><pass name=\"p\"/></workspace>"),
              (Lines{at + "1: error: <workspace>: attribute 'size': expected WIDTHxHEIGHT such as 512x512, got '512'"}));
    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\" format=\"rgba8\" size=\"0x4\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: attribute 'size': expected WIDTHxHEIGHT such as 64x64, got '0x4'"}));
    const std::string scaleError = "attribute 'scale': expected one or two fractions of the viewport in (0, 16] such as "
                                   "1/4 or \"1/2 1/4\" (x and y; a list of choices needs scale-by=\"VARIABLE\"), got ";
    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\" format=\"rgba8\" scale=\"1/0\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: " + scaleError + "'1/0'"}));
    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\" format=\"rgba8\" scale=\"-1\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: " + scaleError + "'-1'"}));
    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\" format=\"rgba8\" scale=\"1/2 1/4 1/8\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: " + scaleError + "'1/2 1/4 1/8'"}));
    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\" format=\"rgba8\" size=\"4x4\" scale=\"1\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: give either 'size' (absolute) or 'scale' (relative to the "
                          "viewport), not both"}));
}

TEST(WorkspaceParser, ScaleByListsOneFractionPerValue) {
    Workspace ws = parsedOk(workspace({"  <int name=\"D\" value=\"1\"/>",
                                       "  <target name=\"t\" format=\"rgba8\" scale=\"1/2, 1/4 1/8\" scale-by=\"D\"/>"}));
    ASSERT_EQ(ws.targets.size(), 1u);
    const RenderTarget& t = ws.targets[0];
    EXPECT_EQ(t.scaleVariable, "D");
    ASSERT_EQ(t.scales.size(), 3u);
    EXPECT_EQ(t.scales[2].scaleX, 0.125);
    EXPECT_EQ(t.scales[2].scaleY, 0.125);
    EXPECT_EQ(t.size.scaleX, 0.5);  // the first choice until a value picks one

    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\" format=\"rgba8\" scale=\"1/2 0 1/8\" scale-by=\"D\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: attribute 'scale': expected fractions of the viewport in (0, 16] "
                          "such as \"1/2 1/4 1/8\" (one per value of 'D'), got '0'"}));
    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\" format=\"rgba8\" size=\"4x4\" scale-by=\"D\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: attribute 'scale-by' needs 'scale' with one fraction per value"}));
}

TEST(WorkspaceParser, MinGreaterThanMax) {
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"g\" value=\"1.5\" min=\"2\" max=\"1\"/>"})),
              (Lines{at + "2: error: <float name=\"g\">: min (2) is greater than max (1)"}));
}

TEST(WorkspaceParser, ValueOutsideRange) {
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"g\" value=\"9\" min=\"0\" max=\"8\"/>"})),
              (Lines{at + "2: error: <float name=\"g\">: value 9 lies outside [0, 8]"}));
    EXPECT_EQ(errorsOf(workspace({"", "  <vec3 name=\"v\" value=\"0.5 -1 0\" min=\"0\"/>"})),
              (Lines{at + "3: error: <vec3 name=\"v\">: value 0.5 -1 0 lies outside [0, inf]"}));
    EXPECT_EQ(errorsOf(workspace({"  <int name=\"n\" value=\"3\" max=\"2\"/>"})),
              (Lines{at + "2: error: <int name=\"n\">: value 3 lies outside [-inf, 2]"}));
}

TEST(WorkspaceParser, WidgetHintsCheckTheirNeeds) {
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"g\" value=\"1\" min=\"0\" ui=\"slider\"/>"})),
              (Lines{at + "2: error: <float name=\"g\">: ui=\"slider\" needs both min and max"}));
    EXPECT_EQ(errorsOf(workspace({"  <int name=\"m\" value=\"0\" ui=\"combo\"/>"})),
              (Lines{at + "2: error: <int name=\"m\">: ui=\"combo\" needs attribute 'options'"}));
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"m\" value=\"0\" options=\"a, b\"/>"})),
              (Lines{at + "2: error: <float name=\"m\">: attribute 'options' applies to int variables"}));
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"m\" value=\"0\" ui=\"combo\" options=\"a, b\"/>"})),
              (Lines{at + "2: error: <float name=\"m\">: ui=\"combo\" applies to int variables",
                     at + "2: error: <float name=\"m\">: attribute 'options' applies to int variables"}));
    EXPECT_EQ(errorsOf(workspace({"  <int name=\"m\" value=\"2\" options=\"a, b\"/>"})),
              (Lines{at + "2: error: <int name=\"m\">: value 2 does not select one of the 2 options"}));
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"m\" value=\"0\" ui=\"checkbox\"/>"})),
              (Lines{at + "2: error: <float name=\"m\">: ui=\"checkbox\" applies to bool variables"}));
    EXPECT_EQ(errorsOf(workspace({"  <bool name=\"b\" value=\"true\" min=\"0\"/>"})),
              (Lines{at + "2: error: <bool name=\"b\">: attribute 'min' does not apply to a bool"}));
}

TEST(WorkspaceParser, ReservedPrefix) {
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"rm_Time\" value=\"0\"/>"})),
              (Lines{at + "2: error: <float name=\"rm_Time\">: the prefix rm_ is reserved for predefined variables"}));
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <vec2 name=\"rm_ViewportSize\" value=\"1 1\"/>", "  </pass>"})),
              (Lines{at + "3: error: <vec2 name=\"rm_ViewportSize\">: the prefix rm_ is reserved for predefined "
                          "variables"}));
}

// ---- structure ----

TEST(WorkspaceParser, SecondOutputNamesTheFirst) {
    auto d = errorsOf(workspace({
        "  <output transform=\"srgb\"/>",
        "  <output transform=\"none\"/>",
    }));
    EXPECT_EQ(d, (Lines{at + "3: error: <output>: a second <output> (the first is at line 2): a workspace has one"}));
}

TEST(WorkspaceParser, SecondShaderOfAStageNamesTheFirst) {
    auto d = errorsOf(workspace({
        "  <pass name=\"p\">",
        "    <shader stage=\"fragment\" file=\"a.frag\"/>",
        "    <shader stage=\"fragment\" file=\"b.frag\"/>",
        "  </pass>",
    }));
    EXPECT_EQ(d, (Lines{at + "4: error: a second fragment shader in <pass name=\"p\"> (first at line 3)"}));
}

TEST(WorkspaceParser, ShaderNeedsFileOrCodeButNotBoth) {
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <shader stage=\"fragment\" file=\"a.frag\">void main(){}</shader>",
                                  "  </pass>"})),
              (Lines{at + "3: error: <shader>: give either attribute 'file' or inline code, not both"}));
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <shader stage=\"fragment\">  </shader>", "  </pass>"})),
              (Lines{at + "3: error: <shader>: no code: give attribute 'file' or the code inside the element"}));
}

TEST(WorkspaceParser, CubemapWithMissingFace) {
    auto d = errorsOf(workspace({
        "  <cubemap name=\"env\">",
        "    <face side=\"+x\" file=\"px.png\"/>",
        "    <face side=\"-x\" file=\"nx.png\"/>",
        "    <face side=\"+y\" file=\"py.png\"/>",
        "    <face side=\"-y\" file=\"ny.png\"/>",
        "    <face side=\"+z\" file=\"pz.png\"/>",
        "  </cubemap>",
    }));
    EXPECT_EQ(d, (Lines{at + "2: error: <cubemap name=\"env\">: face -z is missing (a cubemap takes +x -x +y -y +z -z)"}));
}

TEST(WorkspaceParser, CubemapWithFileAndFaces) {
    auto d = errorsOf(workspace({
        "  <cubemap name=\"env\" file=\"cross.png\">",
        "    <face side=\"+x\" file=\"px.png\"/>",
        "    <face side=\"-x\" file=\"nx.png\"/>",
        "    <face side=\"+y\" file=\"py.png\"/>",
        "    <face side=\"-y\" file=\"ny.png\"/>",
        "    <face side=\"+z\" file=\"pz.png\"/>",
        "    <face side=\"+z\" file=\"nz.png\"/>",
        "  </cubemap>",
    }));
    EXPECT_EQ(d, (Lines{
                     at + "8: error: <face>: face +z is given twice",
                     at + "2: error: <cubemap name=\"env\">: give either attribute 'file' or six <face> elements, not both",
                     at + "2: error: <cubemap name=\"env\">: face -z is missing (a cubemap takes +x -x +y -y +z -z)",
                 }));
    EXPECT_EQ(errorsOf(workspace({"  <cubemap name=\"env\"/>"})),
              (Lines{at + "2: error: <cubemap name=\"env\">: a cubemap needs attribute 'file' (with layout cross or "
                          "equirect) or six <face> elements"}));
}

TEST(WorkspaceParser, SamplerNeedsExactlyOneSource) {
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <sampler name=\"s\" texture=\"a\" target=\"b\"/>", "  </pass>"})),
              (Lines{at + "3: error: <sampler name=\"s\">: give either 'texture' or 'target', not both"}));
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <sampler name=\"s\" filter=\"linear\"/>", "  </pass>"})),
              (Lines{at + "3: error: <sampler name=\"s\">: missing attribute 'texture' or 'target'"}));
}

TEST(WorkspaceParser, PreviousFrameOnlyForTargets) {
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "", "    <sampler name=\"s\" texture=\"a\" frame=\"previous\"/>",
                                  "  </pass>"})),
              (Lines{at + "4: error: <sampler name=\"s\">: frame=\"previous\" applies to render targets"}));
}

TEST(WorkspaceParser, ClearNeedsSomething) {
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <clear/>", "  </pass>"})),
              (Lines{at + "3: error: <clear>: <clear> needs 'color', 'depth' or both"}));
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <clear depth=\"2\"/>", "  </pass>"})),
              (Lines{at + "3: error: <clear>: attribute 'depth' must lie in [0, 1]"}));
}

TEST(WorkspaceParser, DrawNeedsAKnownMeshOrAFile) {
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <draw mesh=\"donut\"/>", "  </pass>"})),
              (Lines{at + "3: error: <draw>: attribute 'mesh': unknown mesh 'donut' (expected fullscreen, cube, sphere, "
                          "plane, teapot, quad, torus)"}));
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <draw mesh=\"cube\" file=\"a.obj\"/>", "  </pass>"})),
              (Lines{at + "3: error: <draw>: give either 'mesh' (built-in) or 'file' (a model), not both"}));
}

TEST(WorkspaceParser, CustomBlendFactorsNeedCustomMode) {
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <blend mode=\"alpha\" src=\"one\"/>", "  </pass>"})),
              (Lines{at + "3: error: <blend>: 'src', 'dst' and 'op' need mode=\"custom\" (or no mode)"}));
    Workspace saturate = parsedOk(workspace({"  <pass name=\"p\">", "    <blend mode=\"custom\" src=\"src-alpha-saturate\" dst=\"one\"/>",
                                             "  </pass>"}));
    const Pass* p = saturate.findPass("p");
    ASSERT_TRUE(p);
    EXPECT_EQ(p->blend.srcColor, BlendFactor::SrcAlphaSaturate);
}

TEST(WorkspaceParser, CameraRanges) {
    EXPECT_EQ(errorsOf(workspace({"  <camera fov=\"180\"/>"})),
              (Lines{at + "2: error: <camera>: attribute 'fov' must lie between 0 and 180 degrees"}));
    EXPECT_EQ(errorsOf(workspace({"  <camera near=\"1\" far=\"0.5\"/>"})),
              (Lines{at + "2: error: <camera>: need 0 < near < far"}));
    EXPECT_EQ(errorsOf(workspace({"  <camera convention=\"vulkan\"/>"})),
              (Lines{at + "2: error: <camera>: attribute 'convention': 'vulkan' is not one of: opengl, direct3d"}));
}

// convention="direct3d" gives D3DX's matrices (left-handed, depth 0…w), as imported Direct3D
// effects get; OpenGL's is the default.
TEST(WorkspaceParser, CameraConvention) {
    Workspace ws = parsedOk(lines({"<workspace version=\"1\">", "  <camera convention=\"direct3d\"/>",
                                   "  <camera name=\"side\"/>", "  <pass name=\"p\"><shader stage=\"fragment\">void main() {}</shader></pass>",
                                   "</workspace>"}));
    EXPECT_EQ(ws.camera.convention, CameraConvention::Direct3D);
    ASSERT_NE(ws.findCamera("side"), nullptr);
    EXPECT_EQ(ws.findCamera("side")->settings.convention, CameraConvention::OpenGL);
}

TEST(WorkspaceParser, NoPassIsAnErrorOnTheWorkspaceElement) {
    auto loaded = [] {
        test::ScratchDir dir;
        auto path = dir.write("empty.xml", lines({"<?xml version=\"1.0\"?>", "<!-- nothing -->",
                                                  "<workspace version=\"1\">", "</workspace>"}));
        return std::pair{path.string(), loadWorkspace(path)};
    }();
    EXPECT_FALSE(loaded.second.ok());
    EXPECT_EQ(formatted(loaded.second.diagnostics()),
              (Lines{loaded.first + ":3: error: <workspace>: no <pass>: nothing to render"}));
}

TEST(WorkspaceParser, MissingFileCannotBeOpened) {
    Result<Workspace> p = parseWorkspaceFile("no/such/workspace.xml");
    EXPECT_EQ(formatted(p.diagnostics()), (Lines{"no/such/workspace.xml: error: the file does not exist"}));
}

// ---- the model ----

TEST(WorkspaceParser, DefaultWorkspace) {
    const auto path = test::sourceDir() / "effects" / "default.xml";
    Result<Workspace> p = parseWorkspaceFile(path);
    ASSERT_EQ(formatAll(p.diagnostics()), "");
    ASSERT_TRUE(p.ok());
    const Workspace& ws = *p;
    const std::string file = path.string();
    EXPECT_EQ(ws.name, "default");
    EXPECT_EQ(ws.folder, path.parent_path());
    EXPECT_EQ(ws.description, "HDR sky and reflective teapot with exposure control");
    EXPECT_EQ(ws.width, 512);
    EXPECT_EQ(ws.height, 512);

    EXPECT_EQ(ws.camera.target, glm::vec3(0.0f));
    EXPECT_FLOAT_EQ(ws.camera.distance, 3.2f);
    EXPECT_FLOAT_EQ(ws.camera.yawDegrees, 35.0f);
    EXPECT_FLOAT_EQ(ws.camera.pitchDegrees, 12.0f);
    EXPECT_FLOAT_EQ(ws.camera.fovYDegrees, 50.0f);
    EXPECT_FLOAT_EQ(ws.camera.nearPlane, 0.05f);  // default
    EXPECT_EQ(ws.camera.where.line, 7);

    ASSERT_EQ(ws.variables.size(), 5u);
    const Variable& exposure = ws.variables[0];
    EXPECT_EQ(exposure.name, "Exposure_Level");
    EXPECT_EQ(exposure.value, Value::ofFloat(0.8f));
    EXPECT_EQ(exposure.min, 0.0f);
    EXPECT_EQ(exposure.max, 8.0f);
    EXPECT_EQ(exposure.step, 0.01f);
    EXPECT_EQ(exposure.widget, WidgetHint::Slider);
    EXPECT_EQ(exposure.description, "scales the HDR image before tone mapping");
    EXPECT_EQ(exposure.where.file, file);
    EXPECT_EQ(exposure.where.line, 9);
    EXPECT_EQ(ws.variables[1].name, "Tone_Map");
    EXPECT_EQ(ws.variables[1].value, Value::ofBool(true));
    EXPECT_EQ(ws.variables[1].where.line, 11);
    EXPECT_EQ(ws.variables[2].value.type, ValueType::Vec3);
    EXPECT_EQ(formatValue(ws.variables[2].value), "-0.35 0.12 -0.93");
    EXPECT_EQ(ws.variables[3].widget, WidgetHint::Drag);
    EXPECT_FALSE(ws.variables[3].step);
    EXPECT_EQ(ws.variables[4].name, "Teapot_Tint");
    EXPECT_EQ(ws.variables[4].value.type, ValueType::Color3);
    EXPECT_EQ(ws.variables[4].where.line, 14);

    ASSERT_EQ(ws.snippets.size(), 1u);
    EXPECT_EQ(ws.snippets[0].name, "sky.glsl");
    EXPECT_EQ(ws.snippets[0].codeLine, 16);
    EXPECT_EQ(ws.snippets[0].where.line, 16);
    EXPECT_NE(ws.snippets[0].code.find("vec3 skyRadiance(vec3 d)"), std::string::npos);

    ASSERT_EQ(ws.targets.size(), 1u);
    EXPECT_EQ(ws.targets[0].name, "hdr");
    EXPECT_EQ(ws.targets[0].format, TargetFormat::RGBA16F);
    EXPECT_TRUE(ws.targets[0].size.relative);
    EXPECT_EQ(ws.targets[0].size.scaleX, 1.0);
    EXPECT_EQ(ws.targets[0].size.scaleY, 1.0);
    EXPECT_FALSE(ws.targets[0].mipmaps);
    EXPECT_EQ(ws.targets[0].where.line, 34);
    EXPECT_TRUE(ws.textures.empty());

    ASSERT_EQ(ws.passes.size(), 3u);
    const Pass& sky = ws.passes[0];
    EXPECT_EQ(sky.name, "sky");
    EXPECT_EQ(sky.target, "hdr");
    EXPECT_EQ(sky.where.line, 36);
    EXPECT_EQ(sky.clear.color, glm::vec4(0, 0, 0, 1));
    EXPECT_EQ(sky.clear.depth, 1.0f);
    EXPECT_FALSE(sky.blend.enabled);
    EXPECT_FALSE(sky.depth.test);
    EXPECT_EQ(sky.draw.mesh, BuiltinMesh::FullscreenTriangle);
    EXPECT_EQ(sky.draw.where.line, 36);  // the implicit draw is located at its pass
    ASSERT_EQ(sky.shaders.size(), 1u);
    EXPECT_EQ(sky.shaders[0].stage, ShaderStage::Fragment);
    EXPECT_TRUE(sky.shaders[0].file.empty());
    EXPECT_EQ(sky.shaders[0].codeLine, 38);
    EXPECT_EQ(sky.shaders[0].code.substr(0, 19), "\n#version 450 core\n");

    const Pass& teapot = ws.passes[1];
    EXPECT_TRUE(teapot.depth.test);
    EXPECT_TRUE(teapot.depth.write);
    EXPECT_EQ(teapot.depth.func, CompareFunc::Less);
    EXPECT_EQ(teapot.raster.cull, CullFace::Back);
    EXPECT_TRUE(teapot.raster.frontCounterClockwise);
    EXPECT_EQ(teapot.draw.mesh, BuiltinMesh::Teapot);
    EXPECT_EQ(teapot.draw.scale, glm::vec3(1.0f));
    EXPECT_EQ(teapot.draw.where.line, 53);

    const Pass& tonemap = ws.passes[2];
    EXPECT_EQ(tonemap.target, "");
    EXPECT_EQ(ws.passTargetName(tonemap), "output");
    ASSERT_EQ(tonemap.samplers.size(), 1u);
    EXPECT_EQ(tonemap.samplers[0].uniform, "hdrImage");
    EXPECT_EQ(tonemap.samplers[0].target, "hdr");
    EXPECT_EQ(tonemap.samplers[0].filter, Filter::Nearest);
    EXPECT_EQ(tonemap.samplers[0].mipmap, MipmapMode::None);
    EXPECT_EQ(tonemap.samplers[0].wrapS, Wrap::Clamp);
    EXPECT_EQ(tonemap.samplers[0].where.line, 75);

    EXPECT_EQ(ws.output.target, "");
    EXPECT_EQ(ws.outputTargetName(), "output");
    EXPECT_EQ(ws.output.transform, DisplayTransform::Srgb);
    EXPECT_EQ(ws.output.format, TargetFormat::RGBA16F);
    EXPECT_EQ(ws.output.where.line, 90);
}

TEST(WorkspaceParser, EveryFeature) {
    Workspace ws = parsedOk(lines({
        /*  1 */ "<workspace version=\"1\" name=\"all\" size=\"256x128\">",
        /*  2 */ "  <camera target=\"0 1 0\" distance=\"5\" yaw=\"-10\" pitch=\"20\" fov=\"40\" near=\"0.1\" far=\"50\"/>",
        /*  3 */ "  <int name=\"Mode\" value=\"1\" options=\"off, soft , hard\" description=\"how\"/>",
        /*  4 */ "  <color name=\"Glow\" value=\"2 1 0.5 1\" hdr=\"true\" ui=\"color\"/>",
        /*  5 */ "  <vec2 name=\"Offset\" value=\"0.5, -0.5\" min=\"-1\" max=\"1\" step=\"0.1\" ui=\"drag\"/>",
        /*  6 */ "  <bool name=\"On\" value=\"0\" ui=\"checkbox\"/>",
        /*  7 */ "  <mat4 name=\"M\" value=\"1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\"/>",
        /*  8 */ "  <texture name=\"noise\" file=\"noise.png\" colorspace=\"srgb\" mipmaps=\"false\"/>",
        /*  9 */ "  <cubemap name=\"env\" file=\"sky.hdr\" layout=\"equirect\" face-size=\"256\"/>",
        /* 10 */ "  <cubemap name=\"box\">",
        /* 11 */ "    <face side=\"-z\" file=\"nz.png\"/>",
        /* 12 */ "    <face side=\"+x\" file=\"px.png\"/>",
        /* 13 */ "    <face side=\"-x\" file=\"nx.png\"/>",
        /* 14 */ "    <face side=\"+y\" file=\"py.png\"/>",
        /* 15 */ "    <face side=\"-y\" file=\"ny.png\"/>",
        /* 16 */ "    <face side=\"+z\" file=\"pz.png\"/>",
        /* 17 */ "  </cubemap>",
        /* 18 */ "  <target name=\"quarter\" format=\"rgba8\" scale=\"1/4\"/>",
        /* 19 */ "  <target name=\"wide\" format=\"r11g11b10f\" scale=\"1/2 0.125\" mipmaps=\"true\" initial=\"0 0 0 1\"/>",
        /* 20 */ "  <target name=\"fixed\" format=\"rg32f\" size=\"64x32\"/>",
        /* 21 */ "  <pass name=\"geometry\" target=\"fixed\" enabled=\"false\">",
        /* 22 */ "    <clear depth=\"0.5\"/>",
        /* 23 */ "    <blend mode=\"custom\" src=\"src-alpha\" dst=\"one-minus-src-alpha\" op=\"reverse-subtract\" dst-alpha=\"one\" constant=\"1 0 0 1\"/>",
        /* 24 */ "    <depth test=\"gequal\" write=\"false\"/>",
        /* 25 */ "    <cull face=\"front\" front=\"cw\"/>",
        /* 26 */ "    <draw file=\"models/rock.obj\" translate=\"1 2 3\" rotate=\"0 90 0\" scale=\"2\"/>",
        /* 27 */ "    <shader stage=\"vertex\" file=\"rock.vert\"/>",
        /* 28 */ "    <shader stage=\"fragment\" file=\"rock.frag\"/>",
        /* 29 */ "    <float name=\"Mode_Scale\" value=\"3\"/>",
        /* 30 */ "  </pass>",
        /* 31 */ "  <pass name=\"blend\" target=\"wide\">",
        /* 32 */ "    <blend mode=\"premultiplied\"/>",
        /* 33 */ "    <depth test=\"off\"/>",
        /* 34 */ "    <draw mesh=\"sphere\" scale=\"1 2 3\"/>",
        /* 35 */ "    <sampler name=\"previous\" target=\"wide\" frame=\"previous\" filter=\"nearest\" mipmap=\"linear\" wrap=\"repeat\" wrap-t=\"border\" border=\"1 1 1 1\"/>",
        /* 36 */ "    <sampler name=\"tex\" texture=\"noise\" wrap=\"mirror\"/>",
        /* 37 */ "    <shader stage=\"fragment\">void main() {}</shader>",
        /* 38 */ "  </pass>",
        /* 39 */ "  <pass name=\"add\">",
        /* 40 */ "    <blend mode=\"add\"/>",
        /* 41 */ "    <cull/>",
        /* 42 */ "    <depth test=\"less\"/>",
        /* 43 */ "    <shader stage=\"fragment\" file=\"add.frag\"/>",
        /* 44 */ "  </pass>",
        /* 45 */ "  <output target=\"wide\" transform=\"none\"/>",
        /* 46 */ "</workspace>",
    }));
    EXPECT_EQ(ws.name, "all");
    EXPECT_EQ(ws.path, kPath);
    EXPECT_EQ(ws.folder, "fx");
    EXPECT_EQ(ws.width, 256);
    EXPECT_EQ(ws.height, 128);
    EXPECT_EQ(ws.camera.target, glm::vec3(0, 1, 0));
    EXPECT_EQ(ws.camera.yawDegrees, -10.0f);
    EXPECT_EQ(ws.camera.farPlane, 50.0f);

    // variables and their hints
    ASSERT_EQ(ws.variables.size(), 5u);
    const Variable& mode = *ws.findVariable("Mode");
    EXPECT_EQ(mode.widget, WidgetHint::Combo);  // implied by options
    EXPECT_EQ(mode.options, (std::vector<std::string>{"off", "soft", "hard"}));
    EXPECT_EQ(mode.value, Value::ofInt(1));
    EXPECT_EQ(mode.description, "how");
    const Variable& glow = *ws.findVariable("Glow");
    EXPECT_EQ(glow.value.type, ValueType::Color4);
    EXPECT_TRUE(glow.hdr);
    EXPECT_EQ(glow.widget, WidgetHint::Color);
    const Variable& offset = *ws.findVariable("Offset");
    EXPECT_EQ(offset.min, -1.0f);
    EXPECT_EQ(offset.max, 1.0f);
    EXPECT_EQ(offset.step, 0.1f);
    EXPECT_EQ(offset.widget, WidgetHint::Drag);
    EXPECT_EQ(ws.findVariable("On")->widget, WidgetHint::Checkbox);
    EXPECT_EQ(ws.findVariable("On")->value, Value::ofBool(false));
    EXPECT_EQ(ws.findVariable("M")->value.type, ValueType::Mat4);
    EXPECT_EQ(ws.findVariable("M")->where.line, 7);

    // textures
    ASSERT_EQ(ws.textures.size(), 3u);
    const Texture& noise = ws.textures[0];
    EXPECT_EQ(noise.kind, TextureKind::Texture2D);
    EXPECT_EQ(noise.colorSpace, ColorSpace::Srgb);
    EXPECT_FALSE(noise.mipmaps);
    EXPECT_EQ(noise.files, (std::vector<std::string>{"noise.png"}));
    const Texture& env = ws.textures[1];
    EXPECT_EQ(env.kind, TextureKind::Cube);
    EXPECT_EQ(env.layout, CubeLayout::Equirect);
    EXPECT_EQ(env.faceSize, 256);
    EXPECT_TRUE(env.mipmaps);
    const Texture& box = ws.textures[2];
    EXPECT_EQ(box.layout, CubeLayout::Faces);
    EXPECT_EQ(box.files, (std::vector<std::string>{"px.png", "nx.png", "py.png", "ny.png", "pz.png", "nz.png"}));
    ASSERT_EQ(box.fileLocations.size(), 6u);
    EXPECT_EQ(box.fileLocations[0].line, 12);  // +x
    EXPECT_EQ(box.fileLocations[5].line, 11);  // -z, given first

    // targets and their sizes
    ASSERT_EQ(ws.targets.size(), 3u);
    const RenderTarget& quarter = *ws.findTarget("quarter");
    EXPECT_EQ(quarter.format, TargetFormat::RGBA8);
    EXPECT_TRUE(quarter.size.relative);
    EXPECT_EQ(quarter.size.scaleX, 0.25);
    EXPECT_EQ(quarter.size.scaleY, 0.25);
    EXPECT_EQ(resolveTargetSize(quarter.size, {256, 128}), glm::ivec2(64, 32));
    const RenderTarget& wide = *ws.findTarget("wide");
    EXPECT_EQ(wide.format, TargetFormat::R11G11B10F);
    EXPECT_EQ(wide.size.scaleX, 0.5);
    EXPECT_EQ(wide.size.scaleY, 0.125);
    EXPECT_TRUE(wide.mipmaps);
    EXPECT_EQ(wide.initial, glm::vec4(0, 0, 0, 1));
    EXPECT_EQ(resolveTargetSize(wide.size, {5, 1}), glm::ivec2(3, 1));
    const RenderTarget& fixed = *ws.findTarget("fixed");
    EXPECT_FALSE(fixed.size.relative);
    EXPECT_EQ(resolveTargetSize(fixed.size, {1000, 1000}), glm::ivec2(64, 32));

    // passes
    ASSERT_EQ(ws.passes.size(), 3u);
    const Pass& geometry = ws.passes[0];
    EXPECT_FALSE(geometry.enabled);
    EXPECT_FALSE(geometry.clear.color);
    EXPECT_EQ(geometry.clear.depth, 0.5f);
    EXPECT_TRUE(geometry.blend.enabled);
    EXPECT_EQ(geometry.blend.srcColor, BlendFactor::SrcAlpha);
    EXPECT_EQ(geometry.blend.dstColor, BlendFactor::OneMinusSrcAlpha);
    EXPECT_EQ(geometry.blend.colorOp, BlendOp::ReverseSubtract);
    EXPECT_EQ(geometry.blend.srcAlpha, BlendFactor::SrcAlpha);  // defaults to the colour factor
    EXPECT_EQ(geometry.blend.dstAlpha, BlendFactor::One);
    EXPECT_EQ(geometry.blend.alphaOp, BlendOp::ReverseSubtract);
    EXPECT_EQ(geometry.blend.constant, glm::vec4(1, 0, 0, 1));
    EXPECT_TRUE(geometry.depth.test);
    EXPECT_FALSE(geometry.depth.write);
    EXPECT_EQ(geometry.depth.func, CompareFunc::GreaterEqual);
    EXPECT_EQ(geometry.raster.cull, CullFace::Front);
    EXPECT_FALSE(geometry.raster.frontCounterClockwise);
    EXPECT_FALSE(geometry.draw.mesh);
    EXPECT_EQ(geometry.draw.file, "models/rock.obj");
    EXPECT_EQ(geometry.draw.translate, glm::vec3(1, 2, 3));
    EXPECT_EQ(geometry.draw.rotateDegrees, glm::vec3(0, 90, 0));
    EXPECT_EQ(geometry.draw.scale, glm::vec3(2.0f));
    EXPECT_EQ(geometry.draw.where.line, 26);
    ASSERT_EQ(geometry.shaders.size(), 2u);
    EXPECT_EQ(geometry.shaders[0].stage, ShaderStage::Vertex);
    EXPECT_EQ(geometry.shaders[0].file, "rock.vert");
    EXPECT_EQ(geometry.shaders[1].stage, ShaderStage::Fragment);
    EXPECT_EQ(geometry.shaders[1].where.line, 28);
    ASSERT_EQ(geometry.constants.size(), 1u);
    EXPECT_EQ(geometry.constants[0].name, "Mode_Scale");
    EXPECT_EQ(geometry.constants[0].where.line, 29);

    const Pass& blend = ws.passes[1];
    EXPECT_TRUE(blend.blend.enabled);
    EXPECT_EQ(blend.blend.srcColor, BlendFactor::One);
    EXPECT_EQ(blend.blend.dstColor, BlendFactor::OneMinusSrcAlpha);
    EXPECT_EQ(blend.blend.dstAlpha, BlendFactor::OneMinusSrcAlpha);
    EXPECT_FALSE(blend.depth.test);
    EXPECT_FALSE(blend.depth.write);
    EXPECT_EQ(blend.draw.mesh, BuiltinMesh::Sphere);
    EXPECT_EQ(blend.draw.scale, glm::vec3(1, 2, 3));
    ASSERT_EQ(blend.samplers.size(), 2u);
    const Sampler& previous = blend.samplers[0];
    EXPECT_EQ(previous.target, "wide");
    EXPECT_TRUE(previous.previousFrame);
    EXPECT_EQ(previous.filter, Filter::Nearest);
    EXPECT_EQ(previous.mipmap, MipmapMode::Linear);
    EXPECT_EQ(previous.wrapS, Wrap::Repeat);
    EXPECT_EQ(previous.wrapT, Wrap::Border);
    EXPECT_EQ(previous.border, glm::vec4(1.0f));
    EXPECT_EQ(previous.where.line, 35);
    EXPECT_EQ(blend.samplers[1].texture, "noise");
    EXPECT_FALSE(blend.samplers[1].previousFrame);
    EXPECT_EQ(blend.samplers[1].wrapS, Wrap::Mirror);
    EXPECT_EQ(blend.samplers[1].wrapT, Wrap::Mirror);
    EXPECT_EQ(blend.shaders[0].code, "void main() {}");
    EXPECT_EQ(blend.shaders[0].codeLine, 37);

    const Pass& add = ws.passes[2];
    EXPECT_EQ(add.blend.srcColor, BlendFactor::One);
    EXPECT_EQ(add.blend.dstColor, BlendFactor::One);
    EXPECT_EQ(add.blend.colorOp, BlendOp::Add);
    EXPECT_EQ(add.raster.cull, CullFace::Back);  // <cull/> culls back faces
    EXPECT_TRUE(add.depth.test);
    EXPECT_TRUE(add.depth.write);  // write follows test unless given
    EXPECT_EQ(ws.passTargetName(add), "wide");

    EXPECT_EQ(ws.output.target, "wide");
    EXPECT_EQ(ws.output.transform, DisplayTransform::None);
    EXPECT_EQ(ws.output.where.line, 45);
}

TEST(WorkspaceParser, NameDefaultsToTheFileStem) {
    Workspace ws = parsedOk(workspace({"  <pass name=\"p\"/>"}));
    EXPECT_EQ(ws.name, "test");
    EXPECT_EQ(ws.width, 512);
    EXPECT_EQ(ws.passes[0].draw.mesh, BuiltinMesh::FullscreenTriangle);
}

TEST(WorkspaceParser, ResolveTargetSizeRoundsUp) {
    auto scaled = [](double sx, double sy) {
        TargetSize s;
        s.scaleX = sx;
        s.scaleY = sy;
        return s;
    };
    EXPECT_EQ(resolveTargetSize(scaled(0.25, 0.25), {256, 256}), glm::ivec2(64, 64));
    EXPECT_EQ(resolveTargetSize(scaled(0.5, 0.5), {5, 5}), glm::ivec2(3, 3));
    EXPECT_EQ(resolveTargetSize(scaled(0.125, 0.125), {1, 1}), glm::ivec2(1, 1));
    EXPECT_EQ(resolveTargetSize(scaled(1.0 / 3.0, 2.0), {300, 7}), glm::ivec2(100, 14));
    // 1/10 is not exact in binary; the product must still not round up past 64.
    EXPECT_EQ(resolveTargetSize(scaled(0.1, 0.1), {640, 641}), glm::ivec2(64, 65));
    TargetSize absolute;
    absolute.relative = false;
    absolute.width = 7;
    absolute.height = 9;
    EXPECT_EQ(resolveTargetSize(absolute, {1, 1}), glm::ivec2(7, 9));
}

}  // namespace rmfx
