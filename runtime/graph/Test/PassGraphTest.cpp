// The pass graph without GL: which passes run for an output, effects left out or switched off,
// the reasons given, and the order errors validation reports (cycles, reads before writes).

#include "graph/PassGraph.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "frontend/workspace/WorkspaceParser.h"
#include "model/EffectSelection.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx {
namespace {

using test::passXml;

using Names = std::vector<std::string>;

std::unique_ptr<Workspace> parse(const std::string& xml) {
    Result<Workspace> parsed = parseWorkspaceText(xml, "graph.xml", ".");
    EXPECT_FALSE(hasErrors(parsed.diagnostics())) << formatAll(parsed.diagnostics());
    if (!parsed.ok()) return nullptr;
    return std::make_unique<Workspace>(std::move(*parsed));
}

std::string workspace(const std::string& body, const Names& targets) {
    std::string xml = "<workspace version=\"1\" name=\"graph\" size=\"8x8\">\n";
    for (const std::string& t : targets) xml += "  <target name=\"" + t + "\" format=\"rgba16f\"/>\n";
    return xml + body + "</workspace>\n";
}

Names scheduled(const PassGraph& g) {
    Names names;
    for (int i : g.schedule) names.push_back(g.nodes[static_cast<size_t>(i)].pass->name);
    return names;
}

PassGraph build(const Workspace& ws, FrameRequest request = {}) {
    if (request.effects.empty())
        for (const Effect& e : ws.effects) request.effects.insert(e.name);
    Result<PassGraph> g = buildPassGraph(ws, request);
    EXPECT_TRUE(g.ok()) << formatAll(g.diagnostics());
    return g ? std::move(*g) : PassGraph{};
}

const PassNode& node(const PassGraph& g, const std::string& name) {
    return g.nodes[static_cast<size_t>(g.passIndex(name))];
}

TEST(PassGraph, OnlyThePassesTheOutputNeedsRunInDocumentOrder) {
    auto ws = parse(workspace(passXml("a", "ta", {}) + passXml("unused", "tu", {}) + passXml("b", "tb", {"ta"}) +
                                  passXml("c", "tc", {"tu"}) + passXml("final", "", {"tb", "ta"}),
                              {"ta", "tb", "tc", "tu"}));
    PassGraph g = build(*ws);
    EXPECT_EQ(scheduled(g), (Names{"a", "b", "final"}));
    EXPECT_EQ(node(g, "unused").fate, PassFate::NotNeeded);
    EXPECT_EQ(node(g, "c").fate, PassFate::NotNeeded);
    EXPECT_EQ(node(g, "c").why, "nothing asked for reads 'tc'");
    EXPECT_EQ(node(g, "a").why, "'final' reads 'ta'");  // the reader nearest the output names it
    EXPECT_EQ(node(g, "final").why, "writes 'output', which is asked for");

    // Asking for tc instead runs exactly its chain.
    PassGraph onlyC = build(*ws, {{"tc"}, {}, {}, {}});
    EXPECT_EQ(scheduled(onlyC), (Names{"unused", "c"}));
    // Two outputs: the union.
    EXPECT_EQ(scheduled(build(*ws, {{"tc", "tb"}, {}, {}, {}})), (Names{"a", "unused", "b", "c"}));
}

TEST(PassGraph, AWriteReplacedBeforeAnyReadIsCulledAndABlendKeepsItsPredecessor) {
    auto ws =
        parse(workspace(passXml("dead", "t", {}) + passXml("replace", "t", {}) +
                            passXml("blend", "t", {}, "    <blend mode=\"add\"/>\n") + passXml("final", "", {"t"}),
                        {"t"}));
    PassGraph g = build(*ws);
    EXPECT_EQ(scheduled(g), (Names{"replace", "blend", "final"}));
    EXPECT_EQ(node(g, "dead").why, "'replace' replaces 't' before anything reads it");
    EXPECT_EQ(node(g, "replace").why, "'blend' draws over 't'");
    EXPECT_TRUE(node(g, "blend").loadsTarget);
    EXPECT_FALSE(node(g, "replace").loadsTarget);
}

TEST(PassGraph, AMeshWithoutClearLoadsItsTargetAndAClearDoesNot) {
    auto ws = parse(
        workspace(passXml("sky", "t", {}) + passXml("model", "t", {}, "    <draw mesh=\"teapot\"/>\n") +
                      passXml("cleared", "u", {}, "    <clear color=\"0 0 0 1\"/>\n    <draw mesh=\"teapot\"/>\n") +
                      passXml("final", "", {"t", "u"}),
                  {"t", "u"}));
    PassGraph g = build(*ws);
    EXPECT_EQ(scheduled(g), (Names{"sky", "model", "cleared", "final"}));
    EXPECT_TRUE(node(g, "model").loadsTarget);
    EXPECT_FALSE(node(g, "cleared").loadsTarget);
    EXPECT_EQ(node(g, "sky").why, "'model' draws over 't'");
}

TEST(PassGraph, APreviousFrameReadNeedsTheTargetsLastWriterAndCarriesIt) {
    auto ws = parse(workspace(
        passXml("measure", "m", {}) + passXml("show", "", {"acc'", "m"}) + passXml("adapt", "acc", {"acc'", "m"}),
        {"m", "acc"}));
    PassGraph g = build(*ws);
    // adapt comes after the output's writer, but the output reads what it leaves for the next frame.
    EXPECT_EQ(scheduled(g), (Names{"measure", "show", "adapt"}));
    EXPECT_EQ(node(g, "adapt").why, "'show' reads last frame's 'acc'");
    EXPECT_EQ(g.carriedTargets, (std::set<std::string>{"acc"}));
}

TEST(PassGraph, DisabledPassesAreCulledAndTheirReadersFail) {
    auto ws = parse(workspace(passXml("a", "t", {}) +
                                  "  <pass name=\"off\" target=\"u\" enabled=\"false\">\n"
                                  "    <shader stage=\"fragment\">out vec4 c; void main() { c = vec4(1.0); }</shader>\n"
                                  "  </pass>\n" +
                                  passXml("final", "", {"t"}) + passXml("other", "v", {"u"}),
                              {"t", "u", "v"}));
    PassGraph g = build(*ws);
    EXPECT_EQ(node(g, "off").fate, PassFate::Disabled);
    EXPECT_EQ(scheduled(g), (Names{"a", "final"}));
    // "other" reads what the disabled pass would have written: an error only when it is needed.
    Result<PassGraph> built = buildPassGraph(*ws, {{"v"}, {}, {}, {}});
    EXPECT_FALSE(built.ok());
    const Diagnostics& d = built.diagnostics();
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].format(),
              "graph.xml:16: error: <sampler name=\"s0\">: pass 'other' reads target 'u', which no running "
              "pass wrote earlier in the frame");
}

