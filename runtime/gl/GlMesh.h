#pragma once
// A Mesh on the GPU: one buffer with interleaved position, normal, texcoord, tangent, binormal and
// colour (white), and 32-bit indices. Its default vertex array feeds rmfx's layout (attribute
// locations 0 position, 1 normal, 2 texcoord). Vertex streams (Pass::streams, and the built-ins
// gl_Vertex, gl_Normal and gl_MultiTexCoord0 that bindStreams lists for a program reading them)
// get a vertex array of their own. Needs a current GL context.

#include <map>
#include <vector>

#include "gl/GlHandles.h"
#include "model/Mesh.h"
#include "model/Workspace.h"

namespace rmfx {

// One vertex stream resolved against a linked program.
struct StreamBinding {
    VertexUsage usage = VertexUsage::Position;
    int usageIndex = 0;
    int location = -1;  // the generic attribute; -1: the compatibility built-in of the usage
    auto operator<=>(const StreamBinding&) const = default;
};

class GlMesh {
public:
    explicit GlMesh(const Mesh& mesh);

    // With streams: a vertex array feeding exactly those (made on first use, then kept).
    // Built-in streams need a compatibility-profile context.
    void draw(const std::vector<StreamBinding>& streams = {}) const;
    size_t indexCount() const { return indexCount_; }

private:
    unsigned streamVertexArray(const std::vector<StreamBinding>& streams) const;

    VertexArrayHandle vertexArray_;
    BufferHandle vertexBuffer_, indexBuffer_;
    size_t indexCount_ = 0;
    bool compatibility_ = false;
    mutable std::map<std::vector<StreamBinding>, VertexArrayHandle> streamArrays_;
};

}  // namespace rmfx
