#pragma once
// A Mesh on the GPU: one vertex array with interleaved position, normal and texcoord
// (attribute locations 0, 1, 2) and 32-bit indices. Needs a current GL context.

#include "runtime/Mesh.h"

namespace rmfx {

class GlMesh {
public:
    explicit GlMesh(const Mesh& mesh);
    ~GlMesh();
    GlMesh(const GlMesh&) = delete;
    GlMesh& operator=(const GlMesh&) = delete;

    void draw() const;
    size_t indexCount() const { return indexCount_; }

private:
    unsigned vertexArray_ = 0, vertexBuffer_ = 0, indexBuffer_ = 0;
    size_t indexCount_ = 0;
};

}  // namespace rmfx
