#pragma once
// effects/hdr_lighting.xml as the pass graph and content skip see it, built in C++: its passes
// (targets, samplers, clears, depth, meshes), targets, <input>, the bloom and star effects with
// their sources, gate and switch variables (the file's values); no shaders, no other variables,
// and every target rgba16f at the viewport's size (the pass plan reads neither).
// validation/Test/GraphTestWorkspacesTest checks it against the file.

#include <memory>
#include <string>

#include "graph/Test/WorkspaceBuilder.h"

namespace rmfx::test {

inline std::unique_ptr<Workspace> hdrLightingWorkspace() {
    WorkspaceBuilder b("hdr_lighting.xml");
    b.variable("Star_Scale", Value::ofFloat(0.5f)).variable("Bloom_Scale", Value::ofFloat(1.0f));
    b.target("scene").input("scene", "scene");
    b.targets({"quarter", "lum64", "lum16", "lum4", "measured", "adapted", "glare_gate", "bright", "star_source",
               "bloom_source", "bloom_blur", "bloom_h", "bloom", "star_work_a", "star_work_b"});
    for (int line = 0; line < 8; ++line) b.target("star_line" + std::to_string(line));
    b.target("star");

    const glm::bvec4 red{true, false, false, false};
    b.effect({.name = "bloom",
              .passes = {"bloom_source", "bloom_blur", "bloom_horizontal", "bloom_vertical"},
              .switches = {"Bloom_Scale"},
              .source = "bright",
              .gate = "glare_gate",
              .gateChannels = red});
    EffectDeclaration star{.name = "star", .switches = {"Star_Scale"}, .source = "bright", .gate = "glare_gate", .gateChannels = red};
    for (int line = 0; line < 8; ++line)
        for (int step = 0; step < 3; ++step) star.passes.push_back("star" + std::to_string(line) + "_" + std::to_string(step));
    star.passes.push_back("star_merge");
    b.effect(star);

    // The scene: floor, walls, teapot, two light spheres and a panel, depth-tested meshes.
    b.pass("floor", "scene", {},
           all({clearColor({0, 0, 0, 0}), clearDepth(1.0f), depthTest(), drawMesh(BuiltinMesh::Plane)}));
    for (const char* wall : {"back_wall", "left_wall"}) b.pass(wall, "scene", {}, all({depthTest(), drawMesh(BuiltinMesh::Plane)}));
    b.pass("teapot", "scene", {}, all({depthTest(), drawMesh(BuiltinMesh::Teapot)}));
    for (const char* light : {"light0", "light1"}) b.pass(light, "scene", {}, all({depthTest(), drawMesh(BuiltinMesh::Sphere)}));
    b.pass("panel", "scene", {}, all({depthTest(), drawMesh(BuiltinMesh::Plane), [](Pass& p) { p.depth.func = CompareFunc::LessEqual; }}));
    b.pass("scene_from_input", "scene").sampler(textureSampler("Input_Image", "scene"));

    // Luminance down to 1x1, adapted over frames; the glare's gate and sources.
    b.pass("scene_to_quarter", "quarter").sampler(targetSampler("Source", "scene"));
    b.pass("luminance64", "lum64").samplers({targetSampler("Quarter", "quarter"), targetSampler("Scene", "scene")});
    b.pass("luminance16", "lum16").samplers({targetSampler("Finer", "lum64"), targetSampler("Quarter", "quarter")});
    b.pass("luminance4", "lum4").samplers({targetSampler("Finer", "lum16"), targetSampler("Quarter", "quarter")});
    b.pass("luminance1", "measured").samplers({targetSampler("Finer", "lum4"), targetSampler("Quarter", "quarter")});
    b.pass("adaptation", "adapted")
        .samplers({targetSampler("Adapted_Previous", "adapted", true), targetSampler("Measured", "measured")});
    b.pass("glare_gate", "glare_gate").samplers({targetSampler("Measured", "measured"), targetSampler("Adapted", "adapted")});
    b.pass("bright_pass", "bright").samplers({targetSampler("Quarter", "quarter"), targetSampler("Adapted", "adapted")});
    b.pass("star_source", "star_source").sampler(targetSampler("Source", "bright"));

    // Bloom: down to 1/8, blurred; star: 8 lines of 3 passes, merged.
    b.pass("bloom_source", "bloom_source").sampler(targetSampler("Source", "star_source"));
    b.pass("bloom_blur", "bloom_blur").sampler(targetSampler("Source", "bloom_source"));
    b.pass("bloom_horizontal", "bloom_h").sampler(targetSampler("Source", "bloom_blur"));
    b.pass("bloom_vertical", "bloom").sampler(targetSampler("Source", "bloom_h"));
    for (int line = 0; line < 8; ++line) {
        const std::string name = "star" + std::to_string(line) + "_";
        b.pass(name + "0", "star_work_a").sampler(targetSampler("Star_Input", "star_source"));
        b.pass(name + "1", "star_work_b").sampler(targetSampler("Star_Input", "star_work_a"));
        b.pass(name + "2", "star_line" + std::to_string(line)).sampler(targetSampler("Star_Input", "star_work_b"));
    }
    b.pass("star_merge", "star");
    for (int line = 0; line < 8; ++line)
        b.sampler(targetSampler("Star_Line_" + std::to_string(line), "star_line" + std::to_string(line)));

    b.pass("final", "").samplers({targetSampler("Scene", "scene"), targetSampler("Bloom", "bloom"), targetSampler("Star", "star"),
                                  targetSampler("Adapted", "adapted"), targetSampler("Measured", "measured")});
    return b.build();
}

}  // namespace rmfx::test
