#pragma once
// A DirectDraw Surface cube map in one file (RenderMonkey's usual environment maps): what a
// cube texture named by a single .dds file holds. OpenImageIO 2.4 decodes DXT1/3/5 and
// uncompressed DDS and presents a cube map as one image with its six faces stacked top to
// bottom (+x -x +y -y +z -z, its "dds:CubeMapSides"); D3D and GL share the face orientation, so
// the faces go to GL as they are.

#include <filesystem>

#include "core/Result.h"
#include "io/image/CubeMapLayout.h"

namespace rmfx {

// Whether a cube texture's single file is read as a DDS cube map: by its extension, any case.
bool isDdsFile(const std::filesystem::path& file);

// The six faces of a DDS cube map. A DDS file that is no cube map (a 2D or volume texture) or
// lacks faces is an error naming the file.
Result<CubeFaces> readDdsCubeMap(const std::filesystem::path& file);

}  // namespace rmfx
