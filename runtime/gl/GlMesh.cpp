#include "gl/GlMesh.h"

#include <vector>

#include <epoxy/gl.h>

#include "model/MeshTangents.h"

namespace rmfx {
namespace {

// Floats per vertex, and where each usage starts.
constexpr GLsizei kStride = 18;
struct Layout {
    GLint size;
    GLuint offset;
};
Layout layoutOf(VertexUsage usage) {
    switch (usage) {
        case VertexUsage::Position: return {3, 0};
        case VertexUsage::Normal: return {3, 3};
        case VertexUsage::TexCoord: return {2, 6};
        case VertexUsage::Tangent: return {3, 8};
        case VertexUsage::Binormal: return {3, 11};
        case VertexUsage::Color: return {4, 14};
    }
    return {3, 0};
}

const void* offsetPointer(GLuint floats) { return reinterpret_cast<const void*>(static_cast<uintptr_t>(floats * sizeof(float))); }

bool compatibilityContext() {
    GLint mask = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
    return (mask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT) != 0;
}

// Feeds a compatibility built-in (gl_Vertex, gl_Normal, gl_MultiTexCoordN, gl_Color) from the
// buffer bound to GL_ARRAY_BUFFER, into the bound vertex array. Tangents and binormals have none.
void enableBuiltinArray(VertexUsage usage, int usageIndex) {
    Layout l = layoutOf(usage);
    const GLsizei stride = kStride * sizeof(float);
    switch (usage) {
        case VertexUsage::Position:
            glEnableClientState(GL_VERTEX_ARRAY);
            glVertexPointer(l.size, GL_FLOAT, stride, offsetPointer(l.offset));
            break;
        case VertexUsage::Normal:
            glEnableClientState(GL_NORMAL_ARRAY);
            glNormalPointer(GL_FLOAT, stride, offsetPointer(l.offset));
            break;
        case VertexUsage::TexCoord:
            glClientActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(usageIndex));
            glEnableClientState(GL_TEXTURE_COORD_ARRAY);
            glTexCoordPointer(l.size, GL_FLOAT, stride, offsetPointer(l.offset));
            glClientActiveTexture(GL_TEXTURE0);
            break;
        case VertexUsage::Color:
            glEnableClientState(GL_COLOR_ARRAY);
            glColorPointer(l.size, GL_FLOAT, stride, offsetPointer(l.offset));
            break;
        case VertexUsage::Tangent:
        case VertexUsage::Binormal: break;
    }
}

}  // namespace

GlMesh::GlMesh(const Mesh& mesh) : indexCount_(mesh.indices.size()), compatibility_(compatibilityContext()) {
    MeshTangents tangents = computeTangents(mesh);
    std::vector<float> interleaved;
    interleaved.reserve(mesh.vertexCount() * kStride);
    for (size_t i = 0; i < mesh.vertexCount(); ++i) {
        const glm::vec3& p = mesh.positions[i];
        glm::vec3 n = i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 0, 1);
        glm::vec2 t = i < mesh.texcoords.size() ? mesh.texcoords[i] : glm::vec2(0);
        const glm::vec3 &u = tangents.tangents[i], &v = tangents.binormals[i];
        interleaved.insert(interleaved.end(),
                           {p.x, p.y, p.z, n.x, n.y, n.z, t.x, t.y, u.x, u.y, u.z, v.x, v.y, v.z, 1.0f, 1.0f, 1.0f, 1.0f});
    }
    vertexBuffer_ = createBuffer();
    glNamedBufferStorage(vertexBuffer_.get(), static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)),
                         interleaved.data(), 0);
    indexBuffer_ = createBuffer();
    glNamedBufferStorage(indexBuffer_.get(), static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(uint32_t)),
                         mesh.indices.data(), 0);
    const VertexUsage defaults[3] = {VertexUsage::Position, VertexUsage::Normal, VertexUsage::TexCoord};
    std::vector<StreamBinding> layout;
    // Generic arrays only: a program that reads the compatibility built-ins draws with the arrays
    // bindStreams lists for it (the two kinds alias on some drivers).
    for (int a = 0; a < 3; ++a) layout.push_back({defaults[a], 0, a});
    streamVertexArray(layout);
    vertexArray_ = std::move(streamArrays_.at(layout));  // the default array is kept apart
    streamArrays_.clear();
}

unsigned GlMesh::streamVertexArray(const std::vector<StreamBinding>& streams) const {
    if (auto it = streamArrays_.find(streams); it != streamArrays_.end()) return it->second.get();
    VertexArrayHandle handle = createVertexArray();
    const GLuint array = handle.get();
    glVertexArrayVertexBuffer(array, 0, vertexBuffer_.get(), 0, kStride * sizeof(float));
    glVertexArrayElementBuffer(array, indexBuffer_.get());
    bool builtins = false;
    for (const StreamBinding& s : streams) {
        if (s.location < 0) {
            builtins = true;
            continue;
        }
        Layout l = layoutOf(s.usage);
        GLuint a = static_cast<GLuint>(s.location);
        glEnableVertexArrayAttrib(array, a);
        glVertexArrayAttribFormat(array, a, l.size, GL_FLOAT, GL_FALSE, l.offset * sizeof(float));
        glVertexArrayAttribBinding(array, a, 0);
    }
    if (builtins && compatibility_) {
        // The built-in arrays have no direct-state-access entry points: bind, point, unbind.
        glBindVertexArray(array);
        glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_.get());
        for (const StreamBinding& s : streams)
            if (s.location < 0) enableBuiltinArray(s.usage, s.usageIndex);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        glBindVertexArray(0);
    }
    streamArrays_[streams] = std::move(handle);
    return array;
}

void GlMesh::draw(const std::vector<StreamBinding>& streams) const {
    glBindVertexArray(streams.empty() ? vertexArray_.get() : streamVertexArray(streams));
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(indexCount_), GL_UNSIGNED_INT, nullptr);
}

}  // namespace rmfx
