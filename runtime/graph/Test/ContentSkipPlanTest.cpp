// Content skip's plan without GL: which effects it may skip and by which probe, what they hand on,
// the feeders skipped with them and the consumers drawn without them (gl/Test/ContentSkipGLTest
// checks what the GPU then draws).

#include "graph/ContentSkipPlan.h"

#include <gtest/gtest.h>

#include "frontend/workspace/WorkspaceParser.h"
#include "graph/FramePlan.h"
#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

using test::passXml;
using Names = std::vector<std::string>;
using EffectsByPass = std::map<std::string, std::set<std::string>>;

std::unique_ptr<Workspace> parse(const std::string& body) {
    std::string xml = "<workspace version=\"1\" name=\"skip\" size=\"8x8\">\n" + body + "</workspace>\n";
    Result<Workspace> parsed = parseWorkspaceText(xml, "skip.xml", ".");
    EXPECT_TRUE(parsed.ok()) << formatAll(parsed.diagnostics());
    if (!parsed) return nullptr;
    return std::make_unique<Workspace>(std::move(*parsed));
}

// scene → bright → [spread] → glow (effect, source bright) → final (reads scene and glow).
std::string glowWorkspace(bool spread, const std::string& effectAttributes = "source=\"bright\"") {
    std::string xml;
    for (const char* t : {"scene", "bright", "spread", "glow"}) xml += std::string("  <target name=\"") + t + "\" format=\"rgba16f\"/>\n";
    xml += "  <effect name=\"glow\" passes=\"glow_pass\" " + effectAttributes + "/>\n";
    xml += passXml("scene_pass", "scene", {}) + passXml("bright_pass", "bright", {"scene"});
    if (spread) xml += passXml("spread_pass", "spread", {"bright"});
    xml += passXml("glow_pass", "glow", {spread ? "spread" : "bright"}) + passXml("final", "", {"scene", "glow"});
    return xml;
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
    Planned p = planFor(parse(glowWorkspace(false)), {"output"});
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
    Planned p = planFor(parse(glowWorkspace(true)), {"output"});
    EXPECT_EQ(p.feeders(), (EffectsByPass{{"spread_pass", {"glow"}}}));
    EXPECT_EQ(p.plan.probeAt(2), 0) << "the feeder is drawn under the effect's condition";

    Planned readBack = planFor(parse(glowWorkspace(true)), {"output", "spread"});
    EXPECT_TRUE(readBack.feeders().empty());
    Planned everyTarget = planFor(parse(glowWorkspace(true)), {});
    EXPECT_TRUE(everyTarget.feeders().empty()) << "every target is read back after the frame";
    ASSERT_EQ(everyTarget.plan.effects.size(), 1u);
    EXPECT_TRUE(everyTarget.plan.effects[0].handedOn[0].readBack);
}

TEST(ContentSkipPlan, AnEffectWhoseTargetIsReadBackRunsWhateverItsSourceHolds) {
    Planned p = planFor(parse(glowWorkspace(false)), {"output", "glow"});
    EXPECT_TRUE(p.plan.empty());
    EXPECT_TRUE(p.plan.consumers.empty());
    EXPECT_EQ(p.plan.runningAlways,
              (std::map<std::string, std::string>{
                  {"glow", "its target 'glow' is read back after the frame, and holds what its passes write"}}));
}

TEST(ContentSkipPlan, AGateWrittenBeforeTheEffectIsCountedInPlaceOfTheSource) {
    std::string xml = glowWorkspace(true, "source=\"bright\" gate=\"gate\" gate-channels=\"r\"");
    xml.insert(0, "  <target name=\"gate\" format=\"rgba16f\" size=\"1x1\"/>\n");
    const std::string brightPass = passXml("bright_pass", "bright", {"scene"});
    xml.insert(xml.find(brightPass), passXml("gate_pass", "gate", {"scene"}));
    Planned p = planFor(parse(xml), {"output"});
    ASSERT_EQ(p.plan.effects.size(), 1u);
    EXPECT_TRUE(p.plan.effects[0].gated);
    ASSERT_EQ(p.plan.probes.size(), 1u);
    EXPECT_EQ(p.plan.probes[0].source, "gate");
    EXPECT_EQ(p.plan.probes[0].channels, glm::bvec4(true, false, false, false));
    EXPECT_EQ(p.feeders(), (EffectsByPass{{"bright_pass", {"glow"}}, {"spread_pass", {"glow"}}}))
        << "with the gate counted, the source's own pass is skipped with the effect";
}

TEST(ContentSkipPlan, AnEffectWithoutASourceOrOutsideTheScheduleIsNotPlanned) {
    Planned none = planFor(parse(glowWorkspace(false, "")), {"output"});
    EXPECT_TRUE(none.plan.empty());
    EXPECT_FALSE(hasSourcedEffects(*none.ws));

    std::unique_ptr<Workspace> ws = parse(glowWorkspace(false));
    ASSERT_TRUE(ws);
    EXPECT_TRUE(hasSourcedEffects(*ws));
    ContentSkipPlan withoutGlow = planContentSkip(*ws, {0, 1, 3}, {"output"});
    EXPECT_TRUE(withoutGlow.empty());
    EXPECT_TRUE(withoutGlow.consumers.empty());
}

// hdr_lighting.xml: bloom and star share one probe (the glare gate's red), the bright pass and the
// star source are fed only to them, and the final pass reads what both hand on.
TEST(ContentSkipPlan, HdrLightingsGlareIsSkippedByItsGateWithTheBrightPassAndStarSource) {
    Result<Workspace> parsed = parseWorkspaceFile(test::sourceDir() / "effects" / "hdr_lighting.xml");
    ASSERT_TRUE(parsed) << formatAll(parsed.diagnostics());
    const Workspace& ws = *parsed;
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
