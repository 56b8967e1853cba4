// The workspace parser's model: the default workspace and one using every feature, read field by
// field; the name from the file stem; target sizes rounded up.

#include "frontend/workspace/WorkspaceParser.h"

#include <gtest/gtest.h>

#include "io/mesh/BuiltinMeshes.h"
#include "WorkspaceParserTestSupport.h"

namespace rmfx {
namespace {

using namespace test;
using namespace test::workspace_parser;

TEST(WorkspaceParserModel, DefaultWorkspace) {
    const auto path = test::sourceDir() / "effects" / "default.xml";
    Result<Workspace> p = parseWorkspaceFile(path);
    ASSERT_EQ(formatAll(p.diagnostics()), "");
    ASSERT_TRUE(p.ok());
    const Workspace& ws = *p;
    const std::string file = path.string();
    EXPECT_EQ(ws.name, "default");
    EXPECT_EQ(ws.folder, path.parent_path());
    EXPECT_EQ(ws.description, "HDR sky and reflective teapot with exposure control");
    EXPECT_EQ(ws.width, 512);
    EXPECT_EQ(ws.height, 512);

    EXPECT_EQ(ws.camera.target, glm::vec3(0.0f));
    EXPECT_FLOAT_EQ(ws.camera.distance, 3.2f);
    EXPECT_FLOAT_EQ(ws.camera.yawDegrees, 35.0f);
    EXPECT_FLOAT_EQ(ws.camera.pitchDegrees, 12.0f);
    EXPECT_FLOAT_EQ(ws.camera.fovYDegrees, 50.0f);
    EXPECT_FLOAT_EQ(ws.camera.nearPlane, 0.05f);  // default
    EXPECT_EQ(ws.camera.where.line, 7);

    ASSERT_EQ(ws.variables.size(), 5u);
    const Variable& exposure = ws.variables[0];
    EXPECT_EQ(exposure.name, "Exposure_Level");
    EXPECT_EQ(exposure.value, Value::ofFloat(0.8f));
    EXPECT_EQ(exposure.min, 0.0f);
    EXPECT_EQ(exposure.max, 8.0f);
    EXPECT_EQ(exposure.step, 0.01f);
    EXPECT_EQ(exposure.widget, WidgetHint::Slider);
    EXPECT_EQ(exposure.description, "scales the HDR image before tone mapping");
    EXPECT_EQ(exposure.where.file, file);
    EXPECT_EQ(exposure.where.line, 9);
    EXPECT_EQ(ws.variables[1].name, "Tone_Map");
    EXPECT_EQ(ws.variables[1].value, Value::ofBool(true));
    EXPECT_EQ(ws.variables[1].where.line, 11);
    EXPECT_EQ(ws.variables[2].value.type, ValueType::Vec3);
    EXPECT_EQ(formatValue(ws.variables[2].value), "-0.35 0.12 -0.93");
    EXPECT_EQ(ws.variables[3].widget, WidgetHint::Drag);
    EXPECT_FALSE(ws.variables[3].step);
    EXPECT_EQ(ws.variables[4].name, "Teapot_Tint");
    EXPECT_EQ(ws.variables[4].value.type, ValueType::Color3);
    EXPECT_EQ(ws.variables[4].where.line, 14);

    ASSERT_EQ(ws.snippets.size(), 1u);
    EXPECT_EQ(ws.snippets[0].name, "sky.glsl");
    EXPECT_EQ(ws.snippets[0].codeLine, 16);
    EXPECT_EQ(ws.snippets[0].where.line, 16);
    EXPECT_NE(ws.snippets[0].code.find("vec3 skyRadiance(vec3 d)"), std::string::npos);

    ASSERT_EQ(ws.targets.size(), 1u);
    EXPECT_EQ(ws.targets[0].name, "hdr");
    EXPECT_EQ(ws.targets[0].format, TargetFormat::RGBA16F);
    EXPECT_TRUE(ws.targets[0].size.relative);
    EXPECT_EQ(ws.targets[0].size.scaleX, 1.0);
    EXPECT_EQ(ws.targets[0].size.scaleY, 1.0);
    EXPECT_FALSE(ws.targets[0].mipmaps);
    EXPECT_EQ(ws.targets[0].where.line, 34);
    EXPECT_TRUE(ws.textures.empty());

    ASSERT_EQ(ws.passes.size(), 3u);
    const Pass& sky = ws.passes[0];
    EXPECT_EQ(sky.name, "sky");
    EXPECT_EQ(sky.target, "hdr");
    EXPECT_EQ(sky.where.line, 36);
    EXPECT_EQ(sky.clear.color, glm::vec4(0, 0, 0, 1));
    EXPECT_EQ(sky.clear.depth, 1.0f);
    EXPECT_FALSE(sky.blend.enabled);
    EXPECT_FALSE(sky.depth.test);
    EXPECT_EQ(sky.draw.mesh, BuiltinMesh::FullscreenTriangle);
    EXPECT_EQ(sky.draw.where.line, 36);  // the implicit draw is located at its pass
    ASSERT_EQ(sky.shaders.size(), 1u);
    EXPECT_EQ(sky.shaders[0].stage, ShaderStage::Fragment);
    EXPECT_TRUE(sky.shaders[0].file.empty());
    EXPECT_EQ(sky.shaders[0].codeLine, 38);
    EXPECT_EQ(sky.shaders[0].code.substr(0, 19), "\n#version 450 core\n");

    const Pass& teapot = ws.passes[1];
    EXPECT_TRUE(teapot.depth.test);
    EXPECT_TRUE(teapot.depth.write);
    EXPECT_EQ(teapot.depth.func, CompareFunc::Less);
    EXPECT_EQ(teapot.raster.cull, CullFace::Back);
    EXPECT_TRUE(teapot.raster.frontCounterClockwise);
    EXPECT_EQ(teapot.draw.mesh, BuiltinMesh::Teapot);
    EXPECT_EQ(teapot.draw.scale, glm::vec3(1.0f));
    EXPECT_EQ(teapot.draw.where.line, 53);

    const Pass& tonemap = ws.passes[2];
    EXPECT_EQ(tonemap.target, "");
    EXPECT_EQ(ws.passTargetName(tonemap), "output");
    ASSERT_EQ(tonemap.samplers.size(), 1u);
    EXPECT_EQ(tonemap.samplers[0].uniform, "hdrImage");
    EXPECT_EQ(tonemap.samplers[0].target, "hdr");
    EXPECT_EQ(tonemap.samplers[0].filter, Filter::Nearest);
    EXPECT_EQ(tonemap.samplers[0].mipmap, MipmapMode::None);
    EXPECT_EQ(tonemap.samplers[0].wrapS, Wrap::Clamp);
    EXPECT_EQ(tonemap.samplers[0].where.line, 75);

    EXPECT_EQ(ws.output.target, "");
    EXPECT_EQ(ws.outputTargetName(), "output");
    EXPECT_EQ(ws.output.transform, DisplayTransform::Srgb);
    EXPECT_EQ(ws.output.format, TargetFormat::RGBA16F);
    EXPECT_EQ(ws.output.where.line, 90);
}

TEST(WorkspaceParserModel, EveryFeature) {
    Workspace ws = parsedOk(lines({
        /*  1 */ "<workspace version=\"1\" name=\"all\" size=\"256x128\">",
        /*  2 */ "  <camera target=\"0 1 0\" distance=\"5\" yaw=\"-10\" pitch=\"20\" fov=\"40\" near=\"0.1\" far=\"50\"/>",
        /*  3 */ "  <int name=\"Mode\" value=\"1\" options=\"off, soft , hard\" description=\"how\"/>",
        /*  4 */ "  <color name=\"Glow\" value=\"2 1 0.5 1\" hdr=\"true\" ui=\"color\"/>",
        /*  5 */ "  <vec2 name=\"Offset\" value=\"0.5, -0.5\" min=\"-1\" max=\"1\" step=\"0.1\" ui=\"drag\"/>",
        /*  6 */ "  <bool name=\"On\" value=\"0\" ui=\"checkbox\"/>",
        /*  7 */ "  <mat4 name=\"M\" value=\"1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\"/>",
        /*  8 */ "  <texture name=\"noise\" file=\"noise.png\" colorspace=\"srgb\" mipmaps=\"false\"/>",
        /*  9 */ "  <cubemap name=\"env\" file=\"sky.hdr\" layout=\"equirect\" face-size=\"256\"/>",
        /* 10 */ "  <cubemap name=\"box\">",
        /* 11 */ "    <face side=\"-z\" file=\"nz.png\"/>",
        /* 12 */ "    <face side=\"+x\" file=\"px.png\"/>",
        /* 13 */ "    <face side=\"-x\" file=\"nx.png\"/>",
        /* 14 */ "    <face side=\"+y\" file=\"py.png\"/>",
        /* 15 */ "    <face side=\"-y\" file=\"ny.png\"/>",
        /* 16 */ "    <face side=\"+z\" file=\"pz.png\"/>",
        /* 17 */ "  </cubemap>",
        /* 18 */ "  <target name=\"quarter\" format=\"rgba8\" scale=\"1/4\"/>",
        /* 19 */ "  <target name=\"wide\" format=\"r11g11b10f\" scale=\"1/2 0.125\" mipmaps=\"true\" initial=\"0 0 0 1\"/>",
        /* 20 */ "  <target name=\"fixed\" format=\"rg32f\" size=\"64x32\"/>",
        /* 21 */ "  <pass name=\"geometry\" target=\"fixed\" enabled=\"false\">",
        /* 22 */ "    <clear depth=\"0.5\"/>",
        /* 23 */ "    <blend mode=\"custom\" src=\"src-alpha\" dst=\"one-minus-src-alpha\" op=\"reverse-subtract\" dst-alpha=\"one\" constant=\"1 0 0 1\"/>",
        /* 24 */ "    <depth test=\"gequal\" write=\"false\"/>",
        /* 25 */ "    <cull face=\"front\" front=\"cw\"/>",
        /* 26 */ "    <draw file=\"models/rock.obj\" translate=\"1 2 3\" rotate=\"0 90 0\" scale=\"2\"/>",
        /* 27 */ "    <shader stage=\"vertex\" file=\"rock.vert\"/>",
        /* 28 */ "    <shader stage=\"fragment\" file=\"rock.frag\"/>",
        /* 29 */ "    <float name=\"Mode_Scale\" value=\"3\"/>",
        /* 30 */ "  </pass>",
        /* 31 */ "  <pass name=\"blend\" target=\"wide\">",
        /* 32 */ "    <blend mode=\"premultiplied\"/>",
        /* 33 */ "    <depth test=\"off\"/>",
        /* 34 */ "    <draw mesh=\"sphere\" scale=\"1 2 3\"/>",
        /* 35 */ "    <sampler name=\"previous\" target=\"wide\" frame=\"previous\" filter=\"nearest\" mipmap=\"linear\" wrap=\"repeat\" wrap-t=\"border\" border=\"1 1 1 1\"/>",
        /* 36 */ "    <sampler name=\"tex\" texture=\"noise\" wrap=\"mirror\"/>",
        /* 37 */ "    <shader stage=\"fragment\">void main() {}</shader>",
        /* 38 */ "  </pass>",
        /* 39 */ "  <pass name=\"add\">",
        /* 40 */ "    <blend mode=\"add\"/>",
        /* 41 */ "    <cull/>",
        /* 42 */ "    <depth test=\"less\"/>",
        /* 43 */ "    <shader stage=\"fragment\" file=\"add.frag\"/>",
        /* 44 */ "  </pass>",
        /* 45 */ "  <output target=\"wide\" transform=\"none\"/>",
        /* 46 */ "</workspace>",
    }));
    EXPECT_EQ(ws.name, "all");
    EXPECT_EQ(ws.path, kPath);
    EXPECT_EQ(ws.folder, "fx");
    EXPECT_EQ(ws.width, 256);
    EXPECT_EQ(ws.height, 128);
    EXPECT_EQ(ws.camera.target, glm::vec3(0, 1, 0));
    EXPECT_EQ(ws.camera.yawDegrees, -10.0f);
    EXPECT_EQ(ws.camera.farPlane, 50.0f);

    // variables and their hints
    ASSERT_EQ(ws.variables.size(), 5u);
    const Variable& mode = *ws.findVariable("Mode");
    EXPECT_EQ(mode.widget, WidgetHint::Combo);  // implied by options
    EXPECT_EQ(mode.options, (std::vector<std::string>{"off", "soft", "hard"}));
    EXPECT_EQ(mode.value, Value::ofInt(1));
    EXPECT_EQ(mode.description, "how");
    const Variable& glow = *ws.findVariable("Glow");
    EXPECT_EQ(glow.value.type, ValueType::Color4);
    EXPECT_TRUE(glow.hdr);
    EXPECT_EQ(glow.widget, WidgetHint::Color);
    const Variable& offset = *ws.findVariable("Offset");
    EXPECT_EQ(offset.min, -1.0f);
    EXPECT_EQ(offset.max, 1.0f);
    EXPECT_EQ(offset.step, 0.1f);
    EXPECT_EQ(offset.widget, WidgetHint::Drag);
    EXPECT_EQ(ws.findVariable("On")->widget, WidgetHint::Checkbox);
    EXPECT_EQ(ws.findVariable("On")->value, Value::ofBool(false));
    EXPECT_EQ(ws.findVariable("M")->value.type, ValueType::Mat4);
    EXPECT_EQ(ws.findVariable("M")->where.line, 7);

    // textures
    ASSERT_EQ(ws.textures.size(), 3u);
    const Texture& noise = ws.textures[0];
    EXPECT_EQ(noise.kind, TextureKind::Texture2D);
    EXPECT_EQ(noise.colorSpace, ColorSpace::Srgb);
    EXPECT_FALSE(noise.mipmaps);
    EXPECT_EQ(noise.files, (std::vector<std::string>{"noise.png"}));
    const Texture& env = ws.textures[1];
    EXPECT_EQ(env.kind, TextureKind::Cube);
    EXPECT_EQ(env.layout, CubeLayout::Equirect);
    EXPECT_EQ(env.faceSize, 256);
    EXPECT_TRUE(env.mipmaps);
    const Texture& box = ws.textures[2];
    EXPECT_EQ(box.layout, CubeLayout::Faces);
    EXPECT_EQ(box.files, (std::vector<std::string>{"px.png", "nx.png", "py.png", "ny.png", "pz.png", "nz.png"}));
    ASSERT_EQ(box.fileLocations.size(), 6u);
    EXPECT_EQ(box.fileLocations[0].line, 12);  // +x
    EXPECT_EQ(box.fileLocations[5].line, 11);  // -z, given first

    // targets and their sizes
    ASSERT_EQ(ws.targets.size(), 3u);
    const RenderTarget& quarter = *ws.findTarget("quarter");
    EXPECT_EQ(quarter.format, TargetFormat::RGBA8);
    EXPECT_TRUE(quarter.size.relative);
    EXPECT_EQ(quarter.size.scaleX, 0.25);
    EXPECT_EQ(quarter.size.scaleY, 0.25);
    EXPECT_EQ(resolveTargetSize(quarter.size, {256, 128}), glm::ivec2(64, 32));
    const RenderTarget& wide = *ws.findTarget("wide");
    EXPECT_EQ(wide.format, TargetFormat::R11G11B10F);
    EXPECT_EQ(wide.size.scaleX, 0.5);
    EXPECT_EQ(wide.size.scaleY, 0.125);
    EXPECT_TRUE(wide.mipmaps);
    EXPECT_EQ(wide.initial, glm::vec4(0, 0, 0, 1));
    EXPECT_EQ(resolveTargetSize(wide.size, {5, 1}), glm::ivec2(3, 1));
    const RenderTarget& fixed = *ws.findTarget("fixed");
    EXPECT_FALSE(fixed.size.relative);
    EXPECT_EQ(resolveTargetSize(fixed.size, {1000, 1000}), glm::ivec2(64, 32));

    // passes
    ASSERT_EQ(ws.passes.size(), 3u);
    const Pass& geometry = ws.passes[0];
    EXPECT_FALSE(geometry.enabled);
    EXPECT_FALSE(geometry.clear.color);
    EXPECT_EQ(geometry.clear.depth, 0.5f);
    EXPECT_TRUE(geometry.blend.enabled);
    EXPECT_EQ(geometry.blend.srcColor, BlendFactor::SrcAlpha);
    EXPECT_EQ(geometry.blend.dstColor, BlendFactor::OneMinusSrcAlpha);
    EXPECT_EQ(geometry.blend.colorOp, BlendOp::ReverseSubtract);
    EXPECT_EQ(geometry.blend.srcAlpha, BlendFactor::SrcAlpha);  // defaults to the colour factor
    EXPECT_EQ(geometry.blend.dstAlpha, BlendFactor::One);
    EXPECT_EQ(geometry.blend.alphaOp, BlendOp::ReverseSubtract);
    EXPECT_EQ(geometry.blend.constant, glm::vec4(1, 0, 0, 1));
    EXPECT_TRUE(geometry.depth.test);
    EXPECT_FALSE(geometry.depth.write);
    EXPECT_EQ(geometry.depth.func, CompareFunc::GreaterEqual);
    EXPECT_EQ(geometry.raster.cull, CullFace::Front);
    EXPECT_FALSE(geometry.raster.frontCounterClockwise);
    EXPECT_FALSE(geometry.draw.mesh);
    EXPECT_EQ(geometry.draw.file, "models/rock.obj");
    EXPECT_EQ(geometry.draw.translate, glm::vec3(1, 2, 3));
    EXPECT_EQ(geometry.draw.rotateDegrees, glm::vec3(0, 90, 0));
    EXPECT_EQ(geometry.draw.scale, glm::vec3(2.0f));
    EXPECT_EQ(geometry.draw.where.line, 26);
    ASSERT_EQ(geometry.shaders.size(), 2u);
    EXPECT_EQ(geometry.shaders[0].stage, ShaderStage::Vertex);
    EXPECT_EQ(geometry.shaders[0].file, "rock.vert");
    EXPECT_EQ(geometry.shaders[1].stage, ShaderStage::Fragment);
    EXPECT_EQ(geometry.shaders[1].where.line, 28);
    ASSERT_EQ(geometry.constants.size(), 1u);
    EXPECT_EQ(geometry.constants[0].name, "Mode_Scale");
    EXPECT_EQ(geometry.constants[0].where.line, 29);

    const Pass& blend = ws.passes[1];
    EXPECT_TRUE(blend.blend.enabled);
    EXPECT_EQ(blend.blend.srcColor, BlendFactor::One);
    EXPECT_EQ(blend.blend.dstColor, BlendFactor::OneMinusSrcAlpha);
    EXPECT_EQ(blend.blend.dstAlpha, BlendFactor::OneMinusSrcAlpha);
    EXPECT_FALSE(blend.depth.test);
    EXPECT_FALSE(blend.depth.write);
    EXPECT_EQ(blend.draw.mesh, BuiltinMesh::Sphere);
    EXPECT_EQ(blend.draw.scale, glm::vec3(1, 2, 3));
    ASSERT_EQ(blend.samplers.size(), 2u);
    const Sampler& previous = blend.samplers[0];
    EXPECT_EQ(previous.target, "wide");
    EXPECT_TRUE(previous.previousFrame);
    EXPECT_EQ(previous.filter, Filter::Nearest);
    EXPECT_EQ(previous.mipmap, MipmapMode::Linear);
    EXPECT_EQ(previous.wrapS, Wrap::Repeat);
    EXPECT_EQ(previous.wrapT, Wrap::Border);
    EXPECT_EQ(previous.border, glm::vec4(1.0f));
    EXPECT_EQ(previous.where.line, 35);
    EXPECT_EQ(blend.samplers[1].texture, "noise");
    EXPECT_FALSE(blend.samplers[1].previousFrame);
    EXPECT_EQ(blend.samplers[1].wrapS, Wrap::Mirror);
    EXPECT_EQ(blend.samplers[1].wrapT, Wrap::Mirror);
    EXPECT_EQ(blend.shaders[0].code, "void main() {}");
    EXPECT_EQ(blend.shaders[0].codeLine, 37);

    const Pass& add = ws.passes[2];
    EXPECT_EQ(add.blend.srcColor, BlendFactor::One);
    EXPECT_EQ(add.blend.dstColor, BlendFactor::One);
    EXPECT_EQ(add.blend.colorOp, BlendOp::Add);
    EXPECT_EQ(add.raster.cull, CullFace::Back);  // <cull/> culls back faces
    EXPECT_TRUE(add.depth.test);
    EXPECT_TRUE(add.depth.write);  // write follows test unless given
    EXPECT_EQ(ws.passTargetName(add), "wide");

    EXPECT_EQ(ws.output.target, "wide");
    EXPECT_EQ(ws.output.transform, DisplayTransform::None);
    EXPECT_EQ(ws.output.where.line, 45);
}

TEST(WorkspaceParserModel, NameDefaultsToTheFileStem) {
    Workspace ws = parsedOk(workspace({"  <pass name=\"p\"/>"}));
    EXPECT_EQ(ws.name, "test");
    EXPECT_EQ(ws.width, 512);
    EXPECT_EQ(ws.passes[0].draw.mesh, BuiltinMesh::FullscreenTriangle);
}

TEST(WorkspaceParserModel, ResolveTargetSizeRoundsUp) {
    auto scaled = [](double sx, double sy) {
        TargetSize s;
        s.scaleX = sx;
        s.scaleY = sy;
        return s;
    };
    EXPECT_EQ(resolveTargetSize(scaled(0.25, 0.25), {256, 256}), glm::ivec2(64, 64));
    EXPECT_EQ(resolveTargetSize(scaled(0.5, 0.5), {5, 5}), glm::ivec2(3, 3));
    EXPECT_EQ(resolveTargetSize(scaled(0.125, 0.125), {1, 1}), glm::ivec2(1, 1));
    EXPECT_EQ(resolveTargetSize(scaled(1.0 / 3.0, 2.0), {300, 7}), glm::ivec2(100, 14));
    // 1/10 is not exact in binary; the product must still not round up past 64.
    EXPECT_EQ(resolveTargetSize(scaled(0.1, 0.1), {640, 641}), glm::ivec2(64, 65));
    TargetSize absolute;
    absolute.relative = false;
    absolute.width = 7;
    absolute.height = 9;
    EXPECT_EQ(resolveTargetSize(absolute, {1, 1}), glm::ivec2(7, 9));
}

}  // namespace
}  // namespace rmfx
