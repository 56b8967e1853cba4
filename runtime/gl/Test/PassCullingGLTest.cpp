// The pass graph on the GPU (shader_5 and HDRLighting): passes culled for the output or for
// effects left out never draw (counted by a GL primitives query around the frame, not by the
// executor's bookkeeping) and their targets hold no memory; switching an effect off and on at run
// time gives the same bits as the workspace without and with it, with no recompile and no
// reallocation; sharing memory between targets changes no pixel.

#include <epoxy/gl.h>

#include <algorithm>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "io/mesh/BuiltinMeshes.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

class PassCullingGLTest : public GlTest {};

constexpr int kSize = 64;
using Names = std::vector<std::string>;

ExecutorOptions outputOnly(std::optional<Names> effects = std::nullopt) {
    ExecutorOptions o;
    o.outputs = {"output"};
    o.effects = std::move(effects);
    return o;
}

GlRun shader5(const ExecutorOptions& options, const Overrides& overrides = {}) {
    return runWorkspace(effectWorkspace("shader_5.xml", overrides), {{kSize, kSize}, 1, 1.0f / 60.0f}, options);
}

// Primitives the GL rasterised during one frame.
long long primitivesOfFrame(GlExecutor& exec) {
    GLuint query = 0;
    glCreateQueries(GL_PRIMITIVES_GENERATED, 1, &query);
    glBeginQuery(GL_PRIMITIVES_GENERATED, query);
    Diagnostics d = exec.renderFrame({0.0f, 1.0f / 60.0f}).takeDiagnostics();
    glEndQuery(GL_PRIMITIVES_GENERATED);
    GLuint64 count = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &count);
    glDeleteQueries(1, &query);
    EXPECT_TRUE(d.empty()) << formatAll(d);
    return static_cast<long long>(count);
}

// What the passes draw: the teapot pass its mesh, every other pass one full-screen triangle.
long long primitivesOf(const Names& passes) {
    long long teapot = static_cast<long long>(makeMesh(BuiltinMesh::Teapot).triangleCount());
    long long n = 0;
    for (const std::string& p : passes) n += p == "teapot" ? teapot : 1;
    return n;
}

Names withPrefix(const GlRun& run, const std::string& prefix) {
    Names names;
    for (const Pass& p : run.ws->passes)
        if (p.name.rfind(prefix, 0) == 0) names.push_back(p.name);
    return names;
}

// shader_5 with the glare alone: the scene, the six glare levels, the screen and the composite.
Names glarePasses(const GlRun& run) {
    Names names{"environment", "teapot"};
    for (const std::string& p : withPrefix(run, "glare_")) names.push_back(p);
    names.insert(names.end(), {"screen", "combine"});
    return names;
}

// Pixels that differ in any bit, and the largest difference.
void expectSameBits(const Image& a, const Image& b, const std::string& what) {
    ASSERT_EQ(a.pixels.size(), b.pixels.size()) << what;
    ASSERT_FALSE(a.pixels.empty()) << what;
    size_t differ = 0;
    float worst = 0.0f;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        if (a.pixels[i] != b.pixels[i]) {
            ++differ;
            worst = std::max(worst, std::abs(a.pixels[i] - b.pixels[i]));
        }
    EXPECT_EQ(differ, 0u) << what << ": largest difference " << worst;
}

TEST_F(PassCullingGLTest, EffectsLeftOutNeverDrawAndHoldNoMemory) {
    GlRun run = shader5(outputOnly(Names{"glare"}));
    ASSERT_TRUE(run.exec);
    Names expected = glarePasses(run);
    EXPECT_EQ(run.exec->passesRun(), expected);
    EXPECT_EQ(primitivesOfFrame(*run.exec), primitivesOf(expected));

    for (const std::string& t : run.exec->targetNames()) {
        if (t.rfind("streak_", 0) != 0 && t.rfind("ghost_", 0) != 0) continue;
        EXPECT_EQ(run.exec->targetTexture(t), 0u) << t;
        auto read = run.exec->readTarget(t);
        ASSERT_FALSE(read) << t;
        EXPECT_NE(read.error().find("is not computed"), std::string::npos) << read.error();
    }
    // By hand at 64x64: scene rgba16f with a 32-bit depth buffer 64·64·(8+4) = 49152 bytes; the six
    // 16x16 glare levels ping-pong between 3 textures of 16·16·8 = 2048 (glare_4, _5 and _6 live
    // until the composite); the output, rgba32f, 64·64·16 = 65536. Declared: scene, 16 quarter-size targets
    // and the output.
    EXPECT_EQ(targetTextureCount(run.exec->targetPlan()), 5);
    EXPECT_EQ(run.exec->targetPlan().allocatedBytes, 49152u + 3 * 2048 + 65536);
    EXPECT_EQ(run.exec->targetPlan().declaredBytes, 49152u + 16 * 2048 + 65536);
}

