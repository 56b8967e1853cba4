// Content skip's plan without GL: which effects it may skip and by which probe, what they hand on,
// the feeders skipped with them and the consumers drawn without them (gl/Test/ContentSkipGLTest
// checks what the GPU then draws).

#include "graph/ContentSkipPlan.h"

#include <gtest/gtest.h>

#include "graph/FramePlan.h"
#include "graph/Test/HdrLightingWorkspace.h"
#include "graph/Test/WorkspaceBuilder.h"

namespace rmfx {
namespace {

using test::WorkspaceBuilder;
using Names = std::vector<std::string>;
using EffectsByPass = std::map<std::string, std::set<std::string>>;

struct Glow {
    bool spread = false;            // a pass between the bright pass and the effect
    std::string source = "bright";  // the effect's source; empty: none
    bool gated = false;             // a 1x1 gate written from the scene before the bright pass, counted in red
};

// scene → bright → [spread] → glow (effect, source bright) → final (reads scene and glow).
std::unique_ptr<Workspace> glowWorkspace(const Glow& glow) {
    WorkspaceBuilder b("skip.xml");
    if (glow.gated) b.target("gate", TargetFormat::RGBA16F, test::fixedSize(1, 1));
    b.targets({"scene", "bright", "spread", "glow"});
    test::EffectDeclaration effect{.name = "glow", .passes = {"glow_pass"}, .source = glow.source};
    if (glow.gated) {
        effect.gate = "gate";
        effect.gateChannels = {true, false, false, false};
    }
    b.effect(effect).pass("scene_pass", "scene");
    if (glow.gated) b.pass("gate_pass", "gate", {"scene"});
    b.pass("bright_pass", "bright", {"scene"});
    if (glow.spread) b.pass("spread_pass", "spread", {"bright"});
    return b.pass("glow_pass", "glow", {glow.spread ? "spread" : "bright"}).pass("final", "", {"scene", "glow"}).build();
}

struct Planned {
    std::unique_ptr<Workspace> ws;
    ContentSkipPlan plan;
    std::vector<int> schedule;

