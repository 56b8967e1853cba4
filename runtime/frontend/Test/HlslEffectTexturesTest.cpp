// Direct3D 9 effect-framework `texture` declarations blanked before glslang reads the HLSL
// (frontend/shader/HlslEffectTextures), as wrdn's HLSLACW.rfx declares them beside sampler_state blocks.

#include "frontend/shader/HlslEffectTextures.h"

#include <gtest/gtest.h>

#include "tests/support/TestSupport.h"

namespace rmfx {

using test::lines;

TEST(HlslEffectTextures, FileScopeTextureDeclarationsAreBlankedLinesKept) {
    const std::string code = lines({
        "texture displacementMap;",
        "sampler displacementSampler = sampler_state",
        "{",
        "    Texture = <displacementMap>;",
        "    MipFilter = Point;",
        "};",
        "texture grass : register(t1) < string file = \"grass.dds\"; >;",
        "// texture inComment;",
        "float4 main(float2 uv : TEXCOORD0) : COLOR0 { float texture2 = 1.0; return tex2D(displacementSampler, uv) * texture2; }",
    });
    EXPECT_EQ(blankEffectTextures(code), lines({
                                             "                        ",
                                             "sampler displacementSampler                ",
                                             " ",
                                             "                                ",
                                             "                      ",
                                             " ;",
                                             std::string(std::string("texture grass : register(t1) < string file = \"grass.dds\"; >;").size(), ' '),
                                             "// texture inComment;",
                                             "float4 main(float2 uv : TEXCOORD0) : COLOR0 { float texture2 = 1.0; return "
                                             "tex2D(displacementSampler, uv) * texture2; }",
                                         }));
}

TEST(HlslEffectTextures, OtherTypesAndBrokenCodeStay) {
    for (const char* code : {"Texture2D t; SamplerState s;", "textureCUBE c;", "float texture_scale;", "texture", "texture x",
                             "} texture y; {", ""}) {
        SCOPED_TRACE(code);
        const std::string out = blankEffectTextures(code);
        EXPECT_EQ(out.size(), std::string(code).size());
    }
    EXPECT_EQ(blankEffectTextures("Texture2D t;"), "Texture2D t;");
    EXPECT_EQ(blankEffectTextures("float texture_scale;"), "float texture_scale;");
}

}  // namespace rmfx
