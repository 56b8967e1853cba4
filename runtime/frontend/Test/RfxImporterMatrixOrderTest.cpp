// The RenderMonkey importer's HLSL matrix order: which way round semantic matrices are passed, from
// the version that saved the file, what the code multiplies, and what --rfx-matrices asks for.

#include "frontend/rfx/RfxImporter.h"

#include <utility>

#include <gtest/gtest.h>

#include "RfxImporterTestSupport.h"

namespace rmfx {
namespace {

using namespace test;
using namespace test::rfx_importer;

// RenderMonkey 1.5 and before passed matrices in OpenGL's layout (its HLSL wrote
// mul(view_proj_matrix, Pos)); 1.6 and later as D3DX does (mul(Input.Position, matViewProjection)).
// The version that saved the file decides; assembly always reads rows (m4x4).
TEST(RfxImporterMatrixOrder, HlslMatrixOrderFollowsTheVersionThatSavedTheFile) {
    for (const auto& [version, order] : {std::pair{"RenderMonkey 1.5", HlslMatrixOrder::ColumnVector},
                                         std::pair{"RenderMonkey 1.0", HlslMatrixOrder::ColumnVector},
                                         std::pair{"RenderMonkey 1.62", HlslMatrixOrder::RowVector},
                                         std::pair{"RenderMonkey 1.71", HlslMatrixOrder::RowVector},
                                         std::pair{"RenderMonkey 2.0", HlslMatrixOrder::RowVector}}) {
        SCOPED_TRACE(version);
        std::string text = d3dEffect(d3dStatePass(0, ""));
        text.replace(text.find("ACTIVE_EFFECT"), 0, "XML_VERSION=\"" + std::string(version) + "\" ");
        Result<Workspace> ws = importRfxText(text, "t.rfx", ".", {""});
        ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
        ASSERT_EQ(ws->passes[0].shaders.size(), 1u);
        EXPECT_EQ(ws->passes[0].shaders[0].matrixOrder, order);
        EXPECT_EQ(formatAll(ws.diagnostics()).find("XML_VERSION"), std::string::npos) << formatAll(ws.diagnostics());
    }
    for (const std::string& attribute : {std::string(), std::string("XML_VERSION=\"RenderMonkey\" ")}) {
        std::string text = d3dEffect(d3dStatePass(0, ""));
        text.replace(text.find("ACTIVE_EFFECT"), 0, attribute);
        Result<Workspace> ws = importRfxText(text, "t.rfx", ".", {""});
        ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
        EXPECT_EQ(ws->passes[0].shaders[0].matrixOrder, HlslMatrixOrder::RowVector);
        const std::string warnings = formatAll(ws.diagnostics());
        EXPECT_TRUE(
            test::hasLine(warnings, "t.rfx:2: warning: <RmEffectWorkspace NAME=\"W\">: XML_VERSION " +
                                        std::string(attribute.empty() ? "missing" : "\"RenderMonkey\"") +
                                        ": HLSL semantic matrices are passed as RenderMonkey 1.6 and later did, for mul(v, M)"))
            << warnings;
    }
    Workspace ws = imported("d3d_hlsl.rfx");  // RenderMonkey 1.71, with a disabled assembly pass
    EXPECT_EQ(ws.passes[0].shaders[0].matrixOrder, HlslMatrixOrder::RowVector);
    EXPECT_EQ(ws.passes[2].shaders[0].matrixOrder, HlslMatrixOrder::ColumnVector);
}

// A file whose HLSL was written for the other order than its version implies (gaxlin's
// LensFlare_10: saved by 1.71, mul(g_matViewProj, v)) is given the order asked for
// (rmfx render --rfx-matrices); assembly still reads rows, and a version that cannot be read is
// not warned about, since it decides nothing.
TEST(RfxImporterMatrixOrder, TheHlslMatrixOrderAskedForOverridesTheVersion) {
    for (const auto& [version, asked] : {std::pair{"RenderMonkey 1.71", HlslMatrixOrder::ColumnVector},
                                         std::pair{"RenderMonkey 1.5", HlslMatrixOrder::RowVector},
                                         std::pair{"", HlslMatrixOrder::ColumnVector}}) {
        SCOPED_TRACE(version);
        std::string text = d3dEffect(d3dStatePass(0, ""));
        if (*version) text.replace(text.find("ACTIVE_EFFECT"), 0, "XML_VERSION=\"" + std::string(version) + "\" ");
        Result<Workspace> ws = importRfxText(text, "t.rfx", ".", {"", asked});
        ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
        EXPECT_EQ(ws->passes[0].shaders[0].matrixOrder, asked);
        EXPECT_EQ(formatAll(ws.diagnostics()).find("XML_VERSION"), std::string::npos) << formatAll(ws.diagnostics());
    }
    Result<Workspace> ws = importRfxFile(rfxDir() / "d3d_hlsl.rfx", {"", HlslMatrixOrder::ColumnVector});
    ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
    EXPECT_EQ(ws->passes[0].shaders[0].matrixOrder, HlslMatrixOrder::ColumnVector);
    EXPECT_EQ(ws->passes[2].shaders[0].matrixOrder, HlslMatrixOrder::ColumnVector);
    ws = importRfxFile(rfxDir() / "d3d_hlsl.rfx", {"", HlslMatrixOrder::RowVector});
    ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
    EXPECT_EQ(ws->passes[2].shaders[0].matrixOrder, HlslMatrixOrder::ColumnVector) << "assembly";
}

// A Direct3D effect saved by `version` whose vertex shader (`code` from line 13 of the file)
// multiplies with `code`, the semantic matrices Mvp (ViewProjection), MvpT
// (ViewProjectionTranspose) and Wld (World) and the stored matrix S visible.
std::string matrixOrderEffect(const std::string& version, const std::string& code) {
    std::string values;
    for (int i = 0; i < 16; ++i) values += " VALUE_" + std::to_string(i) + "=\"" + (i % 5 == 0 ? "1" : "0") + "\"";
    std::string text = d3dEffect(
        "<RmMatrixVariable NAME=\"Mvp\" VARIABLE_SEMANTIC=\"ViewProjection\"" + values + "/>\n"
        "<RmMatrixVariable NAME=\"MvpT\" VARIABLE_SEMANTIC=\"ViewProjectionTranspose\"" + values + "/>\n"
        "<RmMatrixVariable NAME=\"S\" VARIABLE_SEMANTIC=\"\"" + values + "/>\n"
        "<RmMatrixVariable NAME=\"Wld\" VARIABLE_SEMANTIC=\"World\"" + values + "/>\n"
        "<RmPass NAME=\"P\" PASS_INDEX=\"0\"><RmHLSLShader NAME=\"VS\" PIXEL_SHADER=\"FALSE\" TARGET=\"vs_2_0\" "
        "ENTRY_POINT=\"main\"><RmShaderConstant NAME=\"Mvp\"/><RmShaderConstant NAME=\"MvpT\"/><RmShaderConstant NAME=\"S\"/>"
        "<RmShaderConstant NAME=\"Wld\"/><RmShaderCode><![CDATA[\nfloat4x4 Mvp : register(c0);\nfloat4x4 MvpT;\nfloat4x4 S; float4x4 Wld;\n"
        "float4 main(float4 p : POSITION) : POSITION {\n" + code + "\n}]]></RmShaderCode></RmHLSLShader></RmPass>\n");
    if (!version.empty()) text.replace(text.find("ACTIVE_EFFECT"), 0, "XML_VERSION=\"" + version + "\" ");
    return text;
}

// Which way round the HLSL multiplies the semantic matrices decides their order where it says one
// (LensFlare_10, saved by 1.71, writes mul(g_matViewProj, v)); a warning names the line that goes
// against the version. Where the code says both, or nothing, the version decides.
TEST(RfxImporterMatrixOrder, TheHlslMatrixOrderFollowsWhatTheCodeMultiplies) {
    struct Case {
        const char* version;
        const char* code;  // from line 13 of the file
        HlslMatrixOrder expected;
        const char*
            warning;  // on <RmEffectWorkspace NAME="W">, after "t.rfx:2: warning: <RmEffectWorkspace NAME="W">: "; empty: none
    };
    const Case cases[] = {
        {"RenderMonkey 1.71", "return mul(Mvp, p);", HlslMatrixOrder::ColumnVector,
         "t.rfx:13 multiplies mul(Mvp, p) (1 such in the effect), where "
         "RenderMonkey of XML_VERSION \"RenderMonkey 1.71\" passed its semantic matrices for mul(v, M): they are passed for "
         "mul(M, v), as the code asks (--rfx-matrices to choose)"},
        {"RenderMonkey 1.71", "return mul(float4(p.xyz, 1), (Mvp));", HlslMatrixOrder::RowVector, ""},
        {"RenderMonkey 1.5", "return mul(Mvp, p);", HlslMatrixOrder::ColumnVector, ""},
        {"RenderMonkey 1.5", "float4 q = mul(p, Mvp);\nreturn mul(q, Mvp);", HlslMatrixOrder::RowVector,
         "t.rfx:13 multiplies mul(p, Mvp) (2 such in the effect), where RenderMonkey of XML_VERSION \"RenderMonkey 1.5\" passed "
         "its semantic matrices for mul(M, v): they are passed for "
         "mul(v, M), as the code asks (--rfx-matrices to choose)"},
        // A transposed semantic, or transpose(), counts the other way round.
        {"RenderMonkey 1.71", "return mul(MvpT, p);", HlslMatrixOrder::RowVector, ""},
        {"RenderMonkey 1.71", "return mul(transpose(Mvp), p);", HlslMatrixOrder::RowVector, ""},
        {"RenderMonkey 1.5", "return mul(p, transpose(Mvp));", HlslMatrixOrder::ColumnVector, ""},
        // A product of matrices whose order of transforms is unknown (World and a stored or local
        // matrix, a transposed semantic), a stored matrix alone, no variable, or something on the
        // other side that is not known to be a vector says nothing.
        {"RenderMonkey 1.5",
         "float4x4 W = S;\nreturn mul(mul(Wld, S), p) + mul(Mvp, MvpT) + mul(p, S) + mul(p, Mvp[0]) + mul(W, Wld) + "
         "mul(2 * p, Mvp) + mul(unknown, Mvp) + mul(MvpT, S);",
         HlslMatrixOrder::ColumnVector, ""},
        {"RenderMonkey 1.71", "float4x4 W = S;\nreturn mul(Wld, W) + mul((float4x4) S, Wld) + mul(Mvp, MvpT) + mul(S, W);",
         HlslMatrixOrder::RowVector, ""},
        // Nothing comes after the projection: a matrix ending in it stands last whatever the other
        // (simpleCubeMapReflection-3, saved by 1.71: mul(view_proj_matrix, matWorld), matWorld stored).
        {"RenderMonkey 1.71", "float4x4 m = mul(Mvp, S);\nreturn mul(m, p);", HlslMatrixOrder::ColumnVector,
         "t.rfx:13 multiplies mul(Mvp, S) (2 such in the effect), where RenderMonkey of XML_VERSION \"RenderMonkey 1.71\" passed "
         "its semantic matrices for mul(v, M): they are passed for "
         "mul(M, v), as the code asks (--rfx-matrices to choose)"},
        {"RenderMonkey 1.5", "float4x4 W = S;\nreturn mul(p, mul(W, Mvp));", HlslMatrixOrder::RowVector,
         "t.rfx:14 multiplies mul(W, Mvp) (1 such in the effect), where RenderMonkey of XML_VERSION \"RenderMonkey 1.5\" passed "
         "its semantic matrices for mul(M, v): they are passed for "
         "mul(v, M), as the code asks (--rfx-matrices to choose)"},
        // Two semantic matrices: the one applied later on the left is M·v's order (skyBox_11,
        // saved by 1.71, writes m = mul(matViewProjection, matWorld); mul(m, Pos)).
        {"RenderMonkey 1.71", "float4x4 m = mul(Mvp, Wld);\nreturn mul(m, p);", HlslMatrixOrder::ColumnVector,
         "t.rfx:13 multiplies mul(Mvp, Wld) (2 such in the effect), where RenderMonkey of XML_VERSION \"RenderMonkey 1.71\" "
         "passed its semantic matrices for mul(v, M): they are passed for "
         "mul(M, v), as the code asks (--rfx-matrices to choose)"},
        {"RenderMonkey 1.5", "float4x4 m = mul(Wld, Mvp);\nreturn mul(p, m);", HlslMatrixOrder::RowVector,
         "t.rfx:13 multiplies mul(Wld, Mvp) (2 such in the effect), where RenderMonkey of XML_VERSION \"RenderMonkey 1.5\" "
         "passed its semantic matrices for mul(M, v): they are passed for "
         "mul(v, M), as the code asks (--rfx-matrices to choose)"},
        // A local computed from a semantic matrix counts as that matrix beside a vector: the product
        // says v·M's order, the position M·v's (rainBow_transp-1, saved by 1.5), and the version decides.
        {"RenderMonkey 1.5", "float4x4 mtr = mul(S, Mvp);\nreturn mul(mtr, p);", HlslMatrixOrder::ColumnVector,
         "the effect's HLSL multiplies its semantic matrices both ways round (mul(mtr, p) at t.rfx:14, 1 such; mul(S, Mvp) at "
         "t.rfx:13, 1 such): they are passed for mul(M, v), as RenderMonkey of XML_VERSION \"RenderMonkey 1.5\" did "
         "(--rfx-matrices to choose)"},
        {"RenderMonkey 1.71", "float4 q = mul(Mvp, mul(S, p)) + mul(mul(p, S), Mvp);\nreturn mul(Mvp, p) + mul(p.xyzw, Mvp);",
         HlslMatrixOrder::RowVector,
         "the effect's HLSL multiplies its semantic matrices both ways round (mul(Mvp, p) at t.rfx:14, 1 such; mul(p.xyzw, Mvp) "
         "at "
         "t.rfx:14, 1 such): they are passed for mul(v, M), as RenderMonkey of XML_VERSION \"RenderMonkey 1.71\" did "
         "(--rfx-matrices to choose)"},
        // Without a version the code decides, unwarned; with neither, the later versions' order, warned.
        {"", "return mul(Mvp, p);", HlslMatrixOrder::ColumnVector, ""},
        {"", "return p;", HlslMatrixOrder::RowVector,
         "XML_VERSION missing: HLSL semantic matrices are passed as RenderMonkey 1.6 and later did, for mul(v, M)"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(std::string(c.version) + ": " + c.code);
        Result<Workspace> ws = importRfxText(matrixOrderEffect(c.version, c.code), "t.rfx", ".", {""});
        ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
        ASSERT_EQ(ws->passes.size(), 1u);
        ASSERT_EQ(ws->passes[0].shaders.size(), 1u);
        EXPECT_EQ(ws->passes[0].shaders[0].matrixOrder, c.expected);
        const std::string said = formatAll(ws.diagnostics());
        if (*c.warning) {
            EXPECT_TRUE(test::hasLine(said, "t.rfx:2: warning: <RmEffectWorkspace NAME=\"W\">: " + std::string(c.warning)))
                << said;
        } else {
            EXPECT_EQ(said.find("mul("), std::string::npos) << said;
        }
        if (std::string(c.warning).find("XML_VERSION missing") == std::string::npos) {
            EXPECT_EQ(said.find("XML_VERSION missing"), std::string::npos) << said;
        }
    }
    // A matrix the pass declares itself counts too.
    std::string passLevel = matrixOrderEffect("RenderMonkey 1.71", "return mul(Own, p);");
    std::string own16;
    for (int i = 0; i < 16; ++i) own16 += " VALUE_" + std::to_string(i) + "=\"" + (i % 5 == 0 ? "1" : "0") + "\"";
    passLevel.replace(passLevel.find("<RmHLSLShader"), 0,
                      "<RmMatrixVariable NAME=\"Own\" VARIABLE_SEMANTIC=\"WorldViewProjection\"" + own16 + "/>");
    passLevel.replace(passLevel.find("float4x4 S;"), 0, "float4x4 Own;\n");
    Result<Workspace> own = importRfxText(passLevel, "t.rfx", ".", {""});
    ASSERT_TRUE(own) << formatAll(own.diagnostics());
    EXPECT_EQ(own->passes[0].shaders[0].matrixOrder, HlslMatrixOrder::ColumnVector) << formatAll(own.diagnostics());
    // What --rfx-matrices asks for overrides the code too.
    Result<Workspace> asked = importRfxText(matrixOrderEffect("RenderMonkey 1.71", "return mul(Mvp, p);"), "t.rfx", ".",
                                            {"", HlslMatrixOrder::RowVector});
    ASSERT_TRUE(asked) << formatAll(asked.diagnostics());
    EXPECT_EQ(asked->passes[0].shaders[0].matrixOrder, HlslMatrixOrder::RowVector);
    EXPECT_EQ(formatAll(asked.diagnostics()).find("mul("), std::string::npos) << formatAll(asked.diagnostics());
}

// A file upgraded from 1.5 keeps shaders writing mul(M, v) beside new ones writing mul(v, M)
// (atMOS_PassMethod_03: the planet's passes one way, the ring's the other): each shader whose own
// code says one order gets it, unwarned; a shader that says nothing gets the effect's.
TEST(RfxImporterMatrixOrder, EachShaderGetsTheMatrixOrderItsOwnCodeMultiplies) {
    std::string text = matrixOrderEffect("RenderMonkey 1.71", "return mul(Mvp, p);");
    const std::string pass = text.substr(text.find("<RmPass"), text.find("</RmPass>") + 9 - text.find("<RmPass"));
    std::string ring = pass, quiet = pass;
    ring.replace(ring.find("PASS_INDEX=\"0\""), 14, "PASS_INDEX=\"1\"");
    ring.replace(ring.find("return mul(Mvp, p);"), 19, "return mul(p, Mvp);");
    quiet.replace(quiet.find("PASS_INDEX=\"0\""), 14, "PASS_INDEX=\"2\"");
    quiet.replace(quiet.find("return mul(Mvp, p);"), 19, "return p;");
    text.insert(text.find("</RmPass>") + 9, "\n" + ring + "\n" + quiet);
    Result<Workspace> ws = importRfxText(text, "t.rfx", ".", {""});
    ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
    ASSERT_EQ(ws->passes.size(), 3u);
    EXPECT_EQ(ws->passes[0].shaders[0].matrixOrder, HlslMatrixOrder::ColumnVector);
    EXPECT_EQ(ws->passes[1].shaders[0].matrixOrder, HlslMatrixOrder::RowVector);
    EXPECT_EQ(ws->passes[2].shaders[0].matrixOrder, HlslMatrixOrder::RowVector);  // the 1.71 version's
    EXPECT_EQ(formatAll(ws.diagnostics()).find("mul("), std::string::npos) << formatAll(ws.diagnostics());

    // A shader that says both ways round (a product for v·M, a local through it for M·v) gets
    // mul(M, v) when compiled with COMPILER_FLAGS 32 (rainBow_transp-1's copy saved by 1.71), else
    // the version's order.
    for (const auto& [flags, expected] : {std::pair{"32", HlslMatrixOrder::ColumnVector}, std::pair{"0", HlslMatrixOrder::RowVector}}) {
        std::string both = matrixOrderEffect("RenderMonkey 1.71", "float4x4 mtr = mul(S, Mvp);\nreturn mul(mtr, p);");
        both.replace(both.find("ENTRY_POINT=\"main\""), 0, "COMPILER_FLAGS=\"" + std::string(flags) + "\" ");
        Result<Workspace> flagged = importRfxText(both, "t.rfx", ".", {""});
        ASSERT_TRUE(flagged) << formatAll(flagged.diagnostics());
        EXPECT_EQ(flagged->passes[0].shaders[0].matrixOrder, expected) << flags;
    }
}

// The test file written in LensFlare_10's way: both shaders of its pass get the order its vertex
// shader's mul(g_matViewProj, v) asks for, with a warning naming that line.
TEST(RfxImporterMatrixOrder, AFileWrittenForTheOtherMatrixOrderIsReadByItsCode) {
    Result<Workspace> ws = importRfxFile(rfxDir() / "d3d_matrix_order.rfx", {""});
    ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
    ASSERT_EQ(ws->passes.size(), 1u);
    ASSERT_EQ(ws->passes[0].shaders.size(), 2u);
    for (const ShaderSource& s : ws->passes[0].shaders) EXPECT_EQ(s.matrixOrder, HlslMatrixOrder::ColumnVector);
    const std::string said = formatAll(ws.diagnostics());
    const std::string file = (rfxDir() / "d3d_matrix_order.rfx").string();
    EXPECT_TRUE(
        test::hasLine(said, file + ":8: warning: <RmEffectWorkspace NAME=\"Flare\">: " + file +
                                ":34 multiplies mul(g_matViewProj, float4(corner, 1)) (1 such in the effect), where RenderMonkey "
                                "of XML_VERSION \"RenderMonkey 1.71\" passed its semantic matrices for mul(v, M): they are "
                                "passed for mul(M, v), as the code asks (--rfx-matrices to choose)"))
        << said;
}

}  // namespace
}  // namespace rmfx
