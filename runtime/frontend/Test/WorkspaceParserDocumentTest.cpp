// The workspace parser on the document: malformed XML, the root and its version, unknown elements and
// attributes, required attributes and names, each an error at its line.

#include "frontend/workspace/WorkspaceParser.h"

#include <gtest/gtest.h>

#include "WorkspaceParserTestSupport.h"

namespace rmfx {
namespace {

using namespace test;
using namespace test::workspace_parser;

TEST(WorkspaceParserDocument, MalformedXmlNamesTheLineOfTheError) {
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

TEST(WorkspaceParserDocument, MalformedXmlSaysWhatIsWrong) {
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

TEST(WorkspaceParserDocument, OneWorkspacePerFile) {
    EXPECT_EQ(errorsOf(lines({"<workspace version=\"1\"><pass name=\"p\"/></workspace>", "", "<pass name=\"q\"/>"})),
              (Lines{at + "3: error: <pass> after </workspace>: a file holds one <workspace>"}));
}

TEST(WorkspaceParserDocument, WrongRootElement) {
    auto d = errorsOf(lines({"<?xml version=\"1.0\"?>", "<effect version=\"1\"/>"}));
    EXPECT_EQ(d, (Lines{at + "2: error: the root element must be <workspace>, not <effect>"}));
}

TEST(WorkspaceParserDocument, UnsupportedOrMissingVersion) {
    EXPECT_EQ(errorsOf(lines({"<?xml version=\"1.0\"?>", "<workspace version=\"2\">", "<pass name=\"p\"/>", "</workspace>"})),
              (Lines{at + "2: error: <workspace>: unsupported version '2': this rmfx reads version 1"}));
    EXPECT_EQ(errorsOf("<workspace name=\"x\"><pass name=\"p\"/></workspace>"),
              (Lines{at + "1: error: <workspace name=\"x\">: missing attribute 'version'"}));
}

TEST(WorkspaceParserDocument, UnknownElementInWorkspace) {
    auto d = errorsOf(workspace({
        "  <float name=\"a\" value=\"1\"/>",
        "  <texure name=\"t\" file=\"t.png\"/>",
    }));
    EXPECT_EQ(d, (Lines{at + "3: error: unknown element <texure> in <workspace> (expected description, camera, code, "
                             "float, int, bool, vec2, vec3, vec4, color, mat4, texture, cubemap, volume, input, target, pass, effect, output)"}));
}

TEST(WorkspaceParserDocument, AnEffectsSourceAndItsChannels) {
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

TEST(WorkspaceParserDocument, AnEffectsGateAndItsChannels) {
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

TEST(WorkspaceParserDocument, UnknownElementInPass) {
    auto d = errorsOf(workspace({
        "  <pass name=\"blur\">",
        "    <shader stage=\"fragment\" file=\"blur.frag\"/>",
        "    <blnd mode=\"add\"/>",
        "  </pass>",
    }));
    EXPECT_EQ(d, (Lines{at + "4: error: unknown element <blnd> in <pass name=\"blur\"> (expected clear, blend, depth, "
                             "cull, polygon-mode, shader, sampler, draw, stream, or a value element such as float)"}));
}

TEST(WorkspaceParserDocument, UnknownElementInLeafElement) {
    auto d = errorsOf(workspace({
        "  <target name=\"t\" format=\"rgba8\">",
        "    <size w=\"1\"/>",
        "  </target>",
    }));
    EXPECT_EQ(d, (Lines{at + "3: error: unknown element <size> in <target> (it takes no child elements)"}));
}

TEST(WorkspaceParserDocument, UnknownAttributeListsTheKnownOnes) {
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

TEST(WorkspaceParserDocument, MissingRequiredAttribute) {
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

TEST(WorkspaceParserDocument, InvalidName) {
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"2x\" value=\"1\"/>"})),
              (Lines{at + "2: error: <float name=\"2x\">: attribute 'name': '2x' is not a valid name (letters, "
                          "digits and '_', not starting with a digit)"}));
}

}  // namespace
}  // namespace rmfx
