// <input>s in the pass graph, without GL: an image given for an input that replaces a target culls
// the passes that drew the target before it, an input not given culls the passes that sample it,
// and a required input that is missing is an error naming the sampler.

#include <gtest/gtest.h>

#include "frontend/workspace/WorkspaceParser.h"
#include "graph/FramePlan.h"
#include "graph/PassGraph.h"
#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

using Names = std::vector<std::string>;

// A scene drawn by two passes (the second draws over the first), the image put into it by
// "from_input", a pass that draws over the scene after it, and the output reading the scene.
const std::string kScene = test::lines({
    "<workspace version=\"1\" name=\"inputs\" size=\"8x8\">",
    "  <target name=\"scene\" format=\"rgba16f\"/>",
    "  <input name=\"photo\" replaces=\"scene\"/>",
    "  <pass name=\"sky\" target=\"scene\">",
    "    <clear color=\"0 0 0 1\"/>",
    "    <shader stage=\"fragment\">out vec4 c; void main() { c = vec4(1.0); }</shader>",
    "  </pass>",
    "  <pass name=\"teapot\" target=\"scene\">",
    "    <draw mesh=\"teapot\"/>",
    "    <shader stage=\"fragment\">out vec4 c; void main() { c = vec4(1.0); }</shader>",
    "  </pass>",
    "  <pass name=\"from_input\" target=\"scene\">",
    "    <sampler name=\"Image\" texture=\"photo\"/>",
    "    <shader stage=\"fragment\">uniform sampler2D Image; out vec4 c; void main() { c = texture(Image, vec2(0.5)); }</shader>",
    "  </pass>",
    "  <pass name=\"overlay\" target=\"scene\">",
    "    <blend src=\"one\" dst=\"one\"/>",
    "    <shader stage=\"fragment\">out vec4 c; void main() { c = vec4(0.1); }</shader>",
    "  </pass>",
    "  <pass name=\"screen\">",
    "    <sampler name=\"Scene\" target=\"scene\"/>",
    "    <shader stage=\"fragment\">uniform sampler2D Scene; out vec4 c; void main() { c = texture(Scene, vec2(0.5)); }</shader>",
    "  </pass>",
    "</workspace>",
});

Workspace parse(const std::string& xml) {
    Result<Workspace> parsed = parseWorkspaceText(xml, "inputs.xml", ".");
    EXPECT_TRUE(parsed.ok()) << formatAll(parsed.diagnostics());
    return parsed ? std::move(*parsed) : Workspace{};
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
    Workspace ws = parse(kScene);
    Result<PassGraph> g = buildPassGraph(ws, {{}, {}, {}, {"photo"}});
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
    Workspace ws = parse(kScene);
    Result<PassGraph> g = buildPassGraph(ws, {});
    ASSERT_TRUE(g.ok()) << formatAll(g.diagnostics());
    EXPECT_EQ(scheduled(*g), (Names{"sky", "teapot", "overlay", "screen"}));
    EXPECT_EQ(node(*g, "from_input").fate, PassFate::InputNotGiven);
    EXPECT_EQ(node(*g, "from_input").why,
              "no image given for input 'photo' (rmfx render --input photo=FILE): the workspace draws 'scene' itself");
    EXPECT_STREQ(passFateName(PassFate::InputNotGiven), "culled: input not given");
}

TEST(InputCulling, ARequiredInputWithoutAnImageIsAnErrorAtTheSampler) {
    Workspace ws = parse(test::lines({
        "<workspace version=\"1\" size=\"8x8\">",
        "  <input name=\"photo\"/>",
        "  <pass name=\"screen\">",
        "    <sampler name=\"Image\" texture=\"photo\"/>",
        "    <shader stage=\"fragment\">uniform sampler2D Image; out vec4 c; void main() { c = texture(Image, vec2(0.5)); }</shader>",
        "  </pass>",
        "</workspace>",
    }));
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
    std::string xml = kScene;
    xml.insert(xml.find("  <pass name=\"from_input\""),
               "  <pass name=\"depth_pass\" target=\"depth\">\n"
               "    <shader stage=\"fragment\">out vec4 c; void main() { c = vec4(1.0); }</shader>\n  </pass>\n");
    xml.insert(xml.find("  <input"), "  <target name=\"depth\" format=\"r32f\"/>\n");
    Workspace ws = parse(xml);
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
