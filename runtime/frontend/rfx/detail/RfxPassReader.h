#pragma once
// One RenderMonkey pass (RmGLPass, RmGLESPass, RmPass) → an rmfx Pass.

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
};

// Shaders are left empty when the pass has none (the importer gives it the previous pass's).
// HLSL shaders get `hlslMatrices` (rfx::hlslMatrixOrderOf); assembly ones are always ColumnVector.
std::optional<ReadPass> readPass(const RfxElement& e, RfxApi api, const VisibleScopes& scopes, HlslMatrixOrder hlslMatrices);

}  // namespace rmfx::rfx
