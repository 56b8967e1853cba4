#include "model/VertexUsageName.h"

namespace rmfx {

const char* vertexUsageName(VertexUsage usage) {
    switch (usage) {
        case VertexUsage::Position: return "position";
        case VertexUsage::Normal: return "normal";
        case VertexUsage::TexCoord: return "texcoord";
        case VertexUsage::Tangent: return "tangent";
        case VertexUsage::Binormal: return "binormal";
        case VertexUsage::Color: return "color";
    }
    return "?";
}

}  // namespace rmfx
