#include "tests/support/GlTestSupport.h"

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <thread>

#include "frontend/workspace/WorkspaceParser.h"
#include "gl/GlContext.h"
#include "io/image/ImageIO.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::test {
namespace {

struct SharedContext {
    std::unique_ptr<GlContext> context;
    std::string error;
};

SharedContext createContext(GlProfile profile) {
    SharedContext s;
    auto created = GlContext::createHeadless(profile);
    if (created) s.context = std::move(*created);
    else s.error = created.error();
    return s;
}

const SharedContext& sharedContext() {
    static SharedContext shared = createContext(GlProfile::Core);
    return shared;
}

const SharedContext& compatibilityContext() {
    static SharedContext shared = createContext(GlProfile::Compatibility);
    return shared;
}

}  // namespace

void GlTest::SetUp() {
    const SharedContext& shared = sharedContext();
    ASSERT_TRUE(shared.context) << "no headless GL context: " << shared.error;
    shared.context->makeCurrent();
}

void CompatibilityGlTest::SetUp() {
    GlTest::SetUp();  // the core context exists first, so TearDown can return to it
    const SharedContext& compatibility = compatibilityContext();
    ASSERT_TRUE(compatibility.context) << "no compatibility-profile GL context: " << compatibility.error;
    compatibility.context->makeCurrent();
}

void CompatibilityGlTest::TearDown() {
    if (sharedContext().context) sharedContext().context->makeCurrent();
}

std::unique_ptr<Workspace> workspaceFromText(const std::string& xml, const std::filesystem::path& folder) {
    Result<Workspace> parsed = parseWorkspaceText(xml, folder / "test-workspace.xml", folder);
    Diagnostics diagnostics = parsed.diagnostics();
    if (parsed) {
        Diagnostics found = resolveWorkspaceMedia(*parsed, {}).diagnostics();
        if (!hasErrors(found)) found = validateWorkspace(*parsed).diagnostics();
        diagnostics.insert(diagnostics.end(), found.begin(), found.end());
    }
    if (!parsed || hasErrors(diagnostics)) {
        ADD_FAILURE() << "workspace does not load:\n" << formatAll(diagnostics) << "\n" << xml;
        return nullptr;
    }
    return std::make_unique<Workspace>(std::move(*parsed));
}

std::unique_ptr<Workspace> effectWorkspace(const std::string& file, const Overrides& overrides) {
    Result<Workspace> loaded = loadWorkspace(sourceDir() / "effects" / file);
    if (!loaded) {
        ADD_FAILURE() << file << " does not load:\n" << formatAll(loaded.diagnostics());
        return nullptr;
    }
    auto ws = std::make_unique<Workspace>(std::move(*loaded));
    if (Result<void> set = applyOverrides(*ws, overrides); !set) {
        ADD_FAILURE() << formatAll(set.diagnostics());
        return nullptr;
    }
    return ws;
}

std::unique_ptr<Workspace> stageWorkspace(const std::string& file, const std::filesystem::path& input,
                                          const Overrides& overrides) {
    const std::filesystem::path folder = sourceDir() / "effects" / "variants";
    std::string xml = readText(folder / file);
    const std::string media = "file=\"../../samples/media/hdr_scene.exr\"";
    size_t at = xml.find(media);
    if (at == std::string::npos) {
        ADD_FAILURE() << file << " has no " << media;
        return nullptr;
    }
    xml.replace(at, media.size(), "file=\"" + input.string() + "\"");
    auto ws = workspaceFromText(xml, folder);
    if (!ws) return nullptr;
    if (Result<void> set = applyOverrides(*ws, overrides); !set) {
        ADD_FAILURE() << formatAll(set.diagnostics());
        return nullptr;
    }
    return ws;
}

void writeFloatExr(const std::filesystem::path& file, const RefImage& image) {
    Image out;
    out.width = image.width;
    out.height = image.height;
    out.channels = 4;
    out.highDynamicRange = true;
    out.pixels.resize(size_t(image.width) * image.height * 4);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 4; ++c) out.at(x, image.height - 1 - y, c) = static_cast<float>(image.at(x, y)[c]);
    auto written = writeImage(file, out);
    if (!written) ADD_FAILURE() << written.error();
}

void replaceSceneWithLight(Workspace& ws, const std::string& scenePass, glm::ivec2 from, glm::ivec2 to) {
    auto found = std::find_if(ws.passes.begin(), ws.passes.end(), [&](const Pass& p) { return p.name == scenePass; });
    if (found == ws.passes.end()) {
        ADD_FAILURE() << "no pass '" << scenePass << "'";
        return;
    }
    for (Pass& pass : ws.passes)
        if (&pass != &*found && pass.target == found->target) pass.enabled = false;
    found->samplers.clear();
    found->constants.clear();
    ShaderSource fragment;
    fragment.code = "out vec4 fragColor;\n"
                    "void main() {\n"
                    "    ivec2 p = ivec2(gl_FragCoord.xy);\n"
                    "    bool lit = all(greaterThanEqual(p, ivec2(" + std::to_string(from.x) + ", " + std::to_string(from.y) +
                    "))) && all(lessThan(p, ivec2(" + std::to_string(to.x) + ", " + std::to_string(to.y) + ")));\n"
                    "    fragColor = lit ? vec4(1.0) : vec4(0.0);\n"
                    "}\n";
    fragment.codeLine = found->where.line;
    fragment.where = found->where;
    found->shaders = {fragment};
}

