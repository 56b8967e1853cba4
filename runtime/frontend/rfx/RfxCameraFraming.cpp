#include "frontend/rfx/RfxCameraFraming.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/IdentifierSearch.h"
#include "io/mesh/BuiltinMeshes.h"
#include "io/mesh/ModelLoader.h"
#include "model/OrbitCamera.h"

namespace rmfx {

namespace {

struct Sphere {
    glm::dvec3 centre{0.0};
    double radius = 0.0;
};

Sphere boundsOf(const std::vector<const Mesh*>& meshes) {
    glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
    for (const Mesh* mesh : meshes)
        for (const glm::vec3& p : mesh->positions) {
            low = glm::min(low, glm::dvec3(p));
            high = glm::max(high, glm::dvec3(p));
        }
    Sphere s;
    if (!(low.x <= high.x)) return s;
    s.centre = (low + high) * 0.5;
    for (const Mesh* mesh : meshes)
        for (const glm::vec3& p : mesh->positions) s.radius = std::max(s.radius, glm::length(glm::dvec3(p) - s.centre));
    return s;
}

// The value RenderMonkey saved last in a variable it fills by this semantic. RenderMonkey 1.0's
// files name no semantics: their shaders read the camera from constants under the names its
// examples gave them (view_proj_matrix, view_matrix, view_position), saved as the viewer left them.
const Variable* stored(const Workspace& ws, const std::string& semantic, ValueType type) {
    for (const Variable& v : ws.variables)
        if (v.semantic == semantic && v.value.type == type) return &v;
    static const std::map<std::string, std::string> conventionalNames = {
        {"ViewProjection", "view_proj_matrix"}, {"View", "view_matrix"}, {"ViewPosition", "view_position"}};
    auto name = conventionalNames.find(semantic);
    if (name == conventionalNames.end()) return nullptr;
    for (const Variable& v : ws.variables)
        if (v.semantic.empty() && v.value.type == type && v.name == name->second) return &v;
    return nullptr;
}

// The vertical field of view, in degrees, of a perspective projection whose y scale is p11 =
// cot(FOV / 2): past 180 degrees (RenderMonkey's zoom went there) p11 is negative.
float fovFromYScale(double p11) { return static_cast<float>(2.0 * std::atan2(1.0, p11) * 180.0 / std::numbers::pi); }

// RenderMonkey's viewer camera as it saved it in a View matrix (VARIABLE_SEMANTIC="View"): stored
// row by row in the column-vector convention, which rmfx reads with VALUE_0…3 as the first column,
// so element (row i, column j) is data[4i + j]. The eye is -Rᵀt; the view axis is the third row,
// looked along toward the models (OpenGL's view looks down -z, Direct3D's down +z: `base`'s
// convention says which comes first).
std::optional<OrbitCameraSettings> fromStoredView(const Variable& view, const Sphere& models, bool haveModels,
                                                  const OrbitCameraSettings& base) {
    const auto& m = view.value.data;
    auto r = [&](int row, int column) { return static_cast<double>(m[static_cast<size_t>(4 * row + column)]); };
    glm::dvec3 eye(0.0);
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) eye[j] -= r(i, j) * r(i, 3);
    const glm::dvec3 up(r(1, 0), r(1, 1), r(1, 2));
    glm::dvec3 forward = glm::dvec3(r(2, 0), r(2, 1), r(2, 2));
    if (base.convention == CameraConvention::OpenGL) forward = -forward;
    if (!(glm::length(forward) > 1e-6) || !std::isfinite(eye.x + eye.y + eye.z)) return std::nullopt;
    forward = glm::normalize(forward);
    const glm::dvec3 toModels = models.centre - eye;
    // Which way the view axis points is taken from where the models are, when the eye stands
    // outside them: from inside (a stand-in larger than the model it stands for), they say nothing.
    const bool eyeOutside = haveModels && glm::length(toModels) > models.radius;
    if (eyeOutside && glm::dot(toModels, forward) < 0.0) forward = -forward;
    const double along = haveModels ? std::max(glm::dot(toModels, forward), models.radius * 0.1) : glm::length(eye);
    return orbitLookingAt(glm::vec3(eye), glm::vec3(eye + forward * std::max(along, 1e-3)), glm::vec3(up), base);
}

// Whether a model reference (a Windows path, any case) names a .3ds file.
bool isThreeDs(const std::string& reference) {
    if (reference.size() < 4) return false;
    std::string tail = reference.substr(reference.size() - 4);
    for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return tail == ".3ds";
}

// A built-in mesh standing in for a missing model that is no measured stock model (those have
// their own size: io/mesh/StockModels) is unit-sized, and RenderMonkey's models and cameras are
// about a hundred times larger: through the file's own camera it would be a dot. It is scaled to
// span half the height of the camera's view where it stands (a radius of 41 at RenderMonkey's
// default 200 units and 45°). Full-screen quads keep their size. A stock model's stand-in keeps
// the stock size unless the file is no .3ds (RenderMonkey's stock models all are) and the camera
// would stand inside it: then it was the author's own model of that name (a "teapot.X" a few units
// across, seen from 3.5 units away), and it is sized to the camera like any other.
void sizeStandInsToTheCamera(Workspace& ws) {
    const OrbitCamera camera(ws.camera);
    // |tan|: past 180 degrees the view is turned round at 360 - FOV (RfxCamera.cpp).
    const double halfHeightPerDistance = std::abs(std::tan(ws.camera.fovYDegrees * 0.5 * std::numbers::pi / 180.0));
    for (Pass& pass : ws.passes) {
        DrawCall& draw = pass.draw;
        if (!draw.standIn || !draw.mesh || *draw.mesh == BuiltinMesh::Quad || *draw.mesh == BuiltinMesh::FullscreenTriangle)
            continue;
        const Mesh mesh = makeMesh(*draw.mesh);
        const Sphere bounds = boundsOf({&mesh});
        if (draw.stockSize && !isThreeDs(draw.standsInFor)) {
            const glm::dvec3 centre = glm::dvec3(draw.translate) +
                                      (bounds.centre * double(draw.meshScale) + glm::dvec3(draw.meshOffset)) * glm::dvec3(draw.scale);
            const double radius = bounds.radius * double(draw.meshScale) * double(std::max({draw.scale.x, draw.scale.y, draw.scale.z}));
            if (glm::length(glm::dvec3(camera.position()) - centre) < radius) {
                draw.stockSize = false;
                draw.meshScale = 1.0f;
                draw.meshOffset = glm::vec3(0.0f);
            }
        }
        if (draw.stockSize) continue;
        const double distance = glm::length(glm::dvec3(camera.position()) - (glm::dvec3(draw.translate) + bounds.centre * glm::dvec3(draw.scale)));
        const double wanted = 0.5 * distance * halfHeightPerDistance;
        if (!(bounds.radius > 0.0) || !(wanted > bounds.radius) || !std::isfinite(wanted)) continue;
        draw.meshScale = static_cast<float>(wanted / bounds.radius);
    }
}

// Row i of a stored matrix's data (element (row i, column j) at 4i + j, as fromStoredView reads it).
glm::dvec4 rowOf(const Variable& stored, int i) {
    const auto& m = stored.value.data;
    return glm::dvec4(m[static_cast<size_t>(4 * i)], m[static_cast<size_t>(4 * i + 1)], m[static_cast<size_t>(4 * i + 2)],
                      m[static_cast<size_t>(4 * i + 3)]);
}

// The camera from a stored ViewProjection alone (P·V, a symmetric perspective): in either
// convention its last row is w = forward·(p - eye), and its first two rows are P00·right·(p - eye)
// and P11·up·(p - eye), right being the picture's right. So forward, right and up are those rows'
// directions (right and up kept square to forward), the eye solves the three, and P11 is the
// field of view. A matrix whose last row is no direction (an orthographic one) gives nothing.
std::optional<OrbitCameraSettings> fromStoredViewProjection(const Variable& viewProjection, const Sphere& models,
                                                            bool haveModels, const OrbitCameraSettings& base) {
    const glm::dvec4 x = rowOf(viewProjection, 0), y = rowOf(viewProjection, 1), w = rowOf(viewProjection, 3);
    const double wLength = glm::length(glm::dvec3(w));
    if (!(wLength > 1e-9) || !std::isfinite(wLength)) return std::nullopt;
    const glm::dvec3 forward = glm::dvec3(w) / wLength;
    glm::dvec3 right = glm::dvec3(x) - forward * glm::dot(glm::dvec3(x), forward);
    glm::dvec3 up = glm::dvec3(y) - forward * glm::dot(glm::dvec3(y), forward);
    const double p00 = glm::length(right), p11 = glm::length(up);
    if (!(p00 > 1e-9) || !(p11 > 1e-9) || !std::isfinite(p00 + p11)) return std::nullopt;
    right /= p00;
    up /= p11;
    // w = wLength·forward·(p - eye) and x = p00·right·(p - eye): each row's constant gives the eye
    // along its axis.
    const glm::dvec3 eye = right * (-x.w / p00) + up * (-y.w / p11) + forward * (-w.w / wLength);
    if (!std::isfinite(eye.x + eye.y + eye.z)) return std::nullopt;
    // The orbit's centre: where the view passes the models (the origin's depth without them).
    const double along = std::max(glm::dot((haveModels ? models.centre : glm::dvec3(0.0)) - eye, forward), 1e-3 * glm::length(eye) + 1e-3);
    std::optional<OrbitCameraSettings> s = orbitLookingAt(glm::vec3(eye), glm::vec3(eye + forward * along), glm::vec3(up), base);
    if (s) s->fovYDegrees = fovFromYScale(p11);
    return s;
}

// The near and far planes of a stored perspective projection, alone or times a View (and World):
// its depth row is a·(its w row) + c, w being the distance along the view, so z/w runs over
// Direct3D's 0…1 (OpenGL's -1…1) from the near plane to the far one. Nothing for a matrix whose
// rows are not so (orthographic) or whose planes make no sense.
std::optional<std::pair<double, double>> clipPlanesOf(const Variable& stored, CameraConvention convention) {
    const glm::dvec4 z = rowOf(stored, 2), w = rowOf(stored, 3);
    const glm::dvec3 wAxis(w);
    const double wLength2 = glm::dot(wAxis, wAxis);
    if (!(wLength2 > 1e-18) || !std::isfinite(wLength2)) return std::nullopt;
    const double a = glm::dot(glm::dvec3(z), wAxis) / wLength2;
    if (glm::length(glm::dvec3(z) - a * wAxis) > 1e-4 * std::max(1.0, glm::length(glm::dvec3(z)))) return std::nullopt;
    const double c = z.w - a * w.w;
    const double nearPlane = convention == CameraConvention::Direct3D ? -c / a : c / (-1.0 - a);
    const double farPlane = c / (1.0 - a);
    if (!std::isfinite(nearPlane) || !std::isfinite(farPlane) || !(nearPlane > 0.0) || !(farPlane > nearPlane * 1.0001) ||
        farPlane / nearPlane > 1e8)
        return std::nullopt;
    return std::pair{nearPlane, farPlane};
}

// A stored matrix's data (element (row i, column j) at 4i + j, as fromStoredView reads it) as a
// matrix, and back.
glm::dmat4 matrixOf(const std::array<float, 16>& data) {
    glm::dmat4 m(0.0);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) m[j][i] = data[static_cast<size_t>(4 * i + j)];
    return m;
}
std::array<float, 16> dataOf(const glm::dmat4& m) {
    std::array<float, 16> data{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) data[static_cast<size_t>(4 * i + j)] = static_cast<float>(m[j][i]);
    return data;
}