TEST_F(PassCullingGLTest, AskingForOneTargetRunsOnlyItsChain) {
    ExecutorOptions options;
    options.outputs = {"glare_2"};
    GlRun run = shader5(options);
    ASSERT_TRUE(run.exec);
    Names expected{"environment", "teapot", "glare_1", "glare_2"};
    EXPECT_EQ(run.exec->passesRun(), expected);
    EXPECT_EQ(primitivesOfFrame(*run.exec), primitivesOf(expected));
    // The same target from the full workspace.
    GlRun full = shader5({});
    ASSERT_TRUE(full.exec);
    expectSameBits(readBack(*run.exec, "glare_2"), readBack(*full.exec, "glare_2"),
                   "glare_2 alone vs in the full frame");
}

struct Switch {
    std::string effect;
    Names variables;
};

TEST_F(PassCullingGLTest, SwitchingAnEffectOffAndOnMatchesTheWorkspaceWithoutAndWithIt) {
    const std::vector<Switch> switches{{"glare", {"Glow_Factor", "Glow_Factor2", "Glow_Factor3"}},
                                       {"streak", {"Streak_Factor"}},
                                       {"ghost", {"Ghost_Factor"}}};
    GlRun live = shader5(outputOnly());
    ASSERT_TRUE(live.exec);
    Image allOn = readBack(*live.exec, "output");
    Names allPasses = live.exec->passesRun();
    ASSERT_EQ(allPasses.size(), 20u);

    // GL objects before any toggling: no toggle may create or delete one.
    std::map<std::string, unsigned> programs, textures;
    for (const Pass& p : live.ws->passes) programs[p.name] = live.exec->passProgram(p.name);
    for (const std::string& t : live.exec->targetNames()) textures[t] = live.exec->targetTexture(t);
    int textureCount = targetTextureCount(live.exec->targetPlan());

    for (const Switch& s : switches) {
        std::map<std::string, Value> before;
        for (const std::string& v : s.variables) {
            before[v] = *live.exec->variable(v);
            ASSERT_EQ(live.exec->setVariable(v, Value::ofFloat(0.0f)).error(), "");
        }
        ASSERT_TRUE(live.exec->renderFrame({0.0f, 1.0f / 60.0f}).takeDiagnostics().empty());
        Names off = live.exec->passesRun();
        for (const std::string& p : withPrefix(live, s.effect + "_"))
            EXPECT_EQ(std::count(off.begin(), off.end(), p), 0) << p << " ran with " << s.effect << " off";
        EXPECT_EQ(live.exec->switchedOffEffects(), (std::set<std::string>{s.effect}));

        // The workspace without the effect: asked for without it, at its own factor values.
        Names others;
        for (const Switch& o : switches)
            if (o.effect != s.effect) others.push_back(o.effect);
        GlRun without = shader5(outputOnly(others));
        ASSERT_TRUE(without.exec);
        EXPECT_EQ(off, without.exec->passesRun()) << s.effect;
        expectSameBits(readBack(*live.exec, "output"), readBack(*without.exec, "output"), s.effect + " switched off");

        for (const auto& [v, value] : before) ASSERT_EQ(live.exec->setVariable(v, value).error(), "");
        ASSERT_TRUE(live.exec->renderFrame({0.0f, 1.0f / 60.0f}).takeDiagnostics().empty());
        EXPECT_EQ(live.exec->passesRun(), allPasses);
        expectSameBits(readBack(*live.exec, "output"), allOn, s.effect + " switched back on");
    }
    for (const Pass& p : live.ws->passes)
        EXPECT_EQ(live.exec->passProgram(p.name), programs[p.name]) << p.name << " recompiled";
    for (const std::string& t : live.exec->targetNames())
        EXPECT_EQ(live.exec->targetTexture(t), textures[t]) << t << " reallocated";
    EXPECT_EQ(targetTextureCount(live.exec->targetPlan()), textureCount);
}

