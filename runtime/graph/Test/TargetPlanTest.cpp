// Target allocation without GL: only targets a scheduled pass uses get memory, lifetimes that do
// not overlap share it, carried targets never do, and the byte counts are what the formats need.

#include "graph/TargetPlan.h"

#include <gtest/gtest.h>

#include "graph/Test/WorkspaceBuilder.h"

namespace rmfx {
namespace {

using test::WorkspaceBuilder;

using Names = std::vector<std::string>;

struct Planned {
    std::unique_ptr<Workspace> ws;
    PassGraph graph;
    TargetPlan plan;
};

Planned planWorkspace(std::unique_ptr<Workspace> ws, FrameRequest request = {}, bool pool = true) {
    Planned p;
    p.ws = std::move(ws);
    Result<PassGraph> graph = buildPassGraph(*p.ws, request);
    EXPECT_TRUE(graph.ok()) << formatAll(graph.diagnostics());
    if (graph) p.graph = std::move(*graph);
    std::map<std::string, Value> values;
    for (const Variable& v : p.ws->variables) values[v.name] = v.value;
    auto plan = planTargets(*p.ws, {&p.graph}, {p.ws->width, p.ws->height}, values, pool);
    EXPECT_TRUE(plan) << (plan ? "" : plan.error());
    if (plan) p.plan = *plan;
    return p;
}

// An 8x8 workspace; its targets rgba16f unless said otherwise.
WorkspaceBuilder workspace() { return WorkspaceBuilder("plan.xml"); }

Names sharing(const TargetPlan& plan, const std::string& name) {
    Names names;
    const PlannedTarget& t = plan.targets[static_cast<size_t>(plan.find(name))];
    for (int k : plan.resources[static_cast<size_t>(t.resource)].targets)
        names.push_back(plan.targets[static_cast<size_t>(k)].name);
    return names;
}

TEST(TargetPlan, AChainPingPongsBetweenTwoTexturesAndTheOutputReusesOne) {
    auto chain = [] {
        return workspace()
            .targets({"ta", "tb", "tc", "td"})
            .pass("a", "ta")
            .pass("b", "tb", {"ta"})
            .pass("c", "tc", {"tb"})
            .pass("d", "td", {"tc"})
            .pass("final", "", {"td"})
            .build();
    };
    Planned p = planWorkspace(chain());
    // Lifetimes (pass indices): ta 0..1, tb 1..2, tc 2..3, td 3..4, output 4..end.
    EXPECT_EQ(p.plan.resources.size(), 2u);
    EXPECT_EQ(sharing(p.plan, "ta"), (Names{"ta", "tc", "output"}));
    EXPECT_EQ(sharing(p.plan, "tb"), (Names{"tb", "td"}));
    const std::size_t one = 8 * 8 * 8;  // rgba16f: 8 bytes a pixel
    EXPECT_EQ(p.plan.allocatedBytes, 2 * one);
    EXPECT_EQ(p.plan.declaredBytes, 5 * one);
    const PlannedTarget& output = p.plan.targets[static_cast<size_t>(p.plan.find("output"))];
    EXPECT_EQ(output.firstUse, 4);
    EXPECT_EQ(output.lastUse, 5) << "an output lives to the end of the frame";

    Planned unpooled = planWorkspace(chain(), {}, false);
    EXPECT_EQ(unpooled.plan.resources.size(), 5u);
    EXPECT_EQ(unpooled.plan.allocatedBytes, 5 * one);
}

TEST(TargetPlan, OnlySameSizeFormatAndDepthShare) {
    Planned p = planWorkspace(workspace()
                         .target("half")
                         .target("full32", TargetFormat::RGBA32F)
                         .target("small", TargetFormat::RGBA16F, test::fixedSize(4, 4))
                         .targets({"deep", "late"})
                         .pass("a", "half")
                         .pass("b", "full32", {"half"})
                         .pass("c", "small", {"full32"})
                         .pass("d", "deep", {"small"}, test::clearDepth(1.0f))
                         .pass("e", "late", {"deep"})
                         .pass("final", "", {"late"})
                         .build());
    EXPECT_EQ(sharing(p.plan, "half"), (Names{"half", "late"}));  // deep has a depth buffer, half has not
    EXPECT_EQ(sharing(p.plan, "full32"), (Names{"full32"}));
    EXPECT_EQ(sharing(p.plan, "small"), (Names{"small"}));
    EXPECT_EQ(sharing(p.plan, "deep"), (Names{"deep"}));
    EXPECT_EQ(p.plan.targets[static_cast<size_t>(p.plan.find("deep"))].bytes, 8u * 8 * 8 + 8 * 8 * 4);
}

TEST(TargetPlan, CarriedTargetsGetMemoryOfTheirOwn) {
    // acc is read as last frame's (two buffers); blendOnly is drawn over before anything writes it.
    Planned p = planWorkspace(workspace()
                         .targets({"m", "acc", "blendOnly", "later"})
                         .pass("measure", "m")
                         .pass("adapt", "acc", {"acc'", "m"})
                         .pass("glow", "blendOnly", {"acc"}, test::additiveBlend())
                         .pass("after", "later", {"blendOnly"})
                         .pass("final", "", {"later", "acc"})
                         .build());
    const PlannedTarget& acc = p.plan.targets[static_cast<size_t>(p.plan.find("acc"))];
    EXPECT_TRUE(acc.history);
    EXPECT_TRUE(acc.carried);
    EXPECT_EQ(acc.bytes, 2u * 8 * 8 * 8);
    EXPECT_EQ(sharing(p.plan, "acc"), (Names{"acc"}));
    EXPECT_TRUE(p.plan.targets[static_cast<size_t>(p.plan.find("blendOnly"))].carried);
    EXPECT_EQ(sharing(p.plan, "blendOnly"), (Names{"blendOnly"}));
    EXPECT_EQ(sharing(p.plan, "m"), (Names{"m", "later"}));  // m ends at adapt, later starts after
}

TEST(TargetPlan, TargetsOfCulledPassesGetNoMemory) {
    Planned p = planWorkspace(workspace().targets({"used", "unused"}).pass("a", "used").pass("b", "unused").pass("final", "", {"used"}).build());
    const PlannedTarget& unused = p.plan.targets[static_cast<size_t>(p.plan.find("unused"))];
    EXPECT_FALSE(unused.used);
    EXPECT_EQ(unused.resource, -1);
    for (const TargetResource& r : p.plan.resources)
        for (int k : r.targets) EXPECT_NE(p.plan.targets[static_cast<size_t>(k)].name, "unused");
}

TEST(TargetPlan, OnePlanForSeveralGraphsCoversEveryLifetime) {
    // With the effect on, t1 lives 0..2 (read by "use"); with it off, "use" reads nothing and
    // the plan of both must still keep t1 and t2 apart.
    std::unique_ptr<Workspace> fx = workspace()
                                        .targets({"t1", "t2"})
                                        .effect({.name = "fx", .passes = {"b"}})
                                        .pass("a", "t1")
                                        .pass("b", "t2")
                                        .pass("use", "", {"t1", "t2"})
                                        .build();
    Workspace& ws = *fx;
    Result<PassGraph> on = buildPassGraph(ws, {{}, {"fx"}, {}, {}});
    Result<PassGraph> off = buildPassGraph(ws, {{}, {"fx"}, {"fx"}, {}});
    ASSERT_TRUE(on.ok()) << formatAll(on.diagnostics());
    ASSERT_TRUE(off.ok()) << formatAll(off.diagnostics());
    auto both = planTargets(ws, {&on.value(), &off.value()}, {8, 8}, {}, true);
    ASSERT_TRUE(both);
    EXPECT_EQ(sharing(*both, "t1"), (Names{"t1"}));
    EXPECT_EQ(sharing(*both, "t2"), (Names{"t2"}));
    auto offOnly = planTargets(ws, {&off.value()}, {8, 8}, {}, true);
    ASSERT_TRUE(offOnly);
    EXPECT_FALSE(offOnly->targets[static_cast<size_t>(offOnly->find("t2"))].used);
}

TEST(TargetPlan, BytesCountMipLevelsBuffersAndDepth) {
    // 5x3: levels 5x3, 2x1, 1x1 = 18 pixels of 8 bytes, two buffers, and a 4-byte depth per base pixel.
    EXPECT_EQ(targetBytes(TargetFormat::RGBA16F, {5, 3}, true, true, true), 18u * 8 * 2 + 15 * 4);
    EXPECT_EQ(targetBytes(TargetFormat::R32F, {5, 3}, false, false, false), 15u * 4);
    EXPECT_EQ(targetBytes(TargetFormat::RGBA8, {1, 1}, true, false, false), 4u);
    EXPECT_EQ(targetBytes(TargetFormat::RGBA32F, {4096, 4096}, false, false, true), 4096ull * 4096 * 16 * 2);
}

}  // namespace
}  // namespace rmfx
