#include "runtime/GlMesh.h"

#include <vector>

#include <epoxy/gl.h>

namespace rmfx {

GlMesh::GlMesh(const Mesh& mesh) : indexCount_(mesh.indices.size()) {
    std::vector<float> interleaved;
    interleaved.reserve(mesh.vertexCount() * 8);
    for (size_t i = 0; i < mesh.vertexCount(); ++i) {
        const glm::vec3& p = mesh.positions[i];
        glm::vec3 n = i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 0, 1);
        glm::vec2 t = i < mesh.texcoords.size() ? mesh.texcoords[i] : glm::vec2(0);
        interleaved.insert(interleaved.end(), {p.x, p.y, p.z, n.x, n.y, n.z, t.x, t.y});
    }
    glCreateBuffers(1, &vertexBuffer_);
    glNamedBufferStorage(vertexBuffer_, static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)),
                         interleaved.data(), 0);
    glCreateBuffers(1, &indexBuffer_);
    glNamedBufferStorage(indexBuffer_, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(uint32_t)),
                         mesh.indices.data(), 0);
    glCreateVertexArrays(1, &vertexArray_);
    glVertexArrayVertexBuffer(vertexArray_, 0, vertexBuffer_, 0, 8 * sizeof(float));
    glVertexArrayElementBuffer(vertexArray_, indexBuffer_);
    const GLuint sizes[3] = {3, 3, 2}, offsets[3] = {0, 3, 6};
    for (GLuint a = 0; a < 3; ++a) {
        glEnableVertexArrayAttrib(vertexArray_, a);
        glVertexArrayAttribFormat(vertexArray_, a, static_cast<GLint>(sizes[a]), GL_FLOAT, GL_FALSE,
                                  offsets[a] * sizeof(float));
        glVertexArrayAttribBinding(vertexArray_, a, 0);
    }
}

GlMesh::~GlMesh() {
    glDeleteVertexArrays(1, &vertexArray_);
    glDeleteBuffers(1, &vertexBuffer_);
    glDeleteBuffers(1, &indexBuffer_);
}

void GlMesh::draw() const {
    glBindVertexArray(vertexArray_);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(indexCount_), GL_UNSIGNED_INT, nullptr);
}

}  // namespace rmfx
