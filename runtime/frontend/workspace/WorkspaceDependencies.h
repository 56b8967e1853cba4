#pragma once
// Every file a workspace depends on, and what each one feeds: what hot reload watches, and what
// it rebuilds when one of them changes. Reads the shader files to follow their #includes; no GL.

#include <filesystem>
#include <string>
#include <vector>

#include "model/Workspace.h"

namespace rmfx {

enum class DependencyKind {
    Workspace,  // the workspace file itself (its inline shaders and code snippets included)
    Shader,     // a pass's shader file
    Include,    // a file a shader #includes (directly or through other includes)
    Texture,    // an image file of a texture or cube map
    Model,      // a model file a pass draws
};

const char* dependencyKindName(DependencyKind kind);

struct FileDependency {
    std::filesystem::path file;  // absolute and normalised (symbolic links resolved)
    DependencyKind kind = DependencyKind::Workspace;
    std::vector<std::string> passes;    // Shader, Include, Model: the enabled passes that use it, in workspace order
    std::vector<std::string> textures;  // Texture: the textures made from it
};

struct WorkspaceDependencies {
    std::vector<FileDependency> files;  // the workspace file first, then in declaration order; each file once

    // The entry for a file, however the path is spelt; null when the workspace does not use it.
    const FileDependency* find(const std::filesystem::path& file) const;
    std::vector<std::filesystem::path> paths() const;
};

// The same spelling for every path to one file: absolute, normalised, symbolic links resolved
// as far as the path exists.
std::filesystem::path dependencyPath(const std::filesystem::path& file);

// A file that is a pass's shader and another's include is a Shader. Files that do not exist (a
// missing shader or image) are listed too, so that their appearance can be noticed; includes that
// cannot be found are not (their path is unknown).
WorkspaceDependencies findWorkspaceDependencies(const Workspace& ws);

}  // namespace rmfx
