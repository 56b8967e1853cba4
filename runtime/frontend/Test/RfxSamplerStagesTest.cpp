// Direct3D binds textures to sampler stages and keeps them from one pass to the next: which
// texture each sampler of tests/rfx/d3d_sampler_stages.rfx reads, and what is said when a sampler's
// stage holds nothing (the file's comment works the colours out).

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "frontend/rfx/RfxImporter.h"
#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

std::string stagesFile() {
    std::ifstream in(test::sourceDir() / "tests" / "rfx" / "d3d_sampler_stages.rfx");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

const Sampler* samplerOf(const Workspace& ws, const std::string& pass, const std::string& uniform) {
    for (const Pass& p : ws.passes)
        if (p.name == pass)
            for (const Sampler& s : p.samplers)
                if (s.uniform == uniform) return &s;
    return nullptr;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

}  // namespace

TEST(RfxSamplerStages, ASamplerWithoutItsObjectReadsWhatItsStageHolds) {
    Result<Workspace> ws = importRfxText(stagesFile(), "stages.rfx", ".");
    ASSERT_TRUE(ws.ok()) << formatAll(ws.diagnostics());
    const Sampler* carried = samplerOf(*ws, "Show", "Carried");
    const Sampler* renamed = samplerOf(*ws, "Show", "Renamed");
    ASSERT_TRUE(carried && renamed);
    EXPECT_EQ(carried->target, "A");  // from "Bind"; the disabled "Off" binds nothing
    EXPECT_EQ(renamed->target, "C");  // this pass's object "Other" at stage 1, over "Bind"'s B
    // The object read by stage is not a sampler of its own: no shader names "Other".
    EXPECT_EQ(samplerOf(*ws, "Show", "Other"), nullptr);
    EXPECT_EQ(formatAll(ws.diagnostics()), "");
    // What binds stage 0 with "Off" enabled: D.
    Result<Workspace> on = importRfxText(replaced(stagesFile(), "PASS_INDEX=\"5\" ENABLED=\"FALSE\"", "PASS_INDEX=\"5\" ENABLED=\"TRUE\""),
                                         "stages.rfx", ".");
    ASSERT_TRUE(on.ok()) << formatAll(on.diagnostics());
    EXPECT_EQ(samplerOf(*on, "Show", "Carried")->target, "D");
}

TEST(RfxSamplerStages, AStageNothingBoundIsAnErrorNamingTheSamplerAndStage) {
    // "Bind" binds its first texture at stage 2 instead: nothing is at stage 0 when "Show" runs.
    const std::string text = replaced(stagesFile(), "<RmTextureObject NAME=\"First\" API=\"D3D\" STATE_INDEX=\"0\"",
                                      "<RmTextureObject NAME=\"First\" API=\"D3D\" STATE_INDEX=\"2\"");
    Result<Workspace> ws = importRfxText(text, "stages.rfx", ".");
    EXPECT_FALSE(ws.ok());
    const std::string said = formatAll(ws.diagnostics());
    const size_t line = static_cast<size_t>(std::count(text.begin(), text.begin() + static_cast<long>(text.find("<RmSampler NAME=\"Carried\"")), '\n')) + 1;
    EXPECT_NE(said.find("stages.rfx:" + std::to_string(line) + ": error: <RmSampler NAME=\"Carried\">: sampler 'Carried' has no "
                        "<RmTextureObject NAME=\"Carried\"> in the pass, and no texture object of the pass or of a pass before "
                        "it binds stage 0, the stage it reads (REGISTER)"),
              std::string::npos)
        << said;
    // Without REGISTER the stage is unknown.
    Result<Workspace> unregistered =
        importRfxText(replaced(stagesFile(), "<RmSampler NAME=\"Carried\" API=\"\" REGISTER=\"0\"/>", "<RmSampler NAME=\"Carried\" API=\"\"/>"),
                      "stages.rfx", ".");
    EXPECT_NE(formatAll(unregistered.diagnostics()).find("sampler 'Carried' has no <RmTextureObject NAME=\"Carried\"> in the pass and no "
                                                         "REGISTER: rmfx cannot tell which sampler stage it reads"),
              std::string::npos)
        << formatAll(unregistered.diagnostics());
}

}  // namespace rmfx