TEST(PassGraph, AnOutputNothingWritesIsAnError) {
    auto ws = parse(workspace(passXml("a", "t", {}) + passXml("final", "", {"t"}), {"t", "never"}));
    Result<PassGraph> built = buildPassGraph(*ws, {{"never", "nope"}, {}, {}, {}});
    EXPECT_FALSE(built.ok());
    const Diagnostics& d = built.diagnostics();
    ASSERT_EQ(d.size(), 2u);
    EXPECT_EQ(d[0].message, "no running pass writes target 'never', which is asked for; the running passes write 't', 'output' "
                            "(--target NAME)");
    EXPECT_NE(d[1].message.find("no target named 'nope'"), std::string::npos) << d[1].message;
}

// ---- effects ----

std::unique_ptr<Workspace> shader5() {
    Result<Workspace> loaded = loadWorkspace(test::sourceDir() / "effects/shader_5.xml", {false});
    EXPECT_TRUE(loaded.ok()) << formatAll(loaded.diagnostics());
    if (!loaded.ok()) return nullptr;
    return std::make_unique<Workspace>(std::move(*loaded));
}

Names passesOf(const Workspace& ws, const std::string& prefix) {
    Names names;
    for (const Pass& p : ws.passes)
        if (p.name.rfind(prefix, 0) == 0) names.push_back(p.name);
    return names;
}

