// The frame plan without GL (as Filament tests its frame graph on a no-op backend): which passes
// run for the outputs and effects asked for, under each setting of the effect switches, which
// targets get memory and which share it, and the limits checked before anything is allocated.

#include "graph/FramePlan.h"

#include <gtest/gtest.h>

#include "graph/Test/WorkspaceBuilder.h"

namespace rmfx {
namespace {

using test::WorkspaceBuilder;
using Names = std::vector<std::string>;

constexpr int kNoSizeLimit = 16384;

// scene → a; glow (effect "glow", switched by Glow) reads a → b; final reads a and b → output;
// stray → c, which nothing reads.
std::unique_ptr<Workspace> effectWorkspace() {
    return WorkspaceBuilder("frame.xml")
        .targets({"a", "b", "c"})
        .variable("Glow", Value::ofFloat(1.0f))
        .effect({.name = "glow", .passes = {"glow"}, .switches = {"Glow"}})
        .pass("scene", "a")
        .pass("glow", "b", {"a"})
        .pass("final", "", {"a", "b"})
        .pass("stray", "c")
        .build();
}

// a → b → c → d, d an rgba8 output: a and c (rgba16f, 8x8) can share, b overlaps both.
std::unique_ptr<Workspace> chainWorkspace() {
    return WorkspaceBuilder("frame.xml")
        .targets({"a", "b", "c"})
        .target("d", TargetFormat::RGBA8)
        .pass("p1", "a")
        .pass("p2", "b", {"a"})
        .pass("p3", "c", {"b"})
        .pass("p4", "d", {"c"})
        .build();
}

Names scheduled(const Workspace& ws, const PassGraph& g) {
    Names names;
    for (int i : g.schedule) names.push_back(ws.passes[static_cast<size_t>(i)].name);
    return names;
}

FramePlanOptions outputs(Names names) {
    FramePlanOptions options;
    options.outputs = std::move(names);
    return options;
}

TEST(FramePlan, PassesNoOutputNeedsAreCulledAndTheirTargetsGetNoMemory) {
    auto ws = effectWorkspace();
    ASSERT_TRUE(ws);
    auto plan = planFrame(*ws, outputs({"output"}), {8, 8}, declaredValues(*ws), kNoSizeLimit);
    ASSERT_TRUE(plan) << plan.error();
    FrameVariant on = plan->variant({});
    ASSERT_TRUE(on.graph);
    EXPECT_EQ(scheduled(*ws, *on.graph), (Names{"scene", "glow", "final"}));
    EXPECT_EQ(plan->runnablePasses(), (std::set<int>{0, 1, 2}));
    const TargetPlan& targets = plan->targets;
    EXPECT_EQ(targets.targets[static_cast<size_t>(targets.find("c"))].resource, -1);
    EXPECT_GE(targets.targets[static_cast<size_t>(targets.find("a"))].resource, 0);
    EXPECT_GE(targets.targets[static_cast<size_t>(targets.find("b"))].resource, 0);
}

// <effect gate>: the pass writing the gate is needed only where content skip counts it before
// the effect (content skip on and the effect asked for); its target then lives until the effect.
TEST(FramePlan, AnEffectsGateRunsOnlyWhereContentSkipCountsIt) {
    auto ws = WorkspaceBuilder("frame.xml")
                  .targets({"a", "b"})
                  .target("g", TargetFormat::R32F, test::fixedSize(1, 1))
                  .effect({.name = "glow", .passes = {"glow"}, .source = "a", .gate = "g"})
                  .pass("scene", "a")
                  .pass("gate", "g", {"a"})
                  .pass("glow", "b", {"a"})
                  .pass("final", "", {"a", "b"})
                  .build();
    ASSERT_TRUE(ws);
    FramePlanOptions options = outputs({"output"});
    auto on = planFrame(*ws, options, {8, 8}, declaredValues(*ws), kNoSizeLimit);
    ASSERT_TRUE(on) << on.error();
    EXPECT_EQ(scheduled(*ws, *on->variant({}).graph), (Names{"scene", "gate", "glow", "final"}));
    const PassNode& glow = on->variant({}).graph->nodes[2];
    EXPECT_EQ(glow.gate, "g");
    EXPECT_EQ(on->variant({}).graph->nodes[1].why, "content skip counts 'g' to decide whether effect 'glow' runs");
    const PlannedTarget& gate = on->targets.targets[static_cast<size_t>(on->targets.find("g"))];
    EXPECT_EQ(gate.lastUse, 2) << "the gate lives until the effect's pass";

    options.contentSkip = false;
    auto off = planFrame(*ws, options, {8, 8}, declaredValues(*ws), kNoSizeLimit);
    ASSERT_TRUE(off) << off.error();
    EXPECT_EQ(scheduled(*ws, *off->variant({}).graph), (Names{"scene", "glow", "final"}));
    EXPECT_TRUE(off->variant({}).graph->nodes[2].gate.empty());

    options.contentSkip = true;
    options.effects = std::vector<std::string>{};
    auto none = planFrame(*ws, options, {8, 8}, declaredValues(*ws), kNoSizeLimit);
    ASSERT_TRUE(none) << none.error();
    EXPECT_EQ(scheduled(*ws, *none->variant({}).graph), (Names{"scene", "final"}));
}

TEST(FramePlan, WithNoOutputsNamedEveryWrittenTargetIsAnOutput) {
    auto ws = effectWorkspace();
    ASSERT_TRUE(ws);
    auto plan = planFramePasses(*ws, {});
    ASSERT_TRUE(plan) << plan.error();
    EXPECT_EQ(plan->request.outputs, (Names{"a", "b", "c", "output"}));
    EXPECT_FALSE(plan->pooled());
    EXPECT_EQ(scheduled(*ws, *plan->variant({}).graph), (Names{"scene", "glow", "final", "stray"}));
}

TEST(FramePlan, EachSettingOfTheSwitchesHasItsGraphAndTheValuesPickOne) {
    auto ws = effectWorkspace();
    ASSERT_TRUE(ws);
    auto plan = planFramePasses(*ws, outputs({"output"}));
    ASSERT_TRUE(plan) << plan.error();
    EXPECT_EQ(plan->askedEffects, (std::set<std::string>{"glow"}));
    ASSERT_EQ(plan->graphs.size(), 2u);  // glow on, glow off
    std::map<std::string, Value> values = declaredValues(*ws);
    FrameVariant on = plan->variantFor(*ws, values);
    EXPECT_TRUE(on.switchedOff.empty());
    EXPECT_EQ(scheduled(*ws, *on.graph), (Names{"scene", "glow", "final"}));
    values["Glow"] = Value::ofFloat(0.0f);
    FrameVariant off = plan->variantFor(*ws, values);
    EXPECT_EQ(off.switchedOff, (std::set<std::string>{"glow"}));
    EXPECT_EQ(scheduled(*ws, *off.graph), (Names{"scene", "final"}));
    // One set of targets serves both: b keeps its memory while glow is off.
    auto targets = planFrameTargets(*ws, *plan, {8, 8}, values, kNoSizeLimit);
    ASSERT_TRUE(targets) << targets.error();
    EXPECT_GE(targets->targets[static_cast<size_t>(targets->find("b"))].resource, 0);
}

TEST(FramePlan, AnEffectNotAskedForIsLeftOutOfEveryGraph) {
    auto ws = effectWorkspace();
    ASSERT_TRUE(ws);
    FramePlanOptions options = outputs({"output"});
    options.effects = Names{};
    auto plan = planFrame(*ws, options, {8, 8}, declaredValues(*ws), kNoSizeLimit);
    ASSERT_TRUE(plan) << plan.error();
    EXPECT_TRUE(plan->askedEffects.empty());
    ASSERT_EQ(plan->graphs.size(), 1u);
    EXPECT_EQ(scheduled(*ws, *plan->variant({}).graph), (Names{"scene", "final"}));
    EXPECT_EQ(plan->targets.targets[static_cast<size_t>(plan->targets.find("b"))].resource, -1);

    options.effects = Names{"bloom"};
    auto unknown = planFramePasses(*ws, options);
    ASSERT_FALSE(unknown);
    EXPECT_NE(unknown.error().find("bloom"), std::string::npos) << unknown.error();
}

TEST(FramePlan, TargetsWhoseLifetimesDoNotOverlapShareMemoryOnlyWhenPooled) {
    auto ws = chainWorkspace();
    ASSERT_TRUE(ws);
    auto pooled = planFrame(*ws, outputs({"d"}), {8, 8}, declaredValues(*ws), kNoSizeLimit);
    ASSERT_TRUE(pooled) << pooled.error();
    const TargetPlan& p = pooled->targets;
    auto resourceOf = [](const TargetPlan& plan, const char* name) {
        return plan.targets[static_cast<size_t>(plan.find(name))].resource;
    };
    EXPECT_EQ(resourceOf(p, "a"), resourceOf(p, "c"));
    EXPECT_NE(resourceOf(p, "a"), resourceOf(p, "b"));
    EXPECT_NE(resourceOf(p, "d"), resourceOf(p, "a"));
    EXPECT_EQ(p.resources.size(), 3u);
    EXPECT_EQ(targetTextureCount(p), 3);
    // 8x8 rgba16f is 512 bytes, 8x8 rgba8 256: {a, c}, b and d.
    EXPECT_EQ(p.allocatedBytes, 512u + 512u + 256u);

    FramePlanOptions own = outputs({"d"});
    own.poolTargets = false;
    auto unpooled = planFrame(*ws, own, {8, 8}, declaredValues(*ws), kNoSizeLimit);
    ASSERT_TRUE(unpooled) << unpooled.error();
    EXPECT_EQ(targetTextureCount(unpooled->targets), 4);
    EXPECT_EQ(unpooled->targets.allocatedBytes, 3u * 512u + 256u);
}

TEST(FramePlan, LimitsFailBeforeAnythingIsAllocated) {
    auto ws = chainWorkspace();
    ASSERT_TRUE(ws);
    auto viewport = planFrame(*ws, outputs({"d"}), {8, 8}, declaredValues(*ws), 4);
    ASSERT_FALSE(viewport);
    EXPECT_NE(viewport.error().find("viewport size 8x8 is larger than this GL allows"), std::string::npos)
        << viewport.error();

    FramePlanOptions tight = outputs({"d"});
    tight.memoryBudget = 1279;  // one byte short of the 1280 the pooled targets need
    auto over = planFrame(*ws, tight, {8, 8}, declaredValues(*ws), kNoSizeLimit);
    ASSERT_FALSE(over);
    EXPECT_NE(over.error().find("more than the memory budget"), std::string::npos) << over.error();
    tight.memoryBudget = 1280;
    EXPECT_TRUE(planFrame(*ws, tight, {8, 8}, declaredValues(*ws), kNoSizeLimit));
}

}  // namespace
}  // namespace rmfx