    std::string passAt(size_t position) const { return ws->passes[static_cast<size_t>(schedule[position])].name; }
    EffectsByPass feeders() const {
        EffectsByPass out;
        for (const ContentSkipPlan::Feeder& f : plan.feeders) out[passAt(f.position)] = f.effects;
        return out;
    }
    EffectsByPass consumers() const {
        EffectsByPass out;
        for (const ContentSkipPlan::Consumer& c : plan.consumers) out[passAt(c.position)] = c.effects;
        return out;
    }
};

// Every enabled pass in order, as a frame that asks for every target would schedule them.
Planned planFor(std::unique_ptr<Workspace> ws, const Names& outputs) {
    Planned p;
    p.ws = std::move(ws);
    for (size_t i = 0; i < p.ws->passes.size(); ++i) p.schedule.push_back(static_cast<int>(i));
    p.plan = planContentSkip(*p.ws, p.schedule, outputs);
    return p;
}

TEST(ContentSkipPlan, AnEffectIsDecidedByItsSourceAndWhatItHandsOnIsKnown) {
    Planned p = planFor(glowWorkspace({}), {"output"});
    ASSERT_EQ(p.plan.probes.size(), 1u);
    EXPECT_EQ(p.plan.probes[0].source, "bright");
    EXPECT_EQ(p.plan.probes[0].channels, glm::bvec4(true, true, true, false));
    ASSERT_EQ(p.plan.effects.size(), 1u);
    const ContentSkipPlan::SkippableEffect& glow = p.plan.effects[0];
    EXPECT_EQ(glow.effect->name, "glow");
    EXPECT_FALSE(glow.gated);
    EXPECT_EQ(p.passAt(glow.first), "glow_pass");
    EXPECT_EQ(glow.last, glow.first);
    ASSERT_EQ(glow.handedOn.size(), 1u);
    EXPECT_EQ(glow.handedOn[0].target, "glow");
    EXPECT_FALSE(glow.handedOn[0].readBack);
    EXPECT_EQ(glow.handedOn[0].readers, (std::vector<size_t>{3}));  // final
    EXPECT_EQ(p.consumers(), (EffectsByPass{{"final", {"glow"}}}));
    EXPECT_TRUE(p.feeders().empty()) << "bright is the source: it is measured, not skipped";
    EXPECT_EQ(p.plan.probeAt(2), 0);
    EXPECT_EQ(p.plan.probeAt(3), -1);
    EXPECT_TRUE(p.plan.endsAnEffect(2));
    EXPECT_FALSE(p.plan.endsAnEffect(3));
    EXPECT_TRUE(p.plan.runningAlways.empty());
}

TEST(ContentSkipPlan, APassOnlyTheEffectReadsIsAFeederUnlessItIsReadBack) {
    Planned p = planFor(glowWorkspace({.spread = true}), {"output"});
    EXPECT_EQ(p.feeders(), (EffectsByPass{{"spread_pass", {"glow"}}}));
    EXPECT_EQ(p.plan.probeAt(2), 0) << "the feeder is drawn under the effect's condition";

    Planned readBack = planFor(glowWorkspace({.spread = true}), {"output", "spread"});
    EXPECT_TRUE(readBack.feeders().empty());
    Planned everyTarget = planFor(glowWorkspace({.spread = true}), {});
    EXPECT_TRUE(everyTarget.feeders().empty()) << "every target is read back after the frame";
    ASSERT_EQ(everyTarget.plan.effects.size(), 1u);
    EXPECT_TRUE(everyTarget.plan.effects[0].handedOn[0].readBack);
}

TEST(ContentSkipPlan, AnEffectWhoseTargetIsReadBackRunsWhateverItsSourceHolds) {
    Planned p = planFor(glowWorkspace({}), {"output", "glow"});
    EXPECT_TRUE(p.plan.empty());
    EXPECT_TRUE(p.plan.consumers.empty());
    EXPECT_EQ(p.plan.runningAlways,
              (std::map<std::string, std::string>{
                  {"glow", "its target 'glow' is read back after the frame, and holds what its passes write"}}));
}

TEST(ContentSkipPlan, AGateWrittenBeforeTheEffectIsCountedInPlaceOfTheSource) {
    Planned p = planFor(glowWorkspace({.spread = true, .gated = true}), {"output"});
    ASSERT_EQ(p.plan.effects.size(), 1u);
    EXPECT_TRUE(p.plan.effects[0].gated);
    ASSERT_EQ(p.plan.probes.size(), 1u);
    EXPECT_EQ(p.plan.probes[0].source, "gate");
    EXPECT_EQ(p.plan.probes[0].channels, glm::bvec4(true, false, false, false));
    EXPECT_EQ(p.feeders(), (EffectsByPass{{"bright_pass", {"glow"}}, {"spread_pass", {"glow"}}}))
        << "with the gate counted, the source's own pass is skipped with the effect";
}

TEST(ContentSkipPlan, AnEffectWithoutASourceOrOutsideTheScheduleIsNotPlanned) {
    Planned none = planFor(glowWorkspace({.source = ""}), {"output"});
    EXPECT_TRUE(none.plan.empty());
    EXPECT_FALSE(hasSourcedEffects(*none.ws));

    std::unique_ptr<Workspace> ws = glowWorkspace({});
    ASSERT_TRUE(ws);
    EXPECT_TRUE(hasSourcedEffects(*ws));
    ContentSkipPlan withoutGlow = planContentSkip(*ws, {0, 1, 3}, {"output"});
    EXPECT_TRUE(withoutGlow.empty());
    EXPECT_TRUE(withoutGlow.consumers.empty());
}

// hdr_lighting.xml: bloom and star share one probe (the glare gate's red), the bright pass and the
// star source are fed only to them, and the final pass reads what both hand on.
TEST(ContentSkipPlan, HdrLightingsGlareIsSkippedByItsGateWithTheBrightPassAndStarSource) {
    std::unique_ptr<Workspace> hdrLighting = test::hdrLightingWorkspace();
    const Workspace& ws = *hdrLighting;
    FramePlanOptions options;
    options.outputs = {"output"};
    Result<FramePlan> frame = planFramePasses(ws, options);
    ASSERT_TRUE(frame) << formatAll(frame.diagnostics());
    FrameVariant allOn = frame->variant({});
    ASSERT_TRUE(allOn.contentSkip);
    Planned p;
    p.ws = std::make_unique<Workspace>(ws);
    p.schedule = allOn.graph->schedule;
    p.plan = planContentSkip(*p.ws, p.schedule, options.outputs);
    ASSERT_EQ(p.plan.probes.size(), 1u);
    EXPECT_EQ(p.plan.probes[0].source, "glare_gate");
    ASSERT_EQ(p.plan.effects.size(), 2u);
    EXPECT_EQ(p.plan.effects[0].effect->name, "bloom");
    EXPECT_EQ(p.plan.effects[1].effect->name, "star");
    EXPECT_EQ(p.feeders(), (EffectsByPass{{"bright_pass", {"bloom", "star"}}, {"star_source", {"bloom", "star"}}}));
    EXPECT_EQ(p.consumers(), (EffectsByPass{{"final", {"bloom", "star"}}}));
    EXPECT_EQ(allOn.contentSkip->feeders.size(), 2u) << "the frame plan holds the same plan for its schedule";

    FrameVariant starOff = frame->variant({"star"});
    ASSERT_TRUE(starOff.contentSkip);
    ASSERT_EQ(starOff.contentSkip->effects.size(), 1u);
    EXPECT_EQ(starOff.contentSkip->effects[0].effect->name, "bloom");

    options.contentSkip = false;
    Result<FramePlan> off = planFramePasses(ws, options);
    ASSERT_TRUE(off);
    EXPECT_TRUE(off->contentSkip.empty());
    EXPECT_EQ(off->variant({}).contentSkip, nullptr);
}

}  // namespace
}  // namespace rmfx