TEST(PassGraph, EffectsLeftOutAreCulledAndTheCompositeSkipsTheirTargets) {
    auto ws = shader5();
    ASSERT_TRUE(ws);
    PassGraph g = build(*ws, {{}, {"glare"}, {}, {}});
    Names expected{"environment", "teapot"};
    for (const std::string& p : passesOf(*ws, "glare_")) expected.push_back(p);
    expected.insert(expected.end(), {"screen", "combine"});
    EXPECT_EQ(scheduled(g), expected);
    for (const std::string& p : passesOf(*ws, "streak_")) {
        EXPECT_EQ(node(g, p).fate, PassFate::EffectLeftOut) << p;
        EXPECT_EQ(node(g, p).why, "effect 'streak' not asked for (asked for: glare)");
    }
    EXPECT_EQ(node(g, "ghost_1").fate, PassFate::EffectLeftOut);
    EXPECT_EQ(node(g, "combine").skippedInputs,
              (Names{"ghost_2", "streak_dl_16", "streak_dr_16", "streak_ul_16", "streak_ur_16"}));
    EXPECT_TRUE(node(g, "combine").loadsTarget);  // blends onto the screen copy
}

TEST(PassGraph, AnEffectSwitchedOffIsCulledLikeOneLeftOut) {
    auto ws = shader5();
    ASSERT_TRUE(ws);
    PassGraph off = build(*ws, {{}, {"glare", "streak", "ghost"}, {"streak"}, {}});
    PassGraph left = build(*ws, {{}, {"glare", "ghost"}, {}, {}});
    EXPECT_EQ(scheduled(off), scheduled(left));
    EXPECT_EQ(node(off, "streak_ur_16").fate, PassFate::EffectSwitchedOff);
    EXPECT_EQ(node(off, "streak_ur_16").why, "effect 'streak' switched off (Streak_Factor all off)");
    EXPECT_EQ(node(off, "combine").skippedInputs, node(left, "combine").skippedInputs);
}

TEST(PassGraph, SwitchesAreOnWhileAnyOfTheirVariablesIsNonZero) {
    auto ws = shader5();
    ASSERT_TRUE(ws);
    std::map<std::string, Value> values;
    for (const Variable& v : ws->variables) values[v.name] = v.value;
    std::set<std::string> all{"glare", "streak", "ghost"};
    EXPECT_TRUE(switchedOffEffects(*ws, all, values).empty());
    values["Glow_Factor"].data[0] = 0.0f;
    values["Glow_Factor2"].data[0] = 0.0f;
    EXPECT_TRUE(switchedOffEffects(*ws, all, values).empty()) << "Glow_Factor3 still on";
    values["Glow_Factor3"].data[0] = 0.0f;
    values["Ghost_Factor"].data[0] = 0.0f;
    EXPECT_EQ(switchedOffEffects(*ws, all, values), (std::set<std::string>{"ghost", "glare"}));
    values["Glow_Factor2"].data[0] = -1e-30f;  // tiny but not zero: on
    EXPECT_EQ(switchedOffEffects(*ws, all, values), (std::set<std::string>{"ghost"}));
    // An effect left out is not "switched off": it is not there at all.
    EXPECT_EQ(switchedOffEffects(*ws, {"glare"}, values), (std::set<std::string>{}));
}

TEST(PassGraph, TheShaderPreludeFollowsTheSelection) {
    auto ws = shader5();
    ASSERT_TRUE(ws);
    ShaderPrelude p = effectPrelude(*ws, {"glare"});
    EXPECT_EQ(p.defines,
              (Names{"RMFX_EFFECT_glare rmfx_effect_glare", "RMFX_EFFECT_streak false", "RMFX_EFFECT_ghost false"}));
    EXPECT_EQ(p.declarations, (Names{"uniform bool rmfx_effect_glare;"}));
}