TEST_F(PassCullingGLTest, AnEffectSwitchedOffDrawsNothingOfIt) {
    GlRun run = shader5(outputOnly(), {{"Streak_Factor", "0"}, {"Ghost_Factor", "0"}});
    ASSERT_TRUE(run.exec);
    Names expected = glarePasses(run);
    EXPECT_EQ(run.exec->passesRun(), expected);
    EXPECT_EQ(primitivesOfFrame(*run.exec), primitivesOf(expected));
}

TEST_F(PassCullingGLTest, SharingMemoryChangesNoPixel) {
    // shader_5: pooled, unpooled and every target kept.
    GlRun pooled = shader5(outputOnly());
    ExecutorOptions own = outputOnly();
    own.poolTargets = false;
    GlRun unpooled = shader5(own);
    GlRun kept = shader5({});
    ASSERT_TRUE(pooled.exec && unpooled.exec && kept.exec);
    EXPECT_LT(targetTextureCount(pooled.exec->targetPlan()), targetTextureCount(unpooled.exec->targetPlan()));
    expectSameBits(readBack(*pooled.exec, "output"), readBack(*unpooled.exec, "output"), "shader_5 pooled vs not");
    expectSameBits(readBack(*pooled.exec, "output"), readBack(*kept.exec, "output"),
                   "shader_5 pooled vs every target kept");

    // HDRLighting: 45 passes, carried adaptation and luminance targets, several frames.
    RunSettings frames{{kSize, kSize}, 4, 0.1f};
    ExecutorOptions hdrPooled;
    hdrPooled.outputs = {"output"};
    ExecutorOptions hdrOwn = hdrPooled;
    hdrOwn.poolTargets = false;
    GlRun a = runWorkspace(effectWorkspace("hdr_lighting.xml"), frames, hdrPooled);
    GlRun b = runWorkspace(effectWorkspace("hdr_lighting.xml"), frames, hdrOwn);
    ASSERT_TRUE(a.exec && b.exec);
    const TargetPlan& plan = a.exec->targetPlan();
    EXPECT_LT(plan.allocatedBytes, b.exec->targetPlan().allocatedBytes) << "the test must share something";
    expectSameBits(readBack(*a.exec, "output"), readBack(*b.exec, "output"), "hdr_lighting pooled vs not");
}

// HDRLighting: with bloom and star both off nothing reads the bright pass or the star source
// either, so they are culled with them; the frame is that of the workspace asked for no effect.
TEST_F(PassCullingGLTest, HdrLightingWithoutBloomAndStarSkipsTheirSharedSourcesToo) {
    RunSettings frames{{kSize, kSize}, 3, 0.1f};
    GlRun live = runWorkspace(effectWorkspace("hdr_lighting.xml"), frames, outputOnly());
    GlRun none = runWorkspace(effectWorkspace("hdr_lighting.xml"), frames, outputOnly(Names{}));
    ASSERT_TRUE(live.exec && none.exec);
    Names noEffects = none.exec->passesRun();
    for (const char* culled : {"bright_pass", "star_source", "bloom_source", "star0_0", "star_merge"})
        EXPECT_EQ(std::count(noEffects.begin(), noEffects.end(), culled), 0) << culled;
    for (const char* kept : {"teapot", "luminance1", "adaptation", "final"})
        EXPECT_EQ(std::count(noEffects.begin(), noEffects.end(), kept), 1) << kept;

    ASSERT_EQ(live.exec->setVariable("Bloom_Scale", Value::ofFloat(0.0f)).error(), "");
    ASSERT_EQ(live.exec->setVariable("Star_Scale", Value::ofFloat(0.0f)).error(), "");
    // The frames before the switch left the same adaptation state in both: 3 frames each.
    for (int i = 3; i < 5; ++i) {
        ASSERT_TRUE(live.exec->renderFrame({0.1f * i, 0.1f}).takeDiagnostics().empty());
        ASSERT_TRUE(none.exec->renderFrame({0.1f * i, 0.1f}).takeDiagnostics().empty());
    }
    EXPECT_EQ(live.exec->passesRun(), noEffects);
    expectSameBits(readBack(*live.exec, "output"), readBack(*none.exec, "output"), "bloom and star switched off");
    EXPECT_EQ(primitivesOfFrame(*live.exec), primitivesOfFrame(*none.exec));
}

