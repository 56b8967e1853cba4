#include "frontend/workspace/WorkspaceDependencies.h"

#include <algorithm>

#include "frontend/shader/ShaderPreprocessor.h"

namespace rmfx {
namespace {

class Collector {
public:
    WorkspaceDependencies out;

    FileDependency& add(const std::filesystem::path& file, DependencyKind kind) {
        std::filesystem::path key = dependencyPath(file);
        for (FileDependency& d : out.files) {
            if (d.file != key) continue;
            if (kind == DependencyKind::Shader && d.kind == DependencyKind::Include) d.kind = kind;
            return d;
        }
        out.files.push_back({key, kind, {}, {}});
        return out.files.back();
    }

    static void addName(std::vector<std::string>& names, const std::string& name) {
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }

    // The shader file and, through the preprocessor, every file it includes (as the executor
    // would read them: same folders, snippets and root).
    void addShader(const Workspace& ws, const Pass& pass, const ShaderSource& shader) {
        if (shader.file.empty()) {
            addIncludes(ws, pass, shader.code, {ws.path.string(), shader.codeLine}, ws.folder);
            return;
        }
        std::filesystem::path file = ws.folder / shader.file;
        addName(add(file, DependencyKind::Shader).passes, pass.name);
        std::optional<std::string> text = readShaderFile(file);
        if (!text) return;
        addIncludes(ws, pass, *text, {file.lexically_normal().string(), 1}, file.parent_path());
    }

    void addIncludes(const Workspace& ws, const Pass& pass, const std::string& code, const SourceLocation& start,
                     const std::filesystem::path& folder) {
        ShaderInput input;
        input.code = code;
        input.start = start;
        input.folder = folder;
        input.root = ws.includeFolder();
        input.snippets = &ws.snippets;
        Diagnostics ignored;  // validation and the executor report them
        PreprocessedShader shader = preprocessShader(input, ignored);
        for (const auto& included : shader.files) addName(add(included, DependencyKind::Include).passes, pass.name);
    }
};

}  // namespace

const char* dependencyKindName(DependencyKind kind) {
    switch (kind) {
        case DependencyKind::Workspace: return "workspace";
        case DependencyKind::Shader: return "shader";
        case DependencyKind::Include: return "include";
        case DependencyKind::Texture: return "texture";
        case DependencyKind::Model: return "model";
    }
    return "?";
}

std::filesystem::path dependencyPath(const std::filesystem::path& file) {
    std::error_code error;
    std::filesystem::path absolute = std::filesystem::absolute(file, error);
    if (error) absolute = file;
    std::filesystem::path canonical = std::filesystem::weakly_canonical(absolute, error);
    return error ? absolute.lexically_normal() : canonical;
}

const FileDependency* WorkspaceDependencies::find(const std::filesystem::path& file) const {
    std::filesystem::path key = dependencyPath(file);
    for (const FileDependency& d : files)
        if (d.file == key) return &d;
    return nullptr;
}

std::vector<std::filesystem::path> WorkspaceDependencies::paths() const {
    std::vector<std::filesystem::path> out;
    for (const FileDependency& d : files) out.push_back(d.file);
    return out;
}

WorkspaceDependencies findWorkspaceDependencies(const Workspace& ws) {
    Collector c;
    c.add(ws.path, DependencyKind::Workspace);
    for (const Pass& pass : ws.passes) {
        if (!pass.enabled) continue;
        for (const ShaderSource& shader : pass.shaders) c.addShader(ws, pass, shader);
    }
    for (const Texture& texture : ws.textures)
        for (const std::string& file : texture.files)
            Collector::addName(c.add(ws.folder / file, DependencyKind::Texture).textures, texture.name);
    for (const Pass& pass : ws.passes)
        if (pass.enabled && !pass.draw.mesh && !pass.draw.file.empty())
            Collector::addName(c.add(ws.folder / pass.draw.file, DependencyKind::Model).passes, pass.name);
    return c.out;
}

}  // namespace rmfx
