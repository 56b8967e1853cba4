#pragma once
// Workspaces for the graph layer's tests, built from the model's types as the XML front end builds
// them (frontend/workspace/WorkspaceParser), so that these tests link no parser and no shader
// compiler. The graph reads a pass's target, samplers, clear, blend, depth and draw, never its
// shaders, so a pass here has none. Each declaration takes the next line of the file the workspace
// is named after (the <workspace> element is line 1), as if written one to a line: a diagnostic
// names the line of the sampler or target it is about.

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/Value.h"
#include "model/Workspace.h"

namespace rmfx::test {

using PassSetup = std::function<void(Pass&)>;

// Set-ups for WorkspaceBuilder::pass, as the pass elements <blend>, <clear>, <draw> and <depth> set it.
inline PassSetup additiveBlend() {  // <blend mode="add"/>
    return [](Pass& p) {
        p.blend.enabled = true;
        p.blend.srcColor = p.blend.dstColor = p.blend.srcAlpha = p.blend.dstAlpha = BlendFactor::One;
    };
}
inline PassSetup clearColor(glm::vec4 color) {  // <clear color="…"/>
    return [color](Pass& p) { p.clear.color = color; };
}
inline PassSetup clearDepth(float depth) {  // <clear depth="…"/>
    return [depth](Pass& p) { p.clear.depth = depth; };
}
inline PassSetup drawMesh(BuiltinMesh mesh) {  // <draw mesh="…"/>
    return [mesh](Pass& p) { p.draw.mesh = mesh; };
}
inline PassSetup depthTest() {  // <depth test="less" write="true"/>
    return [](Pass& p) { p.depth = {true, true, CompareFunc::Less}; };
}
inline PassSetup disabled() {  // enabled="false"
    return [](Pass& p) { p.enabled = false; };
}
// Several set-ups, in order.
inline PassSetup all(std::vector<PassSetup> setups) {
    return [setups = std::move(setups)](Pass& p) {
        for (const PassSetup& setup : setups) setup(p);
    };
}

// <sampler name="UNIFORM" target="TARGET" [frame="previous"]/> and <sampler name="UNIFORM" texture="TEXTURE"/>.
inline Sampler targetSampler(const std::string& uniform, const std::string& target, bool previousFrame = false) {
    Sampler s;
    s.uniform = uniform;
    s.target = target;
    s.previousFrame = previousFrame;
    return s;
}
inline Sampler textureSampler(const std::string& uniform, const std::string& texture) {
    Sampler s;
    s.uniform = uniform;
    s.texture = texture;
    return s;
}

// A target size of `width`×`height` pixels, whatever the viewport (<target size="WxH">).
inline TargetSize fixedSize(int width, int height) { return {false, 1.0, 1.0, width, height}; }

// An <effect>: what the graph reads of one (a designated initializer may leave out any of it).
struct EffectDeclaration {
    std::string name = {};
    std::vector<std::string> passes = {};
    std::vector<std::string> switches = {};
    std::string source = {};  // counted in red, green and blue
    std::string gate = {};
    glm::bvec4 gateChannels{true, true, true, false};
};

class WorkspaceBuilder {
public:
    // An 8x8 workspace named after its file.
    explicit WorkspaceBuilder(const std::string& file) {
        ws_->path = file;
        ws_->folder = ".";
        ws_->name = std::filesystem::path(file).stem().string();
        ws_->width = ws_->height = 8;
        ws_->output.where = next();
    }

    WorkspaceBuilder& target(const std::string& name, TargetFormat format = TargetFormat::RGBA16F,
                             TargetSize size = {}) {
        RenderTarget t;
        t.name = name;
        t.format = format;
        t.size = size;
        t.where = next();
        ws_->targets.push_back(std::move(t));
        return *this;
    }
    WorkspaceBuilder& targets(const std::vector<std::string>& names) {
        for (const std::string& name : names) target(name);
        return *this;
    }

    WorkspaceBuilder& variable(const std::string& name, Value value) {
        Variable v;
        v.name = name;
        v.value = std::move(value);
        v.where = next();
        ws_->variables.push_back(std::move(v));
        return *this;
    }

    // A 2D texture read from a file, which the graph never opens.
    WorkspaceBuilder& texture(const std::string& name) {
        Texture t;
        t.name = name;
        t.files = {name + ".png"};
        t.where = next();
        ws_->textures.push_back(std::move(t));
        return *this;
    }

    // <input name="NAME" [replaces="TARGET"]/>: the input and the texture of its name, with no file.
    WorkspaceBuilder& input(const std::string& name, const std::string& replaces = "") {
        ImageInput in;
        in.name = name;
        in.replaces = replaces;
        in.sizesViewport = !replaces.empty();
        in.where = next();
        Texture t;
        t.name = name;
        t.where = in.where;
        ws_->inputs.push_back(std::move(in));
        ws_->textures.push_back(std::move(t));
        return *this;
    }

    WorkspaceBuilder& effect(const EffectDeclaration& declared) {
        Effect e;
        e.name = declared.name;
        e.passes = declared.passes;
        e.switches = declared.switches;
        e.source = declared.source;
        e.gate = declared.gate;
        e.gateChannels = declared.gateChannels;
        e.where = next();
        ws_->effects.push_back(std::move(e));
        return *this;
    }

    // A pass drawing the full-screen triangle into `target` ("": the output) and sampling each of
    // `reads` through samplers s0, s1, …; "t'" reads last frame's t (frame="previous"). `setup`
    // then sets what else the pass declares.
    WorkspaceBuilder& pass(const std::string& name, const std::string& target, const std::vector<std::string>& reads = {},
                           const PassSetup& setup = {}) {
        Pass p;
        p.name = name;
        p.target = target;
        p.where = next();
        p.draw.mesh = BuiltinMesh::FullscreenTriangle;
        p.draw.where = p.where;
        if (setup) setup(p);
        ws_->passes.push_back(std::move(p));
        for (size_t i = 0; i < reads.size(); ++i) {
            std::string read = reads[i];
            const bool previous = !read.empty() && read.back() == '\'';
            if (previous) read.pop_back();
            sampler(targetSampler("s" + std::to_string(i), read, previous));
        }
        return *this;
    }

    // More samplers of the last pass (a texture's, or a target's under a name of its own).
    WorkspaceBuilder& sampler(Sampler s) {
        s.where = next();
        ws_->passes.back().samplers.push_back(std::move(s));
        return *this;
    }

    WorkspaceBuilder& samplers(const std::vector<Sampler>& list) {
        for (const Sampler& s : list) sampler(s);
        return *this;
    }

    Workspace& workspace() { return *ws_; }
    std::unique_ptr<Workspace> build() { return std::move(ws_); }

private:
    SourceLocation next() { return {ws_->path.string(), ++line_}; }

    std::unique_ptr<Workspace> ws_ = std::make_unique<Workspace>();
    int line_ = 0;
};

}  // namespace rmfx::test
