// The graph layer's tests build effects/shader_5.xml and effects/hdr_lighting.xml in C++
// (graph/Test/Shader5Workspace.h, HdrLightingWorkspace.h) so that they link no parser: here each is
// compared with the file as rmfx loads it, in what the pass graph and content skip read: the
// passes' targets, samplers, clears, blends, depth and meshes, the targets and inputs, the effects
// and their switch variables' values.

#include <sstream>

#include <gtest/gtest.h>

#include "graph/Test/HdrLightingWorkspace.h"
#include "graph/Test/Shader5Workspace.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx {
namespace {

std::string names(const std::vector<std::string>& list) {
    std::string out;
    for (const std::string& name : list) out += (out.empty() ? "" : " ") + name;
    return out;
}

std::string channels(glm::bvec4 c) {
    std::string out;
    for (int i = 0; i < 4; ++i)
        if (c[i]) out += "rgba"[i];
    return out;
}

// One line for each thing the graph reads, in the workspace's order.
std::string graphShape(const Workspace& ws) {
    std::ostringstream out;
    for (const RenderTarget& t : ws.targets) out << "target " << t.name << "\n";
    for (const ImageInput& in : ws.inputs) out << "input " << in.name << " replaces '" << in.replaces << "'\n";
    for (const Texture& t : ws.textures) out << "texture " << t.name << (t.files.empty() ? " without a file" : "") << "\n";
    for (const Effect& e : ws.effects) {
        out << "effect " << e.name << " passes " << names(e.passes) << " switches " << names(e.switches);
        if (!e.source.empty()) out << " source " << e.source << "." << channels(e.sourceChannels);
        if (!e.gate.empty()) out << " gate " << e.gate << "." << channels(e.gateChannels);
        out << "\n";
        for (const std::string& s : e.switches)
            if (const Variable* v = ws.findVariable(s)) out << "  switch " << s << " = " << formatValue(v->value) << "\n";
    }
    for (const Pass& p : ws.passes) {
        out << "pass " << p.name << " → '" << p.target << "'" << (p.enabled ? "" : " disabled");
        if (p.blend.enabled)
            out << " blend " << static_cast<int>(p.blend.srcColor) << " " << static_cast<int>(p.blend.dstColor) << " "
                << static_cast<int>(p.blend.srcAlpha) << " " << static_cast<int>(p.blend.dstAlpha);
        if (p.clear.color) out << " clears colour";
        if (p.clear.depth) out << " clears depth";
        if (p.depth.test || p.depth.write)
            out << " depth test " << p.depth.test << " write " << p.depth.write << " func " << static_cast<int>(p.depth.func);
        if (p.draw.mesh) out << " mesh " << static_cast<int>(*p.draw.mesh);
        if (!p.draw.file.empty()) out << " model " << p.draw.file;
        out << "\n";
        for (const Sampler& s : p.samplers)
            out << "  sampler " << s.uniform << (s.target.empty() ? " texture " + s.texture : " target " + s.target)
                << (s.previousFrame ? " (previous frame)" : "") << "\n";
    }
    out << "output format " << targetFormatName(ws.output.format) << "\n";
    return out.str();
}

// The textures are left out of the comparison where the graph only needs the names it samples.
std::string withoutFileTextures(const std::string& shape) {
    std::istringstream in(shape);
    std::string out, line;
    while (std::getline(in, line))
        if (line.rfind("texture ", 0) != 0 || line.find("without a file") != std::string::npos) out += line + "\n";
    return out;
}

Workspace load(const char* file) {
    Result<Workspace> loaded = loadWorkspace(test::sourceDir() / "effects" / file, {false});
    EXPECT_TRUE(loaded.ok()) << formatAll(loaded.diagnostics());
    return loaded.ok() ? std::move(*loaded) : Workspace{};
}

TEST(GraphTestWorkspaces, Shader5IsTheFileAsThePassGraphSeesIt) {
    EXPECT_EQ(withoutFileTextures(graphShape(*test::shader5Workspace())), withoutFileTextures(graphShape(load("shader_5.xml"))));
}

TEST(GraphTestWorkspaces, HdrLightingIsTheFileAsThePassGraphSeesIt) {
    EXPECT_EQ(withoutFileTextures(graphShape(*test::hdrLightingWorkspace())),
              withoutFileTextures(graphShape(load("hdr_lighting.xml"))));
}

}  // namespace
}  // namespace rmfx
