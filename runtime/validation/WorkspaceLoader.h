#pragma once
// Parse + validate in one step: what every front end (CLI, editor, tests) does before GL.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/Diagnostic.h"
#include "core/Result.h"
#include "io/media/MediaResolver.h"
#include "model/Workspace.h"
#include "validation/TextureArguments.h"
#include "validation/Validation.h"

namespace rmfx {

// How a file becomes a workspace, beyond validation.
struct WorkspaceLoadOptions {
    // RenderMonkey (.rfx) files: the effect to import (dotted path or name); empty: the active one.
    // An rmfx workspace holds one effect graph, so a non-empty choice is an error for it.
    std::string effect;
    // How the workspace's file references resolve (search path, sandbox), before validation.
    MediaOptions media{};
    // rmfx render --texture NAME=FILE: files put in place of the textures' own before they are
    // resolved, so that a texture whose file is missing (an old .rfx) can be given one.
    std::vector<TextureArgument> textures;
    // RenderMonkey (.rfx) Direct3D effects: the matrix order their HLSL is given, in place of the
    // one the saving RenderMonkey's version implies (--rfx-matrices).
    std::optional<HlslMatrixOrder> rfxMatrices{};
};

// Dispatches on the extension: .rfx (any case) to the RenderMonkey importer, else the XML format.
// The workspace when parsing and validation found no error; the diagnostics (errors and
// warnings) are in file order per stage. With `handOver`, validation's programs go there
// (CheckedPrograms), for the compile step.
Result<Workspace> loadWorkspace(const std::filesystem::path& path, const ValidationOptions& options = {},
                                const WorkspaceLoadOptions& load = {}, CheckedPrograms* handOver = nullptr);
// The built-in default workspace; its relative paths resolve in the current folder. `textures`
// as WorkspaceLoadOptions::textures.
Result<Workspace> loadDefaultWorkspace(const ValidationOptions& options = {}, const MediaOptions& media = {},
                                       const std::vector<TextureArgument>& textures = {}, CheckedPrograms* handOver = nullptr);

// Applies NAME=VALUE overrides to the workspace's variable defaults, checking names and types.
// Each problem is an error naming the variable.
Result<void> applyOverrides(Workspace& ws, const std::vector<std::pair<std::string, std::string>>& overrides);

}  // namespace rmfx
