// The workspace parser on structure: what may appear once, what needs what (shaders, cubemaps,
// samplers, clears, draws, blend factors, cameras), a workspace without passes, a missing file.

#include "frontend/workspace/WorkspaceParser.h"

#include <utility>

#include <gtest/gtest.h>

#include "WorkspaceParserTestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx {
namespace {

using namespace test;
using namespace test::workspace_parser;

TEST(WorkspaceParserStructure, SecondOutputNamesTheFirst) {
    auto d = errorsOf(workspace({
        "  <output transform=\"srgb\"/>",
        "  <output transform=\"none\"/>",
    }));
    EXPECT_EQ(d, (Lines{at + "3: error: <output>: a second <output> (the first is at line 2): a workspace has one"}));
}

TEST(WorkspaceParserStructure, SecondShaderOfAStageNamesTheFirst) {
    auto d = errorsOf(workspace({
        "  <pass name=\"p\">",
        "    <shader stage=\"fragment\" file=\"a.frag\"/>",
        "    <shader stage=\"fragment\" file=\"b.frag\"/>",
        "  </pass>",
    }));
    EXPECT_EQ(d, (Lines{at + "4: error: a second fragment shader in <pass name=\"p\"> (first at line 3)"}));
}

TEST(WorkspaceParserStructure, ShaderNeedsFileOrCodeButNotBoth) {
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <shader stage=\"fragment\" file=\"a.frag\">void main(){}</shader>",
                                  "  </pass>"})),
              (Lines{at + "3: error: <shader>: give either attribute 'file' or inline code, not both"}));
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <shader stage=\"fragment\">  </shader>", "  </pass>"})),
              (Lines{at + "3: error: <shader>: no code: give attribute 'file' or the code inside the element"}));
}

TEST(WorkspaceParserStructure, CubemapWithMissingFace) {
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

TEST(WorkspaceParserStructure, CubemapWithFileAndFaces) {
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

TEST(WorkspaceParserStructure, SamplerNeedsExactlyOneSource) {
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <sampler name=\"s\" texture=\"a\" target=\"b\"/>", "  </pass>"})),
              (Lines{at + "3: error: <sampler name=\"s\">: give either 'texture' or 'target', not both"}));
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <sampler name=\"s\" filter=\"linear\"/>", "  </pass>"})),
              (Lines{at + "3: error: <sampler name=\"s\">: missing attribute 'texture' or 'target'"}));
}

TEST(WorkspaceParserStructure, PreviousFrameOnlyForTargets) {
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "", "    <sampler name=\"s\" texture=\"a\" frame=\"previous\"/>",
                                  "  </pass>"})),
              (Lines{at + "4: error: <sampler name=\"s\">: frame=\"previous\" applies to render targets"}));
}

TEST(WorkspaceParserStructure, ClearNeedsSomething) {
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <clear/>", "  </pass>"})),
              (Lines{at + "3: error: <clear>: <clear> needs 'color', 'depth' or both"}));
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <clear depth=\"2\"/>", "  </pass>"})),
              (Lines{at + "3: error: <clear>: attribute 'depth' must lie in [0, 1]"}));
}

TEST(WorkspaceParserStructure, DrawNeedsAKnownMeshOrAFile) {
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <draw mesh=\"donut\"/>", "  </pass>"})),
              (Lines{at + "3: error: <draw>: attribute 'mesh': unknown mesh 'donut' (expected fullscreen, cube, sphere, "
                          "plane, teapot, quad, torus)"}));
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <draw mesh=\"cube\" file=\"a.obj\"/>", "  </pass>"})),
              (Lines{at + "3: error: <draw>: give either 'mesh' (built-in) or 'file' (a model), not both"}));
}

TEST(WorkspaceParserStructure, CustomBlendFactorsNeedCustomMode) {
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <blend mode=\"alpha\" src=\"one\"/>", "  </pass>"})),
              (Lines{at + "3: error: <blend>: 'src', 'dst' and 'op' need mode=\"custom\" (or no mode)"}));
    Workspace saturate = parsedOk(workspace({"  <pass name=\"p\">", "    <blend mode=\"custom\" src=\"src-alpha-saturate\" dst=\"one\"/>",
                                             "  </pass>"}));
    const Pass* p = saturate.findPass("p");
    ASSERT_TRUE(p);
    EXPECT_EQ(p->blend.srcColor, BlendFactor::SrcAlphaSaturate);
}

TEST(WorkspaceParserStructure, CameraRanges) {
    EXPECT_EQ(errorsOf(workspace({"  <camera fov=\"180\"/>"})),
              (Lines{at + "2: error: <camera>: attribute 'fov' must lie between 0 and 180 degrees"}));
    EXPECT_EQ(errorsOf(workspace({"  <camera near=\"1\" far=\"0.5\"/>"})),
              (Lines{at + "2: error: <camera>: need 0 < near < far"}));
    EXPECT_EQ(errorsOf(workspace({"  <camera convention=\"vulkan\"/>"})),
              (Lines{at + "2: error: <camera>: attribute 'convention': 'vulkan' is not one of: opengl, direct3d"}));
}

// convention="direct3d" gives D3DX's matrices (left-handed, depth 0…w), as imported Direct3D
// effects get; OpenGL's is the default.
TEST(WorkspaceParserStructure, CameraConvention) {
    Workspace ws = parsedOk(lines({"<workspace version=\"1\">", "  <camera convention=\"direct3d\"/>",
                                   "  <camera name=\"side\"/>", "  <pass name=\"p\"><shader stage=\"fragment\">void main() {}</shader></pass>",
                                   "</workspace>"}));
    EXPECT_EQ(ws.camera.convention, CameraConvention::Direct3D);
    ASSERT_NE(ws.findCamera("side"), nullptr);
    EXPECT_EQ(ws.findCamera("side")->settings.convention, CameraConvention::OpenGL);
}

TEST(WorkspaceParserStructure, NoPassIsAnErrorOnTheWorkspaceElement) {
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

TEST(WorkspaceParserStructure, MissingFileCannotBeOpened) {
    Result<Workspace> p = parseWorkspaceFile("no/such/workspace.xml");
    EXPECT_EQ(formatted(p.diagnostics()), (Lines{"no/such/workspace.xml: error: the file does not exist"}));
}

}  // namespace
}  // namespace rmfx
