#pragma once
// What one level of a RenderMonkey workspace (the workspace, a group, an effect or a pass)
// declares: variables, textures, renderable textures, stream maps and models. Inner levels
// shadow outer ones by name.

#include <string>
#include <vector>

#include "frontend/rfx/detail/RfxElement.h"
#include "model/Workspace.h"

namespace rmfx::rfx {

struct StreamMapDeclaration {
    std::string name;
    std::vector<VertexStream> streams;
    std::vector<int> registers;  // each stream's REGISTER (the v# of a vs_1_1 without dcl_*), -1 when absent
    SourceLocation where;
};

struct ModelDeclaration {
    std::string name;
    std::string file;  // FILE_NAME exactly as written (a Windows path, often)
    SourceLocation where;
};

// A declaration rmfx reads past (a light, a material): named, so that what refers
// to it can say so.
struct UnsupportedDeclaration {
    std::string name;
    std::string what;  // "a light variable"
    SourceLocation where;
};

struct Declarations {
    std::vector<Variable> variables;
    std::vector<Texture> textures;
    std::vector<RenderTarget> targets;
    std::vector<StreamMapDeclaration> streamMaps;
    std::vector<ModelDeclaration> models;
    std::vector<UnsupportedDeclaration> unsupported;
};

// Reads `e` into `into` when it is a declaration element (RmFloatVariable, Rm2DTextureVariable,
// RmRenderableTexture, RmStreamMap, RmModelData…) and returns true; false for any other element.
// Declarations rmfx cannot use (lights, materials, strings) give a warning and true.
bool readDeclaration(const RfxElement& e, Declarations& into);

}  // namespace rmfx::rfx