TEST(PassGraph, UnknownEffectNamesAreErrorsListingTheDeclaredOnes) {
    auto ws = shader5();
    ASSERT_TRUE(ws);
    auto bad = selectEffects(*ws, Names{"glare", "bloom"});
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().find("no effect named 'bloom'"), std::string::npos);
    EXPECT_NE(bad.error().find("(it has: ghost, glare, streak)"), std::string::npos) << bad.error();
    EXPECT_EQ(*selectEffects(*ws, std::nullopt), (std::set<std::string>{"ghost", "glare", "streak"}));
    ws->output.effects = Names{"ghost"};
    EXPECT_EQ(*selectEffects(*ws, std::nullopt), (std::set<std::string>{"ghost"}));
    EXPECT_EQ(*selectEffects(*ws, Names{"streak"}), (std::set<std::string>{"streak"})) << "--effects wins";
}

// ---- validation: order ----

TEST(PassOrder, ATwoPassCycleNamesBothPassesAndTheTargets) {
    auto ws = parse(workspace(passXml("a", "ta", {"tb"}) + passXml("b", "tb", {"ta"}) + passXml("final", "", {"tb"}),
                              {"ta", "tb"}));
    Diagnostics d = checkPassOrder(*ws);
    ASSERT_EQ(d.size(), 1u) << formatAll(d);
    EXPECT_EQ(d[0].format(),
              "graph.xml:5: error: <sampler name=\"s0\">: passes form a cycle: 'a' reads 'tb' from 'b', "
              "'b' reads 'ta' from 'a'; read one of them with frame=\"previous\" to take last frame's "
              "contents");
}

TEST(PassOrder, AThreePassCycleIsWalkedInOrder) {
    auto ws = parse(workspace(passXml("a", "ta", {"tc"}) + passXml("b", "tb", {"ta"}) + passXml("c", "tc", {"tb"}) +
                                  passXml("final", "", {"tc"}),
                              {"ta", "tb", "tc"}));
    Diagnostics d = checkPassOrder(*ws);
    ASSERT_EQ(d.size(), 1u) << formatAll(d);
    EXPECT_NE(d[0].message.find("passes form a cycle: 'a' reads 'tc' from 'c', 'c' reads 'tb' from 'b', 'b' reads 'ta' "
                                "from 'a'"),
              std::string::npos)
        << d[0].message;
    // Reading last frame's tc breaks it.
    auto fixed = parse(workspace(passXml("a", "ta", {"tc'"}) + passXml("b", "tb", {"ta"}) + passXml("c", "tc", {"tb"}) +
                                     passXml("final", "", {"tc"}),
                                 {"ta", "tb", "tc"}));
    EXPECT_TRUE(checkPassOrder(*fixed).empty()) << formatAll(checkPassOrder(*fixed));
}

TEST(PassOrder, AReadBeforeTheWriteNamesTheLaterWriter) {
    auto ws = parse(workspace(passXml("early", "te", {"t"}) + passXml("write", "t", {}) + passXml("final", "", {"te"}),
                              {"t", "te"}));
    Diagnostics d = checkPassOrder(*ws);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].message,
              "pass 'early' reads target 't' before any pass writes it in the frame ('write' writes it "
              "later); move the pass after it, or read last frame's contents with frame=\"previous\"");
}

TEST(PassOrder, ATargetNothingWritesIsAnErrorUnlessReadAsLastFrames) {
    auto ws = parse(workspace(passXml("final", "", {"ghost"}), {"ghost"}));
    Diagnostics d = checkPassOrder(*ws);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_NE(d[0].message.find("pass 'final' reads target 'ghost', which no pass writes"), std::string::npos);
    EXPECT_TRUE(checkPassOrder(*parse(workspace(passXml("final", "", {"ghost'"}), {"ghost"}))).empty());
}

TEST(PassOrder, EveryProjectWorkspaceIsInOrder) {
    for (const auto& entry : std::filesystem::directory_iterator(test::sourceDir() / "effects")) {
        if (entry.path().extension() != ".xml") continue;
        Result<Workspace> loaded = loadWorkspace(entry.path(), {false});
        ASSERT_TRUE(loaded.ok()) << entry.path() << formatAll(loaded.diagnostics());
        EXPECT_TRUE(checkPassOrder(*loaded).empty()) << entry.path();
    }
}

}  // namespace
}  // namespace rmfx
