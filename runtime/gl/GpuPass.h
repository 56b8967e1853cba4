#pragma once
// A pass ready to draw: its linked program, target, mesh, vertex streams, and the uniforms and
// samplers found in the program with where each takes its value from.

#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "gl/GlHandles.h"
#include "gl/GlMesh.h"
#include "gl/GlRenderTargets.h"
#include "gl/HealthInstrumentation.h"
#include "graph/UniformBinding.h"
#include "model/Workspace.h"

namespace rmfx {

struct UniformSlot {
    int location = -1;
    std::string name;
    UniformType type = UniformType::Other;
    UniformSource source;
    std::string effectSwitch;  // rmfx_effect_<name>: whether that effect runs this frame
    const Value* value = nullptr;  // a pass constant's, or the variable's current value
    std::optional<SemanticInfo> semantic;  // filled every frame (Variable::semantic)
    // A matrix fed by a semantic to an HLSL program that multiplies as mul(M, v)
    // (HlslMatrixOrder::ColumnVector): uploaded transposed. HLSL's m[r] is rmfx's column r
    // (HlslTranslator.h), so untransposed, mul(v, M) is M·v; transposed, mul(M, v) is.
    bool transposed = false;
    // What the program's uniform holds now, as uploaded last (ints by their bits): uploadUniforms
    // makes no GL call for a value it already holds.
    mutable std::array<float, 16> uploaded{};
    mutable bool hasUploaded = false;
};

struct SamplerSlot {
    int unit = 0;
    SamplerHandle samplerObject;
    const Sampler* sampler = nullptr;
    unsigned texture = 0;              // for textures (owned by the texture cache)
    GpuTarget* target = nullptr;       // for targets
};

struct GpuPass {
    const Pass* pass = nullptr;
    int index = 0;  // in Workspace::passes
    ProgramHandle program;
    GpuTarget* target = nullptr;
    const GlMesh* mesh = nullptr;
    glm::mat4 model{1.0f};
    std::vector<StreamBinding> streams;  // Pass::streams against the program; empty: rmfx's layout
    std::vector<UniformSlot> uniforms;
    std::vector<SamplerSlot> samplers;
    std::set<std::string> initializedUniforms;  // declared with a value: unbound, they keep it
    // With --check, where the program counts what the pass writes (gl/HealthInstrumentation.h):
    // the uniforms it added, and the samplers whose texels it records, in its order.
    HealthUniforms health;
    std::vector<std::string> healthInputs;
    std::string whyNotCounting;  // where the check asked for counting and the pass cannot
};

}  // namespace rmfx
