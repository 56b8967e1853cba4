// The pass graph without GL: which passes run for an output, effects left out or switched off,
// the reasons given, and the order errors validation reports (cycles, reads before writes).

#include "graph/PassGraph.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "graph/Test/HdrLightingWorkspace.h"
#include "graph/Test/Shader5Workspace.h"
#include "graph/Test/WorkspaceBuilder.h"
#include "model/EffectSelection.h"

namespace rmfx {
namespace {

using test::WorkspaceBuilder;

using Names = std::vector<std::string>;

// An 8x8 workspace with these rgba16f targets, declared before its passes.
WorkspaceBuilder workspace(const Names& targets) {
    WorkspaceBuilder b("graph.xml");
    b.targets(targets);
    return b;
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
    auto ws = workspace({"ta", "tb", "tc", "tu"})
                  .pass("a", "ta")
                  .pass("unused", "tu")
                  .pass("b", "tb", {"ta"})
                  .pass("c", "tc", {"tu"})
                  .pass("final", "", {"tb", "ta"})
                  .build();
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
    auto ws = workspace({"t"})
                  .pass("dead", "t")
                  .pass("replace", "t")
                  .pass("blend", "t", {}, test::additiveBlend())
                  .pass("final", "", {"t"})
                  .build();
    PassGraph g = build(*ws);
    EXPECT_EQ(scheduled(g), (Names{"replace", "blend", "final"}));
    EXPECT_EQ(node(g, "dead").why, "'replace' replaces 't' before anything reads it");
    EXPECT_EQ(node(g, "replace").why, "'blend' draws over 't'");
    EXPECT_TRUE(node(g, "blend").loadsTarget);
    EXPECT_FALSE(node(g, "replace").loadsTarget);
}

TEST(PassGraph, AMeshWithoutClearLoadsItsTargetAndAClearDoesNot) {
    auto ws = workspace({"t", "u"})
                  .pass("sky", "t")
                  .pass("model", "t", {}, test::drawMesh(BuiltinMesh::Teapot))
                  .pass("cleared", "u", {}, test::all({test::clearColor({0, 0, 0, 1}), test::drawMesh(BuiltinMesh::Teapot)}))
                  .pass("final", "", {"t", "u"})
                  .build();
    PassGraph g = build(*ws);
    EXPECT_EQ(scheduled(g), (Names{"sky", "model", "cleared", "final"}));
    EXPECT_TRUE(node(g, "model").loadsTarget);
    EXPECT_FALSE(node(g, "cleared").loadsTarget);
    EXPECT_EQ(node(g, "sky").why, "'model' draws over 't'");
}

TEST(PassGraph, APreviousFrameReadNeedsTheTargetsLastWriterAndCarriesIt) {
    auto ws = workspace({"m", "acc"})
                  .pass("measure", "m")
                  .pass("show", "", {"acc'", "m"})
                  .pass("adapt", "acc", {"acc'", "m"})
                  .build();
    PassGraph g = build(*ws);
    // adapt comes after the output's writer, but the output reads what it leaves for the next frame.
    EXPECT_EQ(scheduled(g), (Names{"measure", "show", "adapt"}));
    EXPECT_EQ(node(g, "adapt").why, "'show' reads last frame's 'acc'");
    EXPECT_EQ(g.carriedTargets, (std::set<std::string>{"acc"}));
}

TEST(PassGraph, DisabledPassesAreCulledAndTheirReadersFail) {
    auto ws = workspace({"t", "u", "v"})
                  .pass("a", "t")
                  .pass("off", "u", {}, test::disabled())
                  .pass("final", "", {"t"})
                  .pass("other", "v", {"u"})
                  .build();
    PassGraph g = build(*ws);
    EXPECT_EQ(node(g, "off").fate, PassFate::Disabled);
    EXPECT_EQ(scheduled(g), (Names{"a", "final"}));
    // "other" reads what the disabled pass would have written: an error only when it is needed.
    Result<PassGraph> built = buildPassGraph(*ws, {{"v"}, {}, {}, {}});
    EXPECT_FALSE(built.ok());
    const Diagnostics& d = built.diagnostics();
    ASSERT_EQ(d.size(), 1u);
    // Line 10: each declaration has a line of its own (WorkspaceBuilder), and other's sampler is the tenth.
    EXPECT_EQ(d[0].format(),
              "graph.xml:10: error: <sampler name=\"s0\">: pass 'other' reads target 'u', which no running "
              "pass wrote earlier in the frame");
}

TEST(PassGraph, AnOutputNothingWritesIsAnError) {
    auto ws = workspace({"t", "never"}).pass("a", "t").pass("final", "", {"t"}).build();
    Result<PassGraph> built = buildPassGraph(*ws, {{"never", "nope"}, {}, {}, {}});
    EXPECT_FALSE(built.ok());
    const Diagnostics& d = built.diagnostics();
    ASSERT_EQ(d.size(), 2u);
    EXPECT_EQ(d[0].message, "no running pass writes target 'never', which is asked for; the running passes write 't', 'output' "
                            "(--target NAME)");
    EXPECT_NE(d[1].message.find("no target named 'nope'"), std::string::npos) << d[1].message;
}

// ---- effects: shader_5.xml's glare, streak and ghost (Shader5Workspace.h) ----

Names passesOf(const Workspace& ws, const std::string& prefix) {
    Names names;
    for (const Pass& p : ws.passes)
        if (p.name.rfind(prefix, 0) == 0) names.push_back(p.name);
    return names;
}

TEST(PassGraph, EffectsLeftOutAreCulledAndTheCompositeSkipsTheirTargets) {
    auto ws = test::shader5Workspace();
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
    auto ws = test::shader5Workspace();
    ASSERT_TRUE(ws);
    PassGraph off = build(*ws, {{}, {"glare", "streak", "ghost"}, {"streak"}, {}});
    PassGraph left = build(*ws, {{}, {"glare", "ghost"}, {}, {}});
    EXPECT_EQ(scheduled(off), scheduled(left));
    EXPECT_EQ(node(off, "streak_ur_16").fate, PassFate::EffectSwitchedOff);
    EXPECT_EQ(node(off, "streak_ur_16").why, "effect 'streak' switched off (Streak_Factor all off)");
    EXPECT_EQ(node(off, "combine").skippedInputs, node(left, "combine").skippedInputs);
}

TEST(PassGraph, SwitchesAreOnWhileAnyOfTheirVariablesIsNonZero) {
    auto ws = test::shader5Workspace();
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
    auto ws = test::shader5Workspace();
    ASSERT_TRUE(ws);
    ShaderPrelude p = effectPrelude(*ws, {"glare"});
    EXPECT_EQ(p.defines,
              (Names{"RMFX_EFFECT_glare rmfx_effect_glare", "RMFX_EFFECT_streak false", "RMFX_EFFECT_ghost false"}));
    EXPECT_EQ(p.declarations, (Names{"uniform bool rmfx_effect_glare;"}));
}

TEST(PassGraph, UnknownEffectNamesAreErrorsListingTheDeclaredOnes) {
    auto ws = test::shader5Workspace();
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
    auto ws = workspace({"ta", "tb"}).pass("a", "ta", {"tb"}).pass("b", "tb", {"ta"}).pass("final", "", {"tb"}).build();
    Diagnostics d = checkPassOrder(*ws);
    ASSERT_EQ(d.size(), 1u) << formatAll(d);
    EXPECT_EQ(d[0].format(),
              "graph.xml:5: error: <sampler name=\"s0\">: passes form a cycle: 'a' reads 'tb' from 'b', "
              "'b' reads 'ta' from 'a'; read one of them with frame=\"previous\" to take last frame's "
              "contents");
}

TEST(PassOrder, AThreePassCycleIsWalkedInOrder) {
    auto ws = workspace({"ta", "tb", "tc"})
                  .pass("a", "ta", {"tc"})
                  .pass("b", "tb", {"ta"})
                  .pass("c", "tc", {"tb"})
                  .pass("final", "", {"tc"})
                  .build();
    Diagnostics d = checkPassOrder(*ws);
    ASSERT_EQ(d.size(), 1u) << formatAll(d);
    EXPECT_NE(d[0].message.find("passes form a cycle: 'a' reads 'tc' from 'c', 'c' reads 'tb' from 'b', 'b' reads 'ta' "
                                "from 'a'"),
              std::string::npos)
        << d[0].message;
    // Reading last frame's tc breaks it.
    auto fixed = workspace({"ta", "tb", "tc"})
                     .pass("a", "ta", {"tc'"})
                     .pass("b", "tb", {"ta"})
                     .pass("c", "tc", {"tb"})
                     .pass("final", "", {"tc"})
                     .build();
    EXPECT_TRUE(checkPassOrder(*fixed).empty()) << formatAll(checkPassOrder(*fixed));
}

TEST(PassOrder, AReadBeforeTheWriteNamesTheLaterWriter) {
    auto ws = workspace({"t", "te"}).pass("early", "te", {"t"}).pass("write", "t").pass("final", "", {"te"}).build();
    Diagnostics d = checkPassOrder(*ws);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].message,
              "pass 'early' reads target 't' before any pass writes it in the frame ('write' writes it "
              "later); move the pass after it, or read last frame's contents with frame=\"previous\"");
}

TEST(PassOrder, ATargetNothingWritesIsAnErrorUnlessReadAsLastFrames) {
    auto ws = workspace({"ghost"}).pass("final", "", {"ghost"}).build();
    Diagnostics d = checkPassOrder(*ws);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_NE(d[0].message.find("pass 'final' reads target 'ghost', which no pass writes"), std::string::npos);
    EXPECT_TRUE(checkPassOrder(*workspace({"ghost"}).pass("final", "", {"ghost'"}).build()).empty());
}

// Every workspace of effects/ is checked as loaded in validation/Test/ProjectWorkspaceOrderTest.
TEST(PassOrder, TheGlareWorkspacesAreInOrder) {
    auto shader5 = test::shader5Workspace();
    EXPECT_TRUE(checkPassOrder(*shader5).empty()) << formatAll(checkPassOrder(*shader5));
    auto hdrLighting = test::hdrLightingWorkspace();
    EXPECT_TRUE(checkPassOrder(*hdrLighting).empty()) << formatAll(checkPassOrder(*hdrLighting));
}

}  // namespace
}  // namespace rmfx
