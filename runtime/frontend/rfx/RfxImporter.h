#pragma once
// Front end for RenderMonkey workspaces (.rfx): one effect of the file → the same Workspace the
// XML front end produces. FILE_NAMEs (textures, models) are kept exactly as written; resolving
// Windows paths is the media resolver's job.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/Diagnostic.h"
#include "core/Result.h"
#include "frontend/workspace/WorkspaceParser.h"

namespace rmfx {

struct RfxImportOptions {
    // The effect to import: a dotted path ("Effect Workspace.Group.Effect", or without the
    // workspace's name "Group.Effect"), or a name only one effect has. Empty: ACTIVE_EFFECT.
    std::string effect;
    // How the Direct3D effect's HLSL multiplies the matrices rmfx fills by semantic; unset: by the
    // RenderMonkey that saved the file (docs/rendermonkey.md), which a file written for the other
    // order contradicts (rmfx render --rfx-matrices).
    std::optional<HlslMatrixOrder> hlslMatrices{};
};

Result<Workspace> importRfxFile(const std::filesystem::path& path, const RfxImportOptions& options = {});
// `path` names the text in diagnostics; `folder` is where relative file references resolve.
Result<Workspace> importRfxText(const std::string& text, const std::filesystem::path& path,
                                const std::filesystem::path& folder, const RfxImportOptions& options = {});

struct RfxEffectSummary {
    std::string path;  // dotted path, what --effect takes
    std::string api;   // "OpenGL", "OpenGL ES", "Direct3D 9"
    bool active = false;
    int line = 0;
};

Result<std::vector<RfxEffectSummary>> listRfxEffects(const std::filesystem::path& path);

// Whether the path names a RenderMonkey file: extension .rfx in any case.
bool isRfxPath(const std::filesystem::path& path);

}  // namespace rmfx
