// ReshadeParser's declarations: uniforms with their annotations and initial values, textures,
// samplers and storages with their properties, structs, constants, namespaces, and functions with
// their parameters and bodies kept as spans.
#include "frontend/Test/ReshadeParserTestSupport.h"

#include <gtest/gtest.h>

namespace rmfx {
namespace {

using Lines = std::vector<std::string>;
using test::lines;

Lines annotationsOf(const ReshadeAnnotations& annotations) {
    Lines out;
    for (const ReshadeAnnotation& a : annotations) out.push_back(a.name + "=" + a.value.describe());
    return out;
}

}  // namespace

TEST(ReshadeParserDeclarations, UniformsWithEveryAnnotationAndInitialValues) {
    test::ScratchDir dir;
    test::ReshadeParse parse = test::parseText(
        dir, lines({"uniform float Strength < ui_type = \"slider\"; ui_min = 0.0; ui_max = 1.0; ui_step = 0.01;",
                    "  ui_label = \"Strength \" \"(x)\"; ui_tooltip = \"How much\\nof it\"; ui_category = \"Main\";",
                    "  ui_category_closed = true; ui_spacing = 2; ui_units = \"px\"; hidden = false; > = 0.5;",
                    "uniform int Mode < ui_type = \"combo\"; ui_items = \"A\\0B\\0\"; > = 1;",
                    "uniform float3 Tint < ui_type = \"color\"; ui_min = float3(0, 0, 0); > = float3(1.0, 0.5, 0.25);",
                    "uniform float timer < source = \"timer\"; >;", "uniform bool Flag = true;",
                    "uniform float4x4 M = float4x4(1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1);",
                    "uniform float Weights[3] = { 1, 2.5, 3 };", "uniform uint Bits = 0xFFu, Other = -(2 << 3);",
                    "uniform float Half = 1920 / 2 * 0.5 + float2(1, 2).y;", "float Implicit = 1;",
                    "uniform float2 Comma = (1.5, 2.5);", "uniform vector<int, 3> V = 2; uniform matrix<float, 2, 3> Mx;"}));
    EXPECT_EQ(parse.problems(), (Lines{"main.fx:12: warning: uniform Implicit: a global without 'static' is a uniform, as if "
                                       "declared 'uniform'"}));
    const std::vector<ReshadeUniform>& u = parse.effect.uniforms;
    ASSERT_EQ(u.size(), 14u);
    EXPECT_EQ(u[0].name, "Strength");
    EXPECT_EQ(u[0].type.base, ReshadeBaseType::Float);
    EXPECT_EQ(u[0].where.line, 1);
    EXPECT_EQ(annotationsOf(u[0].annotations),
              (Lines{"ui_type=\"slider\"", "ui_min=0.0", "ui_max=1.0", "ui_step=0.01", "ui_label=\"Strength (x)\"",
                     "ui_tooltip=\"How much\\nof it\"", "ui_category=\"Main\"", "ui_category_closed=true", "ui_spacing=2",
                     "ui_units=\"px\"", "hidden=false"}));
    EXPECT_EQ(u[0].annotations[4].where.line, 2);
    EXPECT_EQ(u[0].initializer->describe(), "0.5");
    EXPECT_EQ(findAnnotation(u[1].annotations, "ui_items")->value.text, std::string("A\0B\0", 4));
    EXPECT_EQ(u[1].initializer->kind, ReshadeValue::Kind::Int);
    EXPECT_EQ(u[2].type.rows, 3);
    EXPECT_EQ(findAnnotation(u[2].annotations, "ui_min")->value.describe(), "{0.0, 0.0, 0.0}");
    EXPECT_EQ(u[2].initializer->describe(), "{1.0, 0.5, 0.25}");
    EXPECT_EQ(findAnnotation(u[3].annotations, "source")->value.text, "timer");
    EXPECT_FALSE(u[3].initializer.has_value());
    EXPECT_EQ(u[4].initializer->describe(), "true");
    EXPECT_EQ(u[5].type.rows, 4);
    EXPECT_EQ(u[5].type.cols, 4);
    EXPECT_EQ(u[5].initializer->components.size(), 16u);
    EXPECT_EQ(u[6].type.arrayLength, 3);
    EXPECT_EQ(u[6].initializer->describe(), "{1.0, 2.5, 3.0}");
    EXPECT_EQ(u[7].name, "Bits");
    EXPECT_EQ(u[7].initializer->describe(), "255");
    EXPECT_EQ(u[8].name, "Other");
    EXPECT_EQ(u[8].initializer->describe(), "4294967280");  // -16 as a uint
    EXPECT_EQ(u[9].initializer->describe(), "482.0");
    EXPECT_TRUE(u[10].implicit);
    EXPECT_EQ(u[11].initializer->describe(), "{2.5, 2.5}");  // the comma operator, then spread
    EXPECT_EQ(u[12].type.base, ReshadeBaseType::Int);
    EXPECT_EQ(u[12].initializer->describe(), "{2, 2, 2}");
    EXPECT_EQ(u[13].type.rows, 2);
    EXPECT_EQ(u[13].type.cols, 3);
    EXPECT_FALSE(u[0].implicit);
}

TEST(ReshadeParserDeclarations, TexturesWithSizesFormatsSemanticsAndAnnotations) {
    test::ScratchDir dir;
    ReshadeSettings settings;
    settings.width = 1280;
    settings.height = 720;
    test::ReshadeParse parse = test::parseText(
        dir,
        lines({"texture BackBufferTex : COLOR;", "texture2D DepthTex : depth;",
               "texture BlurTex { Width = BUFFER_WIDTH / 2; Height = BUFFER_HEIGHT * 0.5; Format = RGBA16F; MipLevels = 1 + 2; };",
               "texture LutTex < source = \"lut.png\"; pooled = true; > { Width = 32 * 32; Height = 32; Format = rgba8; };",
               "texture3D Volume { Width = 16; Height = 16; Depth = 16; Format = R32F; };",
               "texture IntTex { Format = R32I; }; texture UintTex { Format = R32U; }; texture Wide { Format = RGB10A2; };",
               "texture2D<uint> Typed { Format = R8G8; };"}),
        settings);
    EXPECT_EQ(parse.problems(), Lines{});
    const std::vector<ReshadeTexture>& t = parse.effect.textures;
    ASSERT_EQ(t.size(), 9u);
    EXPECT_EQ(t[0].semantic, "COLOR");
    EXPECT_EQ(t[1].semantic, "DEPTH");
    EXPECT_EQ(t[1].type.name, "texture2D");
    EXPECT_EQ(t[2].width, 640);
    EXPECT_EQ(t[2].height, 360);
    EXPECT_EQ(t[2].format, ReshadeTextureFormat::RGBA16F);
    EXPECT_EQ(t[2].mipLevels, 3);
    EXPECT_EQ(t[2].where.line, 3);
    EXPECT_EQ(t[3].width, 1024);
    EXPECT_EQ(t[3].format, ReshadeTextureFormat::RGBA8);
    EXPECT_EQ(annotationsOf(t[3].annotations), (Lines{"source=\"lut.png\"", "pooled=true"}));
    EXPECT_EQ(t[4].type.dimensions, 3);
    EXPECT_EQ(t[4].depth, 16);
    EXPECT_EQ(t[5].format, ReshadeTextureFormat::R32I);
    EXPECT_EQ(t[5].width, 1);  // ReShade's default size
    EXPECT_EQ(t[6].format, ReshadeTextureFormat::R32U);
    EXPECT_EQ(t[7].format, ReshadeTextureFormat::RGB10A2);
    EXPECT_EQ(t[8].type.element, "uint");
    EXPECT_EQ(t[8].format, ReshadeTextureFormat::RG8);
}

TEST(ReshadeParserDeclarations, SamplersAndStoragesWithTheirStates) {
    test::ScratchDir dir;
    test::ReshadeParse parse = test::parseText(
        dir, lines({"texture Tex { Width = 4; Height = 4; };", "namespace Ns { texture Inner { Format = R16F; }; }",
                    "sampler Plain { Texture = Tex; };",
                    "sampler2D Full { Texture = Ns::Inner; AddressU = WRAP; AddressV = REPEAT; AddressW = Mirror;",
                    "  MagFilter = POINT; MinFilter = ANISOTROPIC; MipFilter = LINEAR; MinLOD = 1.5; MaxLOD = 4;",
                    "  MipLODBias = -0.5f; SRGBTexture = true; };", "sampler Bordered { Texture = Tex; AddressU = BORDER; SRGBTexture = TRUE; };",
                    "storage2D Store { Texture = Tex; MipLevel = 2; };", "storage Plain2 { Texture = Tex; };"}));
    EXPECT_EQ(parse.problems(), Lines{});
    const std::vector<ReshadeSampler>& s = parse.effect.samplers;
    ASSERT_EQ(s.size(), 3u);
    EXPECT_EQ(s[0].texture, "Tex");
    EXPECT_EQ(s[0].address[0], ReshadeAddressMode::Clamp);
    EXPECT_EQ(s[0].minFilter, ReshadeFilter::Linear);
    EXPECT_EQ(s[0].maxLod, FLT_MAX);
    EXPECT_FALSE(s[0].srgb);
    EXPECT_EQ(s[1].texture, "Ns::Inner");
    EXPECT_EQ(s[1].address[0], ReshadeAddressMode::Wrap);
    EXPECT_EQ(s[1].address[1], ReshadeAddressMode::Wrap);
    EXPECT_EQ(s[1].address[2], ReshadeAddressMode::Mirror);
    EXPECT_EQ(s[1].magFilter, ReshadeFilter::Point);
    EXPECT_EQ(s[1].minFilter, ReshadeFilter::Anisotropic);
    EXPECT_EQ(s[1].mipFilter, ReshadeFilter::Linear);
    EXPECT_EQ(s[1].minLod, 1.5f);
    EXPECT_EQ(s[1].maxLod, 4.0f);
    EXPECT_EQ(s[1].mipLodBias, -0.5f);
    EXPECT_TRUE(s[1].srgb);
    EXPECT_EQ(s[1].where.line, 4);
    EXPECT_EQ(s[2].address[0], ReshadeAddressMode::Border);
    EXPECT_TRUE(s[2].srgb);  // TRUE, as D3D effects write it and ReShade reads it
    const std::vector<ReshadeStorage>& st = parse.effect.storages;
    ASSERT_EQ(st.size(), 2u);
    EXPECT_EQ(st[0].texture, "Tex");
    EXPECT_EQ(st[0].mipLevel, 2);
    EXPECT_EQ(st[1].mipLevel, 0);
}

TEST(ReshadeParserDeclarations, StructsConstantsAndNamespaces) {
    test::ScratchDir dir;
    test::ReshadeParse parse = test::parseText(
        dir, lines({"static const float PI = 3.14159;", "static const int SIZE = 8;",
                    "struct Vertex { float4 pos : SV_Position; float2 uv : TEXCOORD0, uv2; int id[2]; };",
                    "namespace Outer {", "  static const int SIZE = 16;", "  namespace Inner {",
                    "    texture T { Width = SIZE * 2; Height = ::SIZE; };", "    struct Data { Vertex v; };",
                    "  }", "  uniform float U < ui_max = PI; > = SIZE;", "}", "groupshared float Shared[SIZE];",
                    "static float4 Mutable = float4(1, 2, 3, 4) * PI;", "static const float3 FromIntrinsic = normalize(float3(1, 1, 1));",
                    "Outer::Inner::Data Global;"}));
    EXPECT_EQ(parse.errors(), Lines{});
    ASSERT_EQ(parse.effect.structs.size(), 2u);
    const ReshadeStruct& v = parse.effect.structs[0];
    EXPECT_EQ(v.name, "Vertex");
    ASSERT_EQ(v.fields.size(), 4u);
    EXPECT_EQ(v.fields[0].semantic, "SV_Position");
    EXPECT_EQ(v.fields[2].name, "uv2");
    EXPECT_EQ(v.fields[2].type.name, "float2");
    EXPECT_EQ(v.fields[3].type.arrayLength, 2);
    EXPECT_EQ(parse.effect.structs[1].name, "Outer::Inner::Data");
    EXPECT_EQ(parse.effect.structs[1].fields[0].type.base, ReshadeBaseType::Struct);
    ASSERT_EQ(parse.effect.textures.size(), 1u);
    EXPECT_EQ(parse.effect.textures[0].name, "Outer::Inner::T");
    EXPECT_EQ(parse.effect.textures[0].width, 32);  // the nearest SIZE
    EXPECT_EQ(parse.effect.textures[0].height, 8);  // ::SIZE, the global one
    ASSERT_EQ(parse.effect.uniforms.size(), 2u);
    EXPECT_EQ(parse.effect.uniforms[0].name, "Outer::U");
    EXPECT_EQ(parse.effect.uniforms[0].initializer->describe(), "16.0");
    EXPECT_EQ(findAnnotation(parse.effect.uniforms[0].annotations, "ui_max")->value.describe(), "3.14159");
    EXPECT_EQ(parse.effect.uniforms[1].type.name, "Outer::Inner::Data");
    const std::vector<ReshadeVariable>& vars = parse.effect.variables;
    ASSERT_EQ(vars.size(), 6u);
    EXPECT_EQ(vars[0].value->describe(), "3.14159");
    EXPECT_EQ(vars[2].name, "Outer::SIZE");
    EXPECT_EQ(vars[3].name, "Shared");
    EXPECT_EQ(vars[3].type.arrayLength, 8);
    EXPECT_TRUE(vars[3].qualifiers & kReshadeGroupshared);
    EXPECT_EQ(vars[4].value->describe(), "{3.14159, 6.28318, 9.42477, 12.56636}");
    EXPECT_EQ(parse.text(vars[4].initializer), "float4(1, 2, 3, 4) * PI");
    EXPECT_FALSE(vars[5].value.has_value());  // normalize is left to the shader compiler
    EXPECT_EQ(parse.text(vars[5].initializer), "normalize(float3(1, 1, 1))");
    Lines order;
    for (const ReshadeDeclaration& d : parse.effect.order) order.push_back(std::to_string(int(d.kind)) + ":" + std::to_string(d.index));
    EXPECT_EQ(order, (Lines{"5:0", "5:1", "4:0", "5:2", "1:0", "4:1", "0:0", "5:3", "5:4", "5:5", "0:1"}));
}

TEST(ReshadeParserDeclarations, FunctionsWithParametersAndBodySpans) {
    test::ScratchDir dir;
    test::ReshadeParse parse = test::parseText(
        dir, lines({"float3 Tone(float3 c, uniform float k) { return c; }",
                    "void PostVS(in uint id : SV_VertexID, out float4 position : SV_Position, inout float2 uv : TEXCOORD)",
                    "{", "    if (id == 2) { uv.x = 2.0; } else { uv.x = 0.0; }",
                    "    string s = \"} not a brace {\"; // } nor this", "    /* { */ position = float4(uv, 0, 1);",
                    "}", "float4 PS(float4 pos : SV_Position, nointerpolation float2 uv : TEXCOORD0) : SV_Target { return 0; }",
                    "namespace Ns { float Helper(void) { { { } } return 1; } }", "float3 Tone(float c) { return c; }",
                    "float Filter(sampler s, const int radius = 3, in float seed = 0.5) { return seed; }",
                    "[shader(\"compute\")] [numthreads(8, 4 * 2, 1)] void Main(uint3 id : SV_DispatchThreadID) { }"}));
    EXPECT_EQ(parse.errors(), Lines{});
    const std::vector<ReshadeFunction>& f = parse.effect.functions;
    ASSERT_EQ(f.size(), 7u);
    EXPECT_EQ(f[0].name, "Tone");
    EXPECT_EQ(f[0].returnType.rows, 3);
    EXPECT_EQ(parse.text(f[0].body), "{ return c; }");
    EXPECT_EQ(f[1].name, "PostVS");
    ASSERT_EQ(f[1].parameters.size(), 3u);
    EXPECT_EQ(f[1].parameters[0].qualifiers, kReshadeIn);
    EXPECT_EQ(f[1].parameters[0].semantic, "SV_VertexID");
    EXPECT_EQ(f[1].parameters[1].qualifiers, kReshadeOut);
    EXPECT_EQ(f[1].parameters[1].name, "position");
    EXPECT_EQ(f[1].parameters[2].qualifiers, kReshadeIn | kReshadeOut);
    EXPECT_EQ(f[1].parameters[2].semantic, "TEXCOORD");
    EXPECT_EQ(f[1].where.line, 2);
    EXPECT_EQ(f[1].body.where.line, 3);
    EXPECT_EQ(parse.text(f[1].body),
              "{\n    if (id == 2) { uv.x = 2.0; } else { uv.x = 0.0; }\n    string s = \"} not a brace {\";\n"
              "      position = float4(uv, 0, 1);\n}");
    EXPECT_EQ(f[2].returnSemantic, "SV_Target");
    EXPECT_EQ(f[2].parameters[1].qualifiers, kReshadeIn | kReshadeNoInterpolation);
    EXPECT_EQ(f[3].name, "Ns::Helper");
    EXPECT_TRUE(f[3].parameters.empty());
    EXPECT_EQ(parse.text(f[3].body), "{ { { } } return 1; }");
    EXPECT_EQ(f[4].name, "Tone");  // an overload
    ASSERT_EQ(f[5].parameters.size(), 3u);
    EXPECT_EQ(f[5].parameters[0].type.base, ReshadeBaseType::Sampler);
    EXPECT_FALSE(f[5].parameters[0].defaultValue.has_value());
    EXPECT_EQ(f[5].parameters[1].qualifiers, kReshadeIn | kReshadeConst);
    EXPECT_EQ(f[5].parameters[1].defaultValue->describe(), "3");
    EXPECT_EQ(f[5].parameters[2].defaultValue->describe(), "0.5");
    ASSERT_EQ(f[6].attributes.size(), 2u);
    EXPECT_EQ(f[6].attributes[0].name, "shader");
    EXPECT_EQ(f[6].attributes[0].arguments[0].text, "compute");
    EXPECT_EQ(f[6].attributes[1].name, "numthreads");
    EXPECT_EQ(f[6].attributes[1].arguments[1].describe(), "8");
    EXPECT_TRUE(f[0].attributes.empty());
}

}  // namespace rmfx
