#pragma once
// rmfx render --texture NAME=FILE: a texture's or cube map's files replaced for one run, in an rmfx
// workspace or an imported .rfx alike, before any GL object exists. The workspace file is not
// touched.

#include <filesystem>
#include <string>
#include <vector>

#include "core/Result.h"
#include "model/Workspace.h"

namespace rmfx {

struct TextureArgument {
    std::string name;                         // the texture
    std::vector<std::filesystem::path> files; // one, or six faces (+x,-x,+y,-y,+z,-z) for a cube map
    std::string text;                         // as the user wrote it, for messages
};

// "Sky=env.exr" or "Sky=px.hdr,nx.hdr,py.hdr,ny.hdr,pz.hdr,nz.hdr"; an error without NAME= or FILE.
Result<TextureArgument> parseTextureArgument(const std::string& text);

// Points each named texture at its files. A 2D texture takes one image; a cube map takes six faces,
// a DDS cube map, or one image whose shape says its layout (2:1 longitude/latitude, 4:3 or 3:4
// cross: CubeLayout::FromImage, checked when the image is read). Errors name the argument: an
// unknown texture (listing the workspace's), an <input>'s texture (--input gives those), a texture
// given twice, a wrong number of files, a file that does not exist.
Result<void> replaceTextures(Workspace& ws, const std::vector<TextureArgument>& textures);

}  // namespace rmfx
