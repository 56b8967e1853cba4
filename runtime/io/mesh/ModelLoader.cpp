#include "io/mesh/ModelLoader.h"

#include <cctype>
#include <cmath>
#include <utility>
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

// What an Assimp importer changed from the file's numbers, to be undone (ModelLoader.h).
enum class ImportedConvention { FileOwn, ZUpRotatedToYUp, LeftHandedMirrored };

ImportedConvention conventionOf(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".3ds") return ImportedConvention::ZUpRotatedToYUp;
    if (extension == ".x") return ImportedConvention::LeftHandedMirrored;
    return ImportedConvention::FileOwn;
}

// Back to the file's left-handed numbers: z and the normals' z mirrored again, v flipped back,
// and each triangle's winding reversed back (which keeps the normals on the same side).
void unmirrorLeftHanded(Mesh& mesh) {
    for (glm::vec3& p : mesh.positions) p.z = -p.z;
    for (glm::vec3& n : mesh.normals) n.z = -n.z;
    for (glm::vec2& t : mesh.texcoords) t.y = 1.0f - t.y;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
}

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

    const ImportedConvention convention = conventionOf(path);
    Assimp::Importer importer;
    const aiScene* scene =
        importer.ReadFile(name, aiProcess_Triangulate | aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices);
    if (!scene) return Error{name + ": cannot load model: " + importer.GetErrorString()};
    if (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) return Error{name + ": cannot load model: the scene is incomplete"};
    // The 3DS importer puts its Z-up to Y-up rotation R, (x, y, z) → (x, z, −y), on the root node
    // (root = R · root); R⁻¹ takes it off again.
    if (convention == ImportedConvention::ZUpRotatedToYUp && scene->mRootNode) {
        const aiMatrix4x4 inverseOfR(1, 0, 0, 0,  //
                                     0, 0, -1, 0,  //
                                     0, 1, 0, 0,   //
                                     0, 0, 0, 1);
        scene->mRootNode->mTransformation = inverseOfR * scene->mRootNode->mTransformation;
    }
    scene = importer.ApplyPostProcessing(aiProcess_PreTransformVertices);
    if (!scene) return Error{name + ": cannot load model: " + importer.GetErrorString()};

    Mesh mesh;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) appendTriangles(*scene->mMeshes[m], mesh);
    if (mesh.indices.empty()) return Error{name + ": the model has no triangles"};
    repairNormals(mesh);
    if (convention == ImportedConvention::LeftHandedMirrored) unmirrorLeftHanded(mesh);
    return mesh;
}

}  // namespace rmfx
