// <input>s in the pass graph, without GL: an image given for an input that replaces a target culls
// the passes that drew the target before it, an input not given culls the passes that sample it,
// and a required input that is missing is an error naming the sampler.

#include <gtest/gtest.h>

#include "graph/FramePlan.h"
#include "graph/PassGraph.h"
#include "graph/Test/WorkspaceBuilder.h"

namespace rmfx {
namespace {

using test::WorkspaceBuilder;
using Names = std::vector<std::string>;

// A scene drawn by two passes (the second draws over the first), the image put into it by
// "from_input", a pass that draws over the scene after it, and the output reading the scene.
// With `depthPass`, "depth_pass" writes an r32f "depth" before the image.
std::unique_ptr<Workspace> sceneWorkspace(bool depthPass = false) {
    WorkspaceBuilder b("inputs.xml");
    b.target("scene");
    if (depthPass) b.target("depth", TargetFormat::R32F);
    b.input("photo", "scene")
        .pass("sky", "scene", {}, test::clearColor({0, 0, 0, 1}))
        .pass("teapot", "scene", {}, test::drawMesh(BuiltinMesh::Teapot));
    if (depthPass) b.pass("depth_pass", "depth");
    return b.pass("from_input", "scene")
        .sampler(test::textureSampler("Image", "photo"))
        .pass("overlay", "scene", {}, test::additiveBlend())  // <blend src="one" dst="one"/>
        .pass("screen", "")
        .sampler(test::targetSampler("Scene", "scene"))
        .build();
}

Names scheduled(const PassGraph& g) {
    Names names;
    for (int i : g.schedule) names.push_back(g.nodes[static_cast<size_t>(i)].pass->name);
    return names;
}

const PassNode& node(const PassGraph& g, const std::string& name) {
    return g.nodes[static_cast<size_t>(g.passIndex(name))];
}

TEST(InputCulling, AGivenImageCullsThePassesThatDrewTheTargetBeforeIt) {
    auto ws = sceneWorkspace();
    Result<PassGraph> g = buildPassGraph(*ws, {{}, {}, {}, {"photo"}});
    ASSERT_TRUE(g.ok()) << formatAll(g.diagnostics());
    EXPECT_EQ(scheduled(*g), (Names{"from_input", "overlay", "screen"}));
    for (const char* drawn : {"sky", "teapot"}) {
        EXPECT_EQ(node(*g, drawn).fate, PassFate::InputGiven) << drawn;
        EXPECT_EQ(node(*g, drawn).why, "'scene' comes from the image given for input 'photo'") << drawn;
    }
    // The overlay comes after the image and draws over it, as it drew over the drawn scene.
    EXPECT_EQ(node(*g, "overlay").inputs, (std::vector<int>{g->passIndex("from_input")}));
}

TEST(InputCulling, WithoutAnImageTheWorkspaceDrawsTheTargetItself) {
    auto ws = sceneWorkspace();
    Result<PassGraph> g = buildPassGraph(*ws, {});
    ASSERT_TRUE(g.ok()) << formatAll(g.diagnostics());
    EXPECT_EQ(scheduled(*g), (Names{"sky", "teapot", "overlay", "screen"}));
    EXPECT_EQ(node(*g, "from_input").fate, PassFate::InputNotGiven);
    EXPECT_EQ(node(*g, "from_input").why,
              "no image given for input 'photo' (rmfx render --input photo=FILE): the workspace draws 'scene' itself");
    EXPECT_STREQ(passFateName(PassFate::InputNotGiven), "culled: input not given");
}

TEST(InputCulling, ARequiredInputWithoutAnImageIsAnErrorAtTheSampler) {
    std::unique_ptr<Workspace> screen =
        WorkspaceBuilder("inputs.xml").input("photo").pass("screen", "").sampler(test::textureSampler("Image", "photo")).build();
    Workspace& ws = *screen;
    Result<PassGraph> missing = buildPassGraph(ws, {});
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error(), "inputs.xml:4: error: <sampler name=\"Image\">: pass 'screen' samples input 'photo', and no "
                               "image was given for it (rmfx render --input photo=FILE)");
    Result<PassGraph> given = buildPassGraph(ws, {{}, {}, {}, {"photo"}});
    EXPECT_TRUE(given.ok()) << formatAll(given.diagnostics());
    // An input with a file of its own needs no image.
    ws.textures.front().files = {"default.exr"};
    EXPECT_TRUE(buildPassGraph(ws, {}).ok());
}

TEST(InputCulling, EveryWrittenTargetLeavesOutTargetsOnlyCulledPassesWrite) {
    // With no outputs named, every target a pass that runs writes is one. "depth_pass" writes
    // "depth" before the image: it still runs while the input replaces "scene", and is culled, its
    // target no output, once the input replaces "depth".
    std::unique_ptr<Workspace> withDepth = sceneWorkspace(true);
    Workspace& ws = *withDepth;
    FramePlanOptions options;
    options.givenInputs = {"photo"};
    Result<FramePlan> plan = planFramePasses(ws, options);
    ASSERT_TRUE(plan.ok()) << formatAll(plan.diagnostics());
    EXPECT_EQ(plan->request.outputs, (Names{"scene", "depth", "output"}));
    EXPECT_EQ(plan->request.givenInputs, (std::set<std::string>{"photo"}));
    // When the input replaces "depth" instead, depth_pass only drew what the image stands in for.
    ws.inputs.front().replaces = "depth";
    Result<FramePlan> replaced = planFramePasses(ws, options);
    ASSERT_TRUE(replaced.ok()) << formatAll(replaced.diagnostics());
    EXPECT_EQ(replaced->request.outputs, (Names{"scene", "output"}));
}

}  // namespace
}  // namespace rmfx
