#pragma once
// What the RenderMonkey importer's tests share: the test files (tests/rfx/), importing one, and
// small .rfx texts written in place (an OpenGL or Direct3D effect, a pass with render states).

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "frontend/rfx/RfxImporter.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test::rfx_importer {

inline std::filesystem::path rfxDir() { return test::sourceDir() / "tests" / "rfx"; }

// The 1-based line of the first line of `file` holding `needle`; 0 when none does.
inline int lineOf(const std::filesystem::path& file, const std::string& needle) {
    std::ifstream in(file);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
        if (line.find(needle) != std::string::npos) return n;
    return 0;
}

inline Workspace imported(const std::string& name, const std::string& effect = "") {
    Result<Workspace> p = importRfxFile(rfxDir() / name, {effect});
    EXPECT_FALSE(hasErrors(p.diagnostics())) << formatAll(p.diagnostics());
    EXPECT_TRUE(p.ok());
    return p ? *p : Workspace{};
}

inline std::string allWarnings(const std::string& name, const std::string& effect = "") {
    return formatAll(importRfxFile(rfxDir() / name, {effect}).diagnostics());
}

inline const Variable& variable(const Workspace& ws, const std::string& name) {
    const Variable* v = ws.findVariable(name);
    EXPECT_NE(v, nullptr) << name;
    static Variable none;
    return v ? *v : none;
}

inline void expectColor(glm::vec4 actual, glm::vec4 expected) {
    for (int i = 0; i < 4; ++i) EXPECT_FLOAT_EQ(actual[i], expected[i]) << "component " << i;
}

// Errors of an .rfx text (named t.rfx): its formatted diagnostics.
inline std::string errorsOf(const std::string& text, const std::string& effect = "") {
    Result<Workspace> p = importRfxText(text, "t.rfx", ".", {effect});
    EXPECT_FALSE(p.ok());
    return formatAll(p.diagnostics());
}

// An OpenGL effect "E" in workspace "W" whose body starts on line 4.
inline std::string glEffect(const std::string& body) {
    return "<RENDER_MONKEY>\n"
           "<RmEffectWorkspace NAME=\"W\" ACTIVE_EFFECT=\"W.E\">\n"
           "<RmOpenGLEffect NAME=\"E\" API=\"OpenGL\">\n" +
           body + "</RmOpenGLEffect>\n</RmEffectWorkspace>\n</RENDER_MONKEY>\n";
}

inline const char* kFragment =
    "<RmGLShader NAME=\"F\" PIXEL_SHADER=\"TRUE\"><RmShaderCode><![CDATA[void main() { gl_FragColor = vec4(1.0); }]]>"
    "</RmShaderCode></RmGLShader>";

// A Direct3D pass with a render-state block holding `states`; the first pass has a pixel shader.
inline std::string d3dStatePass(int index, const std::string& states) {
    return "<RmPass NAME=\"P" + std::to_string(index) + "\" PASS_INDEX=\"" + std::to_string(index) +
           "\"><RmRenderStateBlock NAME=\"S\">" + states + "</RmRenderStateBlock>" +
           (index == 0 ? "<RmHLSLShader NAME=\"PS\" PIXEL_SHADER=\"TRUE\" TARGET=\"ps_2_0\" ENTRY_POINT=\"main\">"
                         "<RmShaderCode><![CDATA[float4 main() : COLOR { return 1; }]]></RmShaderCode></RmHLSLShader>"
                       : "") +
           "</RmPass>\n";
}

inline std::string d3dState(int number, const std::string& value) {
    return "<RmState NAME=\"D3DRS_" + std::to_string(number) + "\" STATE=\"" + std::to_string(number) + "\" VALUE=\"" +
           value + "\"/>";
}

inline std::string d3dEffect(const std::string& passes) {
    return "<RENDER_MONKEY>\n<RmEffectWorkspace NAME=\"W\" ACTIVE_EFFECT=\"W.E\">\n<RmDirectXEffect NAME=\"E\" API=\"D3D\">\n" +
           passes + "</RmDirectXEffect>\n</RmEffectWorkspace>\n</RENDER_MONKEY>\n";
}

}  // namespace rmfx::test::rfx_importer
