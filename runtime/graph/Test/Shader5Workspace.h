#pragma once
// effects/shader_5.xml as the pass graph sees it, built in C++: its passes (targets, samplers,
// clears, blends, meshes), targets, <input>, effects and their switch variables with the file's
// values; no shaders, and every target rgba16f at the viewport's size (the pass graph reads
// neither). validation/Test/GraphTestWorkspacesTest checks it against the file.

#include <memory>
#include <string>

#include "graph/Test/WorkspaceBuilder.h"

namespace rmfx::test {

inline std::unique_ptr<Workspace> shader5Workspace() {
    WorkspaceBuilder b("shader_5.xml");
    b.variable("Exposure_Level", Value::ofFloat(0.25f))
        .variable("Environment_Format", Value::ofInt(0))
        .variable("Glow_Factor", Value::ofFloat(0.05f))
        .variable("Glow_Factor2", Value::ofFloat(0.05f))
        .variable("Glow_Factor3", Value::ofFloat(0.05f))
        .variable("Streak_Factor", Value::ofFloat(0.01f))
        .variable("Ghost_Factor", Value::ofFloat(0.3f))
        .texture("Sky_Alpha64")
        .texture("Sky_Float")
        .texture("Ghost_Mask")
        .target("scene")
        .input("scene", "scene");
    const std::vector<std::string> streaks{"streak_dl", "streak_dr", "streak_ul", "streak_ur"};
    for (int i = 1; i <= 6; ++i) b.target("glare_" + std::to_string(i));
    for (const std::string& s : streaks) b.target(s + "_4").target(s + "_16");
    b.target("ghost_1").target("ghost_2");

    b.effect({.name = "glare",
              .passes = {"glare_1", "glare_2", "glare_3", "glare_4", "glare_5", "glare_6"},
              .switches = {"Glow_Factor", "Glow_Factor2", "Glow_Factor3"}});
    EffectDeclaration streak{.name = "streak", .switches = {"Streak_Factor"}};
    for (const std::string& s : streaks) streak.passes.insert(streak.passes.end(), {s + "_4", s + "_16"});
    b.effect(streak).effect({.name = "ghost", .passes = {"ghost_1", "ghost_2"}, .switches = {"Ghost_Factor"}});

    const std::vector<Sampler> environment{textureSampler("Environment", "Sky_Alpha64"),
                                           textureSampler("Environment_Float", "Sky_Float")};
    b.pass("environment", "scene", {}, all({clearColor({0, 0, 0, 1}), clearDepth(1.0f)})).samplers(environment);
    b.pass("teapot", "scene", {}, all({depthTest(), drawMesh(BuiltinMesh::Teapot)})).samplers(environment);
    b.pass("scene_from_input", "scene").sampler(textureSampler("Input_Image", "scene"));
    b.pass("glare_1", "glare_1").sampler(targetSampler("Texture0", "scene"));
    for (int i = 2; i <= 6; ++i)
        b.pass("glare_" + std::to_string(i), "glare_" + std::to_string(i))
            .sampler(targetSampler("Texture0", "glare_" + std::to_string(i - 1)));
    for (const std::string& s : streaks) {
        b.pass(s + "_4", s + "_4").sampler(targetSampler("Texture0", "scene"));
        b.pass(s + "_16", s + "_16").sampler(targetSampler("Texture0", s + "_4"));
    }
    b.pass("ghost_1", "ghost_1").samplers({targetSampler("Texture0", "scene"), textureSampler("Texture1", "Ghost_Mask")});
    b.pass("ghost_2", "ghost_2").samplers({targetSampler("Texture0", "ghost_1"), textureSampler("Texture1", "Ghost_Mask")});
    b.pass("screen", "").sampler(targetSampler("Texture0", "scene"));
    // <blend mode="custom" src="src-alpha" dst="one" src-alpha="zero" dst-alpha="one"/>
    b.pass("combine", "", {}, [](Pass& p) {
        p.blend.enabled = true;
        p.blend.srcColor = BlendFactor::SrcAlpha;
        p.blend.dstColor = BlendFactor::One;
        p.blend.srcAlpha = BlendFactor::Zero;
        p.blend.dstAlpha = BlendFactor::One;
    });
    const std::vector<std::string> combined{"ghost_2",      "glare_4",      "glare_5",      "glare_6",
                                            "streak_dl_16", "streak_dr_16", "streak_ul_16", "streak_ur_16"};
    for (size_t i = 0; i < combined.size(); ++i) b.sampler(targetSampler("Texture" + std::to_string(i), combined[i]));
    b.workspace().output.format = TargetFormat::RGBA32F;
    return b.build();
}

}  // namespace rmfx::test
