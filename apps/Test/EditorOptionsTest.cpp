#include "apps/EditorOptions.h"

#include <gtest/gtest.h>

namespace rmfx::apps {
namespace {

std::string rejection(const std::vector<std::string>& args) {
    std::string error;
    EXPECT_FALSE(parseEditorOptions(args, &error).has_value());
    return error;
}

}  // namespace

TEST(EditorOptions, EffectOfARenderMonkeyFile) {
    std::string error;
    auto o = parseEditorOptions({"--effect", "Group.Effect", "fx.rfx"}, &error);
    ASSERT_TRUE(o) << error;
    EXPECT_EQ(o->workspace, "fx.rfx");
    EXPECT_EQ(o->effect, "Group.Effect");
    EXPECT_EQ(rejection({"fx.rfx", "--effect"}), "--effect needs a value");
}

TEST(EditorOptions, ParsesEveryOption) {
    std::string error;
    auto o = parseEditorOptions({"fx.xml", "--size", "256x128", "--set", "Exposure_Level=2", "--set", "Tint=1 0 0",
                                 "--frames", "5", "--screenshot", "w.png", "--output-screenshot", "o.png", "--view", "scene", "--dt", "0.5", "--media", ".", "--sandbox",
                                 "--input", "scene=shot.exr", "--texture", "Sky=sky.hdr", "--split", "0.25", "--check"},
                                &error);
    ASSERT_TRUE(o) << error;
    EXPECT_EQ(o->workspace, "fx.xml");
    EXPECT_EQ(o->size, glm::ivec2(256, 128));
    ASSERT_EQ(o->overrides.size(), 2u);
    EXPECT_EQ(o->overrides[1], (std::pair<std::string, std::string>{"Tint", "1 0 0"}));
    EXPECT_EQ(o->frames, 5);
    EXPECT_EQ(o->screenshot, std::filesystem::path("w.png"));
    EXPECT_EQ(o->outputScreenshot, std::filesystem::path("o.png"));
    EXPECT_EQ(o->viewTargets, std::vector<std::string>{"scene"});
    EXPECT_EQ(o->deltaTime, 0.5f);
    EXPECT_EQ(o->media.searchPath, std::vector<std::filesystem::path>{"."});
    EXPECT_TRUE(o->media.sandbox);
    ASSERT_EQ(o->inputs.size(), 1u);
    EXPECT_EQ(o->inputs[0].name, "scene");
    EXPECT_EQ(o->inputs[0].file, std::filesystem::path("shot.exr"));
    ASSERT_EQ(o->textures.size(), 1u);
    EXPECT_EQ(o->textures[0].name, "Sky");
    EXPECT_EQ(o->split, 0.25f);
    EXPECT_TRUE(o->checkHealth);
    EXPECT_FALSE(parseEditorOptions({"fx.xml"}, &error)->checkHealth);
}

TEST(EditorOptions, RejectsWhatItCannotUse) {
    EXPECT_NE(rejection({}).find("which workspace"), std::string::npos);
    EXPECT_NE(rejection({"a.xml", "b.xml"}).find("one workspace"), std::string::npos);
    EXPECT_NE(rejection({"a.xml", "--size", "12"}).find("--size"), std::string::npos);
    EXPECT_NE(rejection({"a.xml", "--frames", "0"}).find("--frames"), std::string::npos);
    EXPECT_NE(rejection({"a.xml", "--set", "=3"}).find("NAME=VALUE"), std::string::npos);
    EXPECT_NE(rejection({"a.xml", "--screenshot", "x.png"}).find("--frames"), std::string::npos);
    EXPECT_NE(rejection({"a.xml", "--dt", "0.1"}).find("--frames"), std::string::npos);
    EXPECT_NE(rejection({"a.xml", "--frames", "2", "--dt", "-1"}).find("--dt"), std::string::npos);
    EXPECT_NE(rejection({"a.xml", "--bogus"}).find("'--bogus'"), std::string::npos);
    EXPECT_NE(rejection({"a.xml", "--size"}).find("needs a value"), std::string::npos);
    EXPECT_NE(rejection({"a.xml", "--media", "no/such/folder"}).find("--media"), std::string::npos);
    EXPECT_NE(rejection({"a.xml", "--input", "x.exr", "--split", "1.5"}).find("--split"), std::string::npos);
    EXPECT_NE(rejection({"a.xml", "--split", "0.5"}).find("--input"), std::string::npos);
    EXPECT_NE(rejection({"a.xml", "--texture", "Sky"}).find("--texture"), std::string::npos);
    EXPECT_NE(rejection({"a.xml", "--input", ""}).find("--input"), std::string::npos);
}

}  // namespace rmfx::apps
