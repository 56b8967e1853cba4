#pragma once
// One RenderMonkey pass (RmGLPass, RmGLESPass, RmPass) → an rmfx Pass.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "frontend/rfx/detail/RfxDeclarations.h"
#include "frontend/rfx/detail/RfxEffectCatalogue.h"
#include "frontend/rfx/detail/RfxElement.h"
#include "model/Workspace.h"

namespace rmfx::rfx {

// What a pass can see: the declarations of its effect, group and workspace, innermost first.
struct VisibleScopes {
    std::vector<const Declarations*> levels;  // effect, group (if any), workspace

    const Variable* variable(const std::string& name) const;
    const Texture* texture(const std::string& name) const;
    const RenderTarget* target(const std::string& name) const;
    const StreamMapDeclaration* streamMap(const std::string& name) const;
    const ModelDeclaration* model(const std::string& name) const;
    const UnsupportedDeclaration* unsupported(const std::string& name) const;
};

struct ReadPass {
    Pass pass;
    int index = 0;        // PASS_INDEX
    bool runnable = true; // false: a shader rmfx cannot compile (assembly)
    std::string whyNotRunnable;
    // Its RmRenderStateBlocks, applied by the importer in run order: states carry over from the
    // pass before (rfx::applyRenderStateBlock).
    std::vector<const tinyxml2::XMLElement*> stateBlocks;
    // Texture variables, renderable textures, models and stream maps declared inside the pass
    // (RenderMonkey allowed it): the pass sees them first; the importer adds the textures and
    // targets to the workspace.
    Declarations declared;
    // Direct3D binds textures to sampler stages, not to names, and a binding stays on the device
    // from one pass to the next. The importer, which runs the passes in order, binds each sampler
    // that has no texture object of its name to what its stage holds.
    std::map<int, Sampler> stageObjects;  // d3dSamplerStage → the texture object this pass binds there
    struct SamplerWithoutObject {
        std::string name;
        std::optional<int> stage;  // d3dSamplerStage of its REGISTER; none without one
        const tinyxml2::XMLElement* element = nullptr;
        bool used = false;  // whether a shader of the pass names it
    };
    std::vector<SamplerWithoutObject> samplersWithoutObject;
};

// Direct3D's sampler stage: a pixel sampler's register, or D3DVERTEXTEXTURESAMPLER0 (257) plus a
// vertex texture sampler's register.
constexpr int d3dSamplerStage(int index, bool vertexTexture) { return vertexTexture ? 257 + index : index; }

// Shaders are left empty when the pass has none (the importer gives it the previous pass's).
// HLSL shaders get their own order from `shaderOrders` (rfx::shaderMatrixOrders), else
// `hlslMatrices` (rfx::hlslMatrixOrderOf); assembly ones are always ColumnVector.
std::optional<ReadPass> readPass(const RfxElement& e, RfxApi api, const VisibleScopes& scopes, HlslMatrixOrder hlslMatrices,
                                 const std::map<const tinyxml2::XMLElement*, HlslMatrixOrder>& shaderOrders = {});

}  // namespace rmfx::rfx
