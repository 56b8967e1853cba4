#pragma once
// Binds a linked pass program to the workspace: its vertex streams to the mesh's attributes, its
// uniforms to variables, constants, semantics and effect switches, its samplers to textures and
// targets (each with a sampler object of the <sampler>'s filter and wrap). Needs a current GL context.

#include <map>
#include <string>

#include "core/Result.h"
#include "gl/GlRenderTargets.h"
#include "gl/GlTextureCache.h"
#include "gl/GpuPass.h"
#include "graph/FramePlan.h"

namespace rmfx {

// Pass::streams against the linked program: a named attribute by its location, an empty one to
// its compatibility built-in. A stream the program does not read is a warning, then skipped.
Result<void> bindStreams(GpuPass& pass, bool compatibilityProfile);

struct UniformSources {
    const Workspace& ws;
    const FramePlan& plan;
    const GlTextureCache& textures;
    const GlRenderTargets& targets;
    const std::map<std::string, Value>& values;  // slots point to these: they must stay put
};

// Fills the pass's uniform and sampler slots; errors for uniforms whose type does not match what
// they are bound to, and for samplers of targets that have no memory.
Result<void> bindUniforms(GpuPass& pass, const UniformSources& sources);

}  // namespace rmfx
