#include "io/mesh/ModelLoader.h"

#include <cmath>
#include <system_error>
#include <vector>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/geometric.hpp>

namespace rmfx {

namespace {

constexpr uint32_t kUnused = UINT32_MAX;

glm::vec3 toGlm(const aiVector3D& v) { return {v.x, v.y, v.z}; }

bool isUsableNormal(glm::vec3 n) {
    const float length = glm::length(n);
    return std::isfinite(length) && length > 1e-12f;
}

// Appends the triangles of one Assimp mesh, copying only the vertices they use (a mesh may
// also hold points or lines, whose vertices carry no meaningful normal).
void appendTriangles(const aiMesh& source, Mesh& mesh) {
    std::vector<uint32_t> remap(source.mNumVertices, kUnused);
    for (unsigned f = 0; f < source.mNumFaces; ++f) {
        const aiFace& face = source.mFaces[f];
        if (face.mNumIndices != 3) continue;
        for (unsigned k = 0; k < 3; ++k) {
            const unsigned v = face.mIndices[k];
            if (remap[v] == kUnused) {
                remap[v] = static_cast<uint32_t>(mesh.positions.size());
                mesh.positions.push_back(toGlm(source.mVertices[v]));
                mesh.normals.push_back(source.HasNormals() ? toGlm(source.mNormals[v]) : glm::vec3(0));
                mesh.texcoords.push_back(source.HasTextureCoords(0)
                                             ? glm::vec2(source.mTextureCoords[0][v].x, source.mTextureCoords[0][v].y)
                                             : glm::vec2(0));
            }
            mesh.indices.push_back(remap[v]);
        }
    }
}

// Assimp leaves NaN or zero normals on degenerate triangles; rebuild those from the faces
// around the vertex, and as a last resort point them up, so every normal is unit length.
void repairNormals(Mesh& mesh) {
    std::vector<glm::vec3> fromFaces(mesh.positions.size(), glm::vec3(0));
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        const glm::vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
        if (!isUsableNormal(n)) continue;
        for (uint32_t v : {a, b, c}) fromFaces[v] += n;
    }
    for (size_t v = 0; v < mesh.normals.size(); ++v) {
        glm::vec3& n = mesh.normals[v];
        if (!isUsableNormal(n)) n = fromFaces[v];
        n = isUsableNormal(n) ? glm::normalize(n) : glm::vec3(0, 1, 0);
    }
}

}  // namespace

Result<Mesh> loadModel(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return Error{name + ": no such model file"};
    if (!std::filesystem::is_regular_file(path, ec)) return Error{name + ": not a model file (not a regular file)"};

    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(
        name, aiProcess_Triangulate | aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices |
                  aiProcess_PreTransformVertices);
    if (!scene) return Error{name + ": cannot load model: " + importer.GetErrorString()};
    if (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) return Error{name + ": cannot load model: the scene is incomplete"};

    Mesh mesh;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) appendTriangles(*scene->mMeshes[m], mesh);
    if (mesh.indices.empty()) return Error{name + ": the model has no triangles"};
    repairNormals(mesh);
    return mesh;
}

}  // namespace rmfx
