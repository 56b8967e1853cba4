#pragma once
// What the HLSL GL tests share: a workspace whose passes named hlsl* are HLSL (vs_2_0 / ps_2_0,
// entry "main"), validated as an imported Direct3D effect would be, rendered once and read back.

#include <filesystem>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <glm/mat4x4.hpp>

#include "frontend/workspace/WorkspaceParser.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"
#include "validation/Validation.h"

namespace rmfx::test::hlsl_gl {

// Parses `xml`, marks the shaders of passes named hlsl* as HLSL (vs_2_0 / ps_2_0, entry "main")
// and validates it, as an imported Direct3D effect would be.
inline std::unique_ptr<Workspace> hlslWorkspace(const std::string& xml, const std::filesystem::path& folder = ".") {
    Result<Workspace> parsed = parseWorkspaceText(xml, folder / "hlsl-test.xml", folder);
    if (!parsed.ok()) {
        ADD_FAILURE() << formatAll(parsed.diagnostics());
        return nullptr;
    }
    for (Pass& pass : parsed->passes) {
        if (pass.name.rfind("hlsl", 0) != 0) continue;
        for (ShaderSource& s : pass.shaders) {
            s.dialect = ShaderDialect::Hlsl;
            s.entryPoint = "main";
            s.profile = s.stage == ShaderStage::Vertex ? "vs_2_0" : "ps_2_0";
        }
    }
    Diagnostics d = validateWorkspace(*parsed).diagnostics();
    if (hasErrors(d)) {
        ADD_FAILURE() << formatAll(d);
        return nullptr;
    }
    return std::make_unique<Workspace>(std::move(*parsed));
}

// Passes the mesh's position and first texture coordinates on, with a chosen clip-space z and w.
inline const char* passThroughVertexShader = R"(
float depth;
float w;
struct VS_OUTPUT { float4 Pos : POSITION; float2 Tex : TEXCOORD0; };
VS_OUTPUT main(float4 Pos : POSITION, float2 Tex : TEXCOORD0) {
    VS_OUTPUT o;
    o.Pos = float4(Pos.xy * w, depth * w, w);
    o.Tex = Tex;
    return o;
}
)";

inline std::string vertexShaderXml(const std::string& code) {
    return R"(<shader stage="vertex"><![CDATA[)" + code + "]]></shader>\n";
}

inline glm::dvec4 pixel(const RefImage& image, int x, int y) { return image.at(x, y); }

// Renders one frame of hlslWorkspace(xml) and reads target "out" back; an empty image (and a test
// failure) when it does not run.
inline RefImage renderOut(const std::string& xml, const std::filesystem::path& folder = ".") {
    GlRun run = runWorkspace(hlslWorkspace(xml, folder), RunSettings());
    if (!run.exec) return {};
    return readRef(run, "out");
}

inline void expectNear(glm::dvec4 got, glm::dvec4 want, double tolerance, const std::string& what) {
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], tolerance) << what << " channel " << c;
}

}  // namespace rmfx::test::hlsl_gl