TEST_F(PassCullingGLTest, ReadingATargetWhoseMemoryWasReusedSaysSo) {
    GlRun run = shader5(outputOnly(Names{"glare"}));
    ASSERT_TRUE(run.exec);
    auto shared = run.exec->readTarget("glare_1");
    ASSERT_FALSE(shared);
    EXPECT_NE(shared.error().find("shares memory with 'glare_5'"), std::string::npos) << shared.error();
    EXPECT_TRUE(run.exec->readTarget("glare_5")) << "the last user of the memory keeps its contents";
}

const char* kGuardedWorkspace = R"(<workspace version="1" name="guard" size="4x4">
  <target name="extra" format="rgba32f"/>
  <effect name="fx" passes="extra"/>
  <pass name="extra" target="extra">
    <shader stage="fragment">out vec4 c; void main() { c = vec4(0.25); }</shader>
  </pass>
  <pass name="final">
    <sampler name="extra" target="extra" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
uniform sampler2D extra;
out vec4 c;
void main() {
    c = vec4(1.0);
    GUARD c += texelFetch(extra, ivec2(0), 0);
}
]]></shader>
  </pass>
  <output format="rgba32f"/>
</workspace>)";

std::string guarded(const std::string& guard) {
    std::string xml = kGuardedWorkspace;
    xml.replace(xml.find("GUARD"), 5, guard);
    return xml;
}

TEST_F(PassCullingGLTest, AnUnguardedReadOfALeftOutEffectIsAnErrorAndAGuardedOneCompilesAway) {
    ExecutorOptions none = outputOnly(Names{});
    auto ws = workspaceFromText(guarded(""));
    ASSERT_TRUE(ws);
    auto exec = GlExecutor::create(std::move(ws), {4, 4}, none);
    EXPECT_FALSE(exec);
    const Diagnostics& d = exec.diagnostics();
    ASSERT_FALSE(d.empty());
    EXPECT_NE(d.front().message.find("guard the read with `if (RMFX_EFFECT_fx)`"), std::string::npos) << formatAll(d);

    GlRun left = runWorkspace(workspaceFromText(guarded("if (RMFX_EFFECT_fx)")), {{4, 4}, 1, 0.1f}, none);
    GlRun in = runWorkspace(workspaceFromText(guarded("if (RMFX_EFFECT_fx)")), {{4, 4}, 1, 0.1f}, outputOnly());
    ASSERT_TRUE(left.exec && in.exec);
    EXPECT_EQ(left.exec->passesRun(), (Names{"final"}));
    EXPECT_EQ(atGl(readBack(*left.exec, "output"), 0, 0, 0), 1.0f);
    EXPECT_EQ(atGl(readBack(*in.exec, "output"), 0, 0, 0), 1.25f);
}

TEST_F(PassCullingGLTest, ExplainPrintsTheScheduleTargetsAndPeakMemory) {
    ScratchDir dir;
    CommandResult r = runRmfx(
        "render " + shellQuoted(sourceDir() / "effects/shader_5.xml") + " --explain --effects glare --size 64x64",
        dir.path());
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("passes: 10 of 21 run"), std::string::npos) << r.out;  // scene_from_input: no --input
    EXPECT_NE(r.out.find("targets: 8 of 18 allocated, in 5 textures"), std::string::npos) << r.out;
    // The same byte counts as EffectsLeftOutNeverDrawAndHoldNoMemory, worked out by hand.
    EXPECT_NE(r.out.find("peak GPU memory of the frame: 118.0 KiB (120832 bytes) of 144.0 KiB (147456 bytes) for all "
                         "declared targets: 82%"),
              std::string::npos)
        << r.out;
    bool streakLine = false, glareLine = false;
    std::istringstream out(r.out);
    for (std::string line; std::getline(out, line);) {
        if (line.find("streak_ur_16") != std::string::npos && line.find("culled: effect left out") != std::string::npos)
            streakLine = true;
        if (line.find("glare_1") != std::string::npos && line.find("16x16") != std::string::npos &&
            line.find("2.0 KiB") != std::string::npos && line.find("shared with glare_3, glare_5") != std::string::npos)
            glareLine = true;
    }
    EXPECT_TRUE(streakLine) << r.out;
    EXPECT_TRUE(glareLine) << r.out;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "shader_5.png")) << "--explain without -o writes no image";
}

}  // namespace
}  // namespace rmfx::test
