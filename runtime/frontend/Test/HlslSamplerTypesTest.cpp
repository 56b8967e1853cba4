#include "frontend/shader/HlslSamplerTypes.h"

#include <string>

#include <gtest/gtest.h>

namespace rmfx {
namespace {

TEST(HlslSamplerTypes, AnUntypedSamplerTakesTheTypeItsReadsImply) {
    EXPECT_EQ(typeGenericSamplers("sampler Sky : register(s0);\nfloat4 main(float3 d : TEXCOORD0) : COLOR { return texCUBE( Sky, d); }"),
              "samplerCUBE Sky : register(s0);\nfloat4 main(float3 d : TEXCOORD0) : COLOR { return texCUBE( Sky, d); }");
    EXPECT_EQ(typeGenericSamplers("sampler Noise;\nfloat f(float3 p) { return tex3D(Noise, p).r + tex3Dlod(Noise, float4(p, 0)).g; }"),
              "sampler3D Noise;\nfloat f(float3 p) { return tex3D(Noise, p).r + tex3Dlod(Noise, float4(p, 0)).g; }");
    EXPECT_EQ(typeGenericSamplers("sampler A; sampler B;\n// texCUBE(B, x)\nfloat4 g(float3 d) { return texCUBEbias(A, float4(d, 1)); }"),
              "samplerCUBE A; sampler B;\n// texCUBE(B, x)\nfloat4 g(float3 d) { return texCUBEbias(A, float4(d, 1)); }");
}

TEST(HlslSamplerTypes, A1DReadOfAnUntypedSamplerReadsTheMiddleRowOfA2DTexture) {
    EXPECT_EQ(typeGenericSamplers("sampler Rainbow;\nfloat3 f(float v) { return tex1D(Rainbow, v * (1 + v)).rgb + tex1D( Rainbow ,0.5).rgb; }"),
              "sampler Rainbow;\nfloat3 f(float v) { return tex2D(Rainbow,float2( v * (1 + v), 0.5)).rgb + tex2D( Rainbow ,float2(0.5, 0.5)).rgb; }");
    // With tex1Dlod among the reads there is no 2D equivalent written: sampler1D.
    EXPECT_EQ(typeGenericSamplers("sampler R; float4 f(float v) { return tex1D(R, v) + tex1Dlod(R, float4(v, 0, 0, 0)); }"),
              "sampler1D R; float4 f(float v) { return tex1D(R, v) + tex1Dlod(R, float4(v, 0, 0, 0)); }");
}

TEST(HlslSamplerTypes, OtherSamplersAreLeftAsTheyAre) {
    for (const std::string code : {
             "sampler Base; float4 main(float2 uv : TEXCOORD0) : COLOR { return tex2D(Base, uv); }",
             "sampler Mixed; float4 f(float3 d) { return tex2D(Mixed, d.xy) + texCUBE(Mixed, d); }",
             "sampler Unused; float4 main() : COLOR { return 0; }",
             "float4 f(float3 d) { sampler Local; return texCUBE(Local, d); }",  // not global
             "samplerCUBE Typed; float4 f(float3 d) { return texCUBE(Typed, d); }",
             "sampler", "",
         })
        EXPECT_EQ(typeGenericSamplers(code), code);
}

}  // namespace
}  // namespace rmfx
