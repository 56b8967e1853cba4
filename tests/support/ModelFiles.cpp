#include "tests/support/ModelFiles.h"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

namespace rmfx::test {
namespace {

void appendBytes(std::string& out, const void* data, size_t size) { out.append(static_cast<const char*>(data), size); }
void appendU16(std::string& out, uint16_t v) { appendBytes(out, &v, 2); }  // little-endian hosts only
void appendU32(std::string& out, uint32_t v) { appendBytes(out, &v, 4); }
void appendFloat(std::string& out, float v) { appendBytes(out, &v, 4); }

// A 3DS chunk: its id, its length with the 6-byte header, its payload.
std::string chunk(uint16_t id, const std::string& payload) {
    std::string out;
    appendU16(out, id);
    appendU32(out, static_cast<uint32_t>(payload.size() + 6));
    return out + payload;
}

void writeBytes(const std::filesystem::path& file, const std::string& bytes) {
    std::ofstream out(file, std::ios::binary);
    out << bytes;
    if (!out) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace

void write3ds(const std::filesystem::path& file, const Mesh& mesh, const std::optional<std::array<float, 12>>& localAxes) {
    if (mesh.vertexCount() > 0xFFFF || mesh.triangleCount() > 0xFFFF)
        throw std::runtime_error("a .3ds object holds at most 65535 vertices and faces");
    std::string vertices, faces, texcoords, axes;
    appendU16(vertices, static_cast<uint16_t>(mesh.vertexCount()));
    for (const glm::vec3& p : mesh.positions) appendFloat(vertices, p.x), appendFloat(vertices, p.y), appendFloat(vertices, p.z);
    appendU16(faces, static_cast<uint16_t>(mesh.triangleCount()));
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        for (int k = 0; k < 3; ++k) appendU16(faces, static_cast<uint16_t>(mesh.indices[3 * t + k]));
        appendU16(faces, 0);  // edge flags
    }
    appendU16(texcoords, static_cast<uint16_t>(mesh.vertexCount()));
    for (const glm::vec2& t : mesh.texcoords) appendFloat(texcoords, t.x), appendFloat(texcoords, t.y);
    std::string triMesh = chunk(0x4110, vertices) + chunk(0x4120, faces) + chunk(0x4140, texcoords);
    if (localAxes) {
        for (float v : *localAxes) appendFloat(axes, v);
        triMesh += chunk(0x4160, axes);
    }
    std::string object = std::string("Shape", 6) + chunk(0x4100, triMesh);  // the name, NUL-terminated
    std::string version;
    appendU32(version, 3);
    std::string editor = chunk(0x3D3E, version) + chunk(0x4000, object);
    writeBytes(file, chunk(0x4D4D, chunk(0x0002, version) + chunk(0x3D3D, editor)));
}

void writeDirectX(const std::filesystem::path& file, const Mesh& mesh) {
    std::string out = "xof 0303txt 0032\nMesh Shape {\n " + std::to_string(mesh.vertexCount()) + ";\n";
    char line[160];
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
        const glm::vec3& p = mesh.positions[v];
        std::snprintf(line, sizeof line, " %.9g;%.9g;%.9g;%s\n", p.x, p.y, p.z, v + 1 < mesh.vertexCount() ? "," : ";");
        out += line;
    }
    out += " " + std::to_string(mesh.triangleCount()) + ";\n";
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        std::snprintf(line, sizeof line, " 3;%u,%u,%u;%s\n", mesh.indices[3 * t], mesh.indices[3 * t + 1],
                      mesh.indices[3 * t + 2], t + 1 < mesh.triangleCount() ? "," : ";");
        out += line;
    }
    out += " MeshTextureCoords {\n  " + std::to_string(mesh.vertexCount()) + ";\n";
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
        const glm::vec2& t = mesh.texcoords[v];
        std::snprintf(line, sizeof line, "  %.9g;%.9g;%s\n", t.x, t.y, v + 1 < mesh.vertexCount() ? "," : ";");
        out += line;
    }
    out += " }\n}\n";
    writeBytes(file, out);
}

void writeObj(const std::filesystem::path& file, const Mesh& mesh) {
    std::string out;
    char line[160];
    for (const glm::vec3& p : mesh.positions) {
        std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
        out += line;
    }
    for (const glm::vec2& t : mesh.texcoords) {
        std::snprintf(line, sizeof line, "vt %.9g %.9g\n", t.x, t.y);
        out += line;
    }
    for (const glm::vec3& n : mesh.normals) {
        std::snprintf(line, sizeof line, "vn %.9g %.9g %.9g\n", n.x, n.y, n.z);
        out += line;
    }
    const bool normals = !mesh.normals.empty();
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        out += "f";
        for (int k = 0; k < 3; ++k) {
            const uint32_t i = mesh.indices[3 * t + k] + 1;
            std::snprintf(line, sizeof line, normals ? " %u/%u/%u" : " %u/%u", i, i, i);
            out += line;
        }
        out += "\n";
    }
    writeBytes(file, out);
}

Mesh asymmetricBoxes() {
    Mesh mesh;
    // Each box: its far corner and the square of texture space its faces span.
    struct Box {
        glm::vec3 size;
        glm::vec2 uvMin, uvMax;
    };
    const Box boxes[] = {{{1.0f, 0.2f, 0.2f}, {0.0f, 0.0f}, {0.5f, 0.4f}},
                         {{0.25f, 0.7f, 0.25f}, {0.5f, 0.1f}, {1.0f, 0.6f}},
                         {{0.3f, 0.3f, 0.45f}, {0.1f, 0.6f}, {0.6f, 1.0f}}};
    for (const Box& box : boxes) {
        // Six faces, each its own four vertices: (axis, sign) and two axes spanning it,
        // counter-clockwise seen from outside.
        for (int axis = 0; axis < 3; ++axis)
            for (int side = 0; side < 2; ++side) {
                const int u = (axis + 1) % 3, v = (axis + 2) % 3;
                const uint32_t first = static_cast<uint32_t>(mesh.positions.size());
                const glm::vec2 corners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
                for (glm::vec2 c : corners) {
                    glm::vec3 p(0.0f);
                    p[axis] = side ? box.size[axis] : 0.0f;
                    p[u] = c.x * box.size[u];
                    p[v] = c.y * box.size[v];
                    mesh.positions.push_back(p);
                    glm::vec3 n(0.0f);
                    n[axis] = side ? 1.0f : -1.0f;
                    mesh.normals.push_back(n);
                    mesh.texcoords.push_back(box.uvMin + (box.uvMax - box.uvMin) * c);
                }
                // (u, v, axis) is right-handed, so 0-1-2 winds counter-clockwise seen from +axis.
                if (side)
                    mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
                else
                    mesh.indices.insert(mesh.indices.end(), {first, first + 2, first + 1, first, first + 3, first + 2});
            }
    }
    return mesh;
}

}  // namespace rmfx::test
