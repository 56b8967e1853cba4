#pragma once
// The name rmfx's XML gives a vertex usage (<stream usage="texcoord">), for messages and listings.

#include "model/Workspace.h"

namespace rmfx {

const char* vertexUsageName(VertexUsage usage);

}  // namespace rmfx