void replaceSceneWithPattern(Workspace& ws, const std::string& target, const std::string& pattern) {
    for (Pass& pass : ws.passes)
        if (pass.target == target) pass.enabled = false;
    Pass replacement;
    replacement.name = "test_pattern";
    replacement.target = target;
    ShaderSource fragment;
    fragment.stage = ShaderStage::Fragment;
    fragment.code = "#version 450 core\nout vec4 fragColor;\n" + pattern;
    replacement.shaders.push_back(fragment);
    replacement.draw.mesh = BuiltinMesh::FullscreenTriangle;
    ws.passes.insert(ws.passes.begin(), replacement);
}

std::string singlePixelPattern(glm::ivec2 pixel, double value) {
    return "void main() { fragColor = vec4(ivec2(gl_FragCoord.xy) == ivec2(" + std::to_string(pixel.x) + ", " +
           std::to_string(pixel.y) + ") ? vec3(" + glslFloat(value) + ") : vec3(0.0), 1.0); }\n";
}

std::string EdgePixelCase::name() const {
    return std::to_string(size.x) + "x" + std::to_string(size.y) + ", pixel " + std::to_string(pixel.x) + "," +
           std::to_string(pixel.y);
}

std::vector<EdgePixelCase> edgePixelCases(glm::ivec2 largePixel) {
    return {{{1, 1}, {0, 0}}, {{3, 5}, {2, 2}}, {{3, 5}, {1, 4}}, {{3, 5}, {2, 4}}, {{1921, 1081}, largePixel}};
}

GlRun runWorkspace(std::unique_ptr<Workspace> ws, const RunSettings& settings, const ExecutorOptions& options) {
    GlRun run;
    run.ws = std::move(ws);
    if (!run.ws) return run;
    auto ran = runHeadless(*run.ws, settings, options);
    run.diagnostics = ran.diagnostics();
    if (ran) run.exec = std::move(*ran);
    if (!run.exec || hasErrors(run.diagnostics))
        ADD_FAILURE() << "runHeadless failed:\n" << formatAll(run.diagnostics);
    return run;
}

GlRun runWorkspace(const std::string& xml, const RunSettings& settings) {
    return runWorkspace(workspaceFromText(xml), settings);
}

Image readBack(const GlExecutor& exec, const std::string& target) {
    auto image = exec.readTarget(target);
    if (!image) {
        ADD_FAILURE() << "readTarget(" << target << "): " << image.error();
        return {};
    }
    return *image;
}

RefImage readRef(const GlRun& run, const std::string& target) { return fromImage(readBack(*run.exec, target)); }

double bilinearWeightError() {
    static const double error = [] {
        const std::string xml = R"(<workspace version="1" name="subtexel" size="1000x1">
  <target name="edge" format="r32f" size="2x1"/>
  <target name="ramp" format="r32f" size="1000x1"/>
  <pass name="edge" target="edge"><shader stage="fragment"><![CDATA[
#version 450 core
out vec4 c;
void main() { c = vec4(gl_FragCoord.x > 1.0 ? 1.0 : 0.0); }
]]></shader></pass>
  <pass name="ramp" target="ramp"><sampler name="E" target="edge" filter="linear" wrap="clamp"/><shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D E;
out vec4 c;
void main() { c = texture(E, vec2((0.5 + floor(gl_FragCoord.x) / 1000.0) / 2.0, 0.5)); }
]]></shader></pass>
  <pass name="final"><sampler name="R" target="ramp" filter="nearest"/><shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D R;
out vec4 c;
void main() { c = texelFetch(R, ivec2(gl_FragCoord.xy), 0); }
]]></shader></pass>
</workspace>
)";
        GlRun run = runWorkspace(xml, RunSettings({1000, 1}));
        if (!run.exec) return 1.0;
        const Image ramp = readBack(*run.exec, "ramp");
        double worst = 0.0;
        // Texel coordinate 0.5 + x / 1000: x / 1000 of the way (not a binary fraction, which a
        // filter with 10 bits of subtexel precision would hit exactly) from the centre of texel 0 to texel 1's.
        for (int x = 0; x < ramp.width; ++x) worst = std::max(worst, std::abs(static_cast<double>(ramp.at(x, 0, 0)) - x / 1000.0));
        // The probe itself: a ramp from 0 through one half, not a constant or a step.
        if (ramp.width != 1000 || std::abs(ramp.at(500, 0, 0) - 0.5f) > 0.01f || std::abs(ramp.at(250, 0, 0) - 0.25f) > 0.01f)
            ADD_FAILURE() << "bilinearWeightError: the probe did not draw a ramp";
        return worst;
    }();
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", error);
    ::testing::Test::RecordProperty("bilinear weight error", text);
    return error;
}

double filteringAllowance(int passes) { return 2.0 * passes * bilinearWeightError(); }

void expectWithin(const std::string& what, double error, double tolerance) {
    char text[64];
    std::snprintf(text, sizeof text, "%.3g of %.3g", error, tolerance);  // to_string would print 1e-7 as 0.000000
    ::testing::Test::RecordProperty(what, text);
    EXPECT_LE(error, tolerance) << what;
}

std::string glslFloat(double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(static_cast<float>(value)));
    std::string s = buffer;
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return s;
}

bool waitForReload(LiveWorkspace& live) {
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (std::chrono::steady_clock::now() < deadline) {
        if (live.poll()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ADD_FAILURE() << "no reload within 5 s";
    return false;
}

Image blankHdrImage(int width, int height) {
    Image image;
    image.width = width;
    image.height = height;
    image.channels = 4;
    image.highDynamicRange = true;
    image.pixels.assign(static_cast<size_t>(width) * height * 4, 0.0f);
    return image;
}

}  // namespace rmfx::test