// P·V from a stored WorldViewProjection (P·V·W): times the inverse of the stored World, where the
// file kept one; without one the world is taken as the identity, as RenderMonkey's viewer leaves
// it (its camera moves, not the model). Nothing where the World kept cannot be inverted.
std::optional<Variable> viewProjectionFromWorldViewProjection(const Workspace& ws, const Variable& worldViewProjection) {
    Variable viewProjection = worldViewProjection;
    if (const Variable* world = stored(ws, "World", ValueType::Mat4)) {
        const glm::dmat4 w = matrixOf(world->value.data);
        const double determinant = glm::determinant(w);
        if (!(std::abs(determinant) > 1e-12) || !std::isfinite(determinant)) return std::nullopt;
        viewProjection.value.data = dataOf(matrixOf(worldViewProjection.value.data) * glm::inverse(w));
    }
    return viewProjection;
}

}  // namespace

void frameDrawnModels(Workspace& ws) {
    if (!ws.camera.where.file.empty()) {  // an RmCamera placed it
        sizeStandInsToTheCamera(ws);
        return;
    }
    std::vector<Mesh> meshes;
    for (const Pass& pass : ws.passes) {
        if (pass.draw.mesh) {
            if (*pass.draw.mesh == BuiltinMesh::Quad || *pass.draw.mesh == BuiltinMesh::FullscreenTriangle) continue;
            meshes.push_back(*makeDrawnMesh(pass.draw));
        } else if (!pass.draw.file.empty()) {
            if (auto loaded = loadModel(ws.folder / pass.draw.file)) meshes.push_back(std::move(*loaded));
        }
    }
    // A sky dome or box around the scene is no object to frame: a mesh whose bounds hold every
    // other's and are five times larger than all of them together is left out.
    std::vector<const Mesh*> framed;
    for (const Mesh& mesh : meshes) framed.push_back(&mesh);
    if (framed.size() > 1) {
        std::vector<Sphere> each;
        for (const Mesh& mesh : meshes) each.push_back(boundsOf({&mesh}));
        for (size_t i = 0; i < meshes.size(); ++i) {
            std::vector<const Mesh*> others;
            for (size_t j = 0; j < meshes.size(); ++j)
                if (j != i) others.push_back(&meshes[j]);
            const Sphere rest = boundsOf(others);
            if (each[i].radius > 5.0 * rest.radius && glm::length(rest.centre - each[i].centre) + rest.radius <= each[i].radius)
                std::erase(framed, &meshes[i]);
        }
    }
    const Sphere models = boundsOf(framed);
    const bool haveModels = !framed.empty() && models.radius > 0.0 && std::isfinite(models.radius);

    // The camera RenderMonkey's viewer last showed, where the file kept its matrices. Its clip
    // planes are those of the stored Projection (or ViewProjection, or WorldViewProjection), which
    // the shaders' own scaling and shadow maps were made for; without one they are set to hold the
    // models.
    auto adopt = [&](const OrbitCameraSettings& camera) {
        ws.camera = camera;
        std::optional<std::pair<double, double>> planes;
        for (const char* semantic : {"Projection", "ViewProjection", "WorldViewProjection"})
            if (const Variable* m = stored(ws, semantic, ValueType::Mat4); m && !planes) planes = clipPlanesOf(*m, camera.convention);
        if (planes) {
            ws.camera.nearPlane = static_cast<float>(planes->first);
            ws.camera.farPlane = static_cast<float>(planes->second);
        } else {
            const double reach = haveModels ? glm::length(models.centre - glm::dvec3(camera.target)) + models.radius : 0.0;
            ws.camera.farPlane = static_cast<float>(std::max<double>(ws.camera.farPlane, (ws.camera.distance + reach) * 2.0));
            ws.camera.nearPlane = static_cast<float>(std::max(ws.camera.distance * 1e-3, 1e-3));
        }
        sizeStandInsToTheCamera(ws);
    };
    // A View (or ViewInverse) left at the identity was never filled by the viewer, which stands
    // away from the models (it would put the eye at the origin, inside them): passed over.
    const Variable* view = stored(ws, "View", ValueType::Mat4);
    auto identity = [](const Variable& v) {
        for (size_t i = 0; i < 16; ++i)
            if (v.value.data[i] != (i % 5 == 0 ? 1.0f : 0.0f)) return false;
        return true;
    };
    if (view && identity(*view)) view = nullptr;
    const Variable* viewProjection = stored(ws, "ViewProjection", ValueType::Mat4);
    const Variable* worldViewProjection = stored(ws, "WorldViewProjection", ValueType::Mat4);
    const Variable* viewInverse = stored(ws, "ViewInverse", ValueType::Mat4);
    if (viewInverse && identity(*viewInverse)) viewInverse = nullptr;
    // The matrices the passes read decide: a file often keeps the viewer's last View (stale, or
    // its default 200 units away) beside the ViewProjection its shaders read. Those a shader reads
    // are tried first; the others only when none of those holds a camera (a matrix the viewer never
    // filled, the identity, holds none).
    // A matrix a shader declares and never uses is not read (Nebula.rfx declares a stale
    // ViewInverse beside the WorldViewProjection it multiplies by): its name must come up again
    // after the declaration.
    // A Direct3D shader's constant table (RmShaderConstant) says it outright: RenderMonkey lists
    // the constants the compiled code kept, so a View only dead code reads is not there.
    auto read = [&](const Variable* v) {
        if (!v) return false;
        for (const Pass& pass : ws.passes)
            for (const ShaderSource& shader : pass.shaders) {
                if (!shader.constantTable.empty()) {
                    if (std::find(shader.constantTable.begin(), shader.constantTable.end(), v->name) != shader.constantTable.end())
                        return true;
                } else if (mentionCount(shader.code, v->name) >= 2) {
                    return true;
                }
            }
        return false;
    };
    // The camera of a stored P·V, or of P·V·W with the World taken off.
    auto productCamera = [&](const Variable* viewProjection, const Variable* worldViewProjection) -> std::optional<OrbitCameraSettings> {
        if (viewProjection)
            if (auto camera = fromStoredViewProjection(*viewProjection, models, haveModels, ws.camera)) return camera;
        if (worldViewProjection)
            if (std::optional<Variable> product = viewProjectionFromWorldViewProjection(ws, *worldViewProjection))
                if (auto camera = fromStoredViewProjection(*product, models, haveModels, ws.camera)) return camera;
        return std::nullopt;
    };
    const Variable* storedViewProjection = viewProjection;
    const Variable* storedWorldViewProjection = worldViewProjection;
    auto cameraFrom = [&](const Variable* view, const Variable* viewProjection, const Variable* worldViewProjection,
                          const Variable* viewInverse) -> std::optional<OrbitCameraSettings> {
        // ViewInverse, the camera's own transform: the View is its inverse, in the same layout.
        std::optional<Variable> invertedViewInverse;
        if (!view && viewInverse) {
            glm::dmat4 m;
            for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = viewInverse->value.data[static_cast<size_t>(i)];
            if (std::abs(glm::determinant(m)) > 1e-12) {
                const glm::dmat4 inverse = glm::inverse(m);
                invertedViewInverse = *viewInverse;
                for (int i = 0; i < 16; ++i)
                    invertedViewInverse->value.data[static_cast<size_t>(i)] = static_cast<float>(inverse[i / 4][i % 4]);
                view = &*invertedViewInverse;
            }
        }
        if (view) {
            if (auto camera = fromStoredView(*view, models, haveModels, ws.camera)) {
                // The field of view: from a stored Projection, else from the ViewProjection (or
                // WorldViewProjection) the file keeps beside the View, read by a shader or not.
                if (const Variable* projection = stored(ws, "Projection", ValueType::Mat4)) {
                    const double p11 = projection->value.data[5];
                    if (std::abs(p11) > 1e-6 && std::isfinite(p11)) camera->fovYDegrees = fovFromYScale(p11);
                } else if (auto fromProduct = productCamera(storedViewProjection, storedWorldViewProjection)) {
                    camera->fovYDegrees = fromProduct->fovYDegrees;
                }
                return camera;
            }
        }
        return productCamera(viewProjection, worldViewProjection);
    };
    auto ifRead = [&](const Variable* v) { return read(v) ? v : nullptr; };
    std::optional<OrbitCameraSettings> camera =
        cameraFrom(ifRead(view), ifRead(viewProjection), ifRead(worldViewProjection), ifRead(viewInverse));
    if (!camera) camera = cameraFrom(view, viewProjection, worldViewProjection, viewInverse);
    if (camera) {
        adopt(*camera);
        return;
    }
    if (!haveModels) return;
    // Only the eye kept (ViewPosition, which the viewer fills with the matrices; 0 where it never
    // did): looking from it at the models, when it stands outside them.
    const Variable* viewPosition = stored(ws, "ViewPosition", ValueType::Vec4);
    if (!viewPosition) viewPosition = stored(ws, "ViewPosition", ValueType::Vec3);
    if (viewPosition) {
        const glm::dvec3 eye(viewPosition->value.data[0], viewPosition->value.data[1], viewPosition->value.data[2]);
        const glm::dvec3 toModels = models.centre - eye;
        if (std::isfinite(eye.x + eye.y + eye.z) && eye != glm::dvec3(0.0) && glm::length(toModels) > models.radius) {
            const glm::dvec3 forward = glm::normalize(toModels);
            const glm::dvec3 up = std::abs(forward.y) > 0.999 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
            if (auto camera = orbitLookingAt(glm::vec3(eye), glm::vec3(models.centre), glm::vec3(up), ws.camera)) {
                adopt(*camera);
                return;
            }
        }
    }
    const double halfFov = ws.camera.fovYDegrees * 0.5 * std::numbers::pi / 180.0;
    const double distance = models.radius / std::sin(halfFov) * 1.05;
    ws.camera.target = glm::vec3(models.centre);
    ws.camera.distance = static_cast<float>(distance);
    ws.camera.nearPlane = static_cast<float>(std::max((distance - models.radius) * 0.5, distance * 1e-3));
    ws.camera.farPlane = static_cast<float>((distance + models.radius) * 2.0);
}

}  // namespace rmfx
