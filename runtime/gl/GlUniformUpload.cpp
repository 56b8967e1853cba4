#include "gl/GlUniformUpload.h"

#include <cstring>

#include <epoxy/gl.h>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace rmfx {
namespace {

glm::dmat4 toDouble(const glm::mat4& m) { return glm::dmat4(m); }

size_t components(UniformType type) {
    switch (type) {
        case UniformType::Vec2: return 2;
        case UniformType::Vec3: return 3;
        case UniformType::Vec4: return 4;
        case UniformType::Mat2: return 4;
        case UniformType::Mat3: return 9;
        case UniformType::Mat4: return 16;
        default: return 1;
    }
}

// Whether the slot's uniform holds other data than `data` (`count` floats or ints), noting that
// it will from now on.
bool differs(const UniformSlot& u, const void* data, size_t count) {
    const size_t bytes = count * sizeof(float);
    if (u.hasUploaded && std::memcmp(u.uploaded.data(), data, bytes) == 0) return false;
    std::memcpy(u.uploaded.data(), data, bytes);
    u.hasUploaded = true;
    return true;
}

// A value's first components into a uniform of the given type (a vec3 takes a vec4's xyz), unless
// the uniform holds them already.
void uploadValue(GLuint program, const UniformSlot& u, const float* data) {
    const UniformType type = u.type;
    const GLint location = u.location;
    if (!differs(u, data, components(type))) return;
    const GLboolean transpose = u.transposed ? GL_TRUE : GL_FALSE;
    switch (type) {
        case UniformType::Float: glProgramUniform1f(program, location, data[0]); break;
        case UniformType::Int:
        case UniformType::Bool: glProgramUniform1i(program, location, static_cast<GLint>(data[0])); break;
        case UniformType::Vec2: glProgramUniform2fv(program, location, 1, data); break;
        case UniformType::Vec3: glProgramUniform3fv(program, location, 1, data); break;
        case UniformType::Vec4: glProgramUniform4fv(program, location, 1, data); break;
        case UniformType::Mat2: glProgramUniformMatrix2fv(program, location, 1, transpose, data); break;
        case UniformType::Mat3: glProgramUniformMatrix3fv(program, location, 1, transpose, data); break;
        case UniformType::Mat4: glProgramUniformMatrix4fv(program, location, 1, transpose, data); break;
        default: break;
    }
}

SemanticInputs semanticInputs(const GpuPass& gp, const FrameInputs& f) {
    const FrameCamera& camera = *f.camera;
    SemanticInputs in;
    in.world = toDouble(gp.model);
    in.view = toDouble(camera.view);
    in.projection = toDouble(camera.projection);
    in.fovYRadians = glm::radians(static_cast<double>(camera.lens.fovYDegrees));
    in.nearPlane = camera.lens.nearPlane;
    in.farPlane = camera.lens.farPlane;
    in.viewport = f.viewport;
    in.time = f.clock.time;
    in.deltaTime = f.clock.deltaTime;
    in.frame = f.frame;
    in.passIndex = gp.index;
    in.mouse = f.mouse;
    in.mouseButtons = f.mouseButtons;
    return in;
}

void uploadPredefined(const GpuPass& gp, const UniformSlot& u, const FrameInputs& f) {
    const FrameCamera& camera = *f.camera;
    const GLuint program = gp.program.get();
    const auto& p = std::get<BoundPredefined>(u.source);
    glm::vec2 targetSize = gp.target->resource->spec.size;
    auto mat4 = [&](const glm::mat4& m) {
        if (differs(u, glm::value_ptr(m), 16)) glProgramUniformMatrix4fv(program, u.location, 1, GL_FALSE, glm::value_ptr(m));
    };
    auto vec2 = [&](glm::vec2 v) {
        if (differs(u, glm::value_ptr(v), 2)) glProgramUniform2f(program, u.location, v.x, v.y);
    };
    auto scalar = [&](float v) {
        if (differs(u, &v, 1)) glProgramUniform1f(program, u.location, v);
    };
    switch (p.info.id) {
        case Predefined::ViewportSize: vec2(glm::vec2(f.viewport)); break;
        case Predefined::InvViewportSize: vec2(1.0f / glm::vec2(f.viewport)); break;
        case Predefined::TargetSize: vec2(targetSize); break;
        case Predefined::InvTargetSize: vec2(1.0f / targetSize); break;
        case Predefined::Time: scalar(f.clock.time); break;
        case Predefined::DeltaTime: scalar(f.clock.deltaTime); break;
        case Predefined::Frame:
            if (differs(u, &f.frame, 1)) glProgramUniform1i(program, u.location, f.frame);
            break;
        case Predefined::View: mat4(camera.view); break;
        case Predefined::Projection: mat4(camera.projection); break;
        case Predefined::ViewProjection: mat4(camera.viewProjection); break;
        case Predefined::InvView: mat4(camera.inverseView); break;
        case Predefined::InvProjection: mat4(camera.inverseProjection); break;
        case Predefined::InvViewProjection: mat4(camera.inverseViewProjection); break;
        case Predefined::Model: mat4(gp.model); break;
        case Predefined::ModelViewProjection: mat4(camera.viewProjection * gp.model); break;
        case Predefined::NormalMatrix: {
            glm::mat3 n = glm::inverseTranspose(glm::mat3(gp.model));
            if (differs(u, glm::value_ptr(n), 9)) glProgramUniformMatrix3fv(program, u.location, 1, GL_FALSE, glm::value_ptr(n));
            break;
        }
        case Predefined::CameraPosition: {
            const glm::vec3& c = camera.position;
            if (differs(u, glm::value_ptr(c), 3)) glProgramUniform3f(program, u.location, c.x, c.y, c.z);
            break;
        }
    }
}

}  // namespace

FrameCamera::FrameCamera(const OrbitCamera& camera, glm::ivec2 viewport)
    : view(camera.view()),
      projection(camera.projection(static_cast<float>(viewport.x) / static_cast<float>(viewport.y))),
      viewProjection(projection * view),
      inverseView(glm::inverse(view)),
      inverseProjection(glm::inverse(projection)),
      inverseViewProjection(glm::inverse(viewProjection)),
      position(camera.position()),
      lens(camera.settings()) {}

void uploadUniforms(const GpuPass& gp, const FrameInputs& f) {
    std::optional<SemanticInputs> semantics;
    const GLuint program = gp.program.get();
    for (const UniformSlot& u : gp.uniforms) {
        if (!u.effectSwitch.empty()) {
            const int on = f.switchedOff->count(u.effectSwitch) ? 0 : 1;
            if (differs(u, &on, 1)) glProgramUniform1i(program, u.location, on);
            continue;
        }
        if (u.semantic) {
            if (!semantics) semantics = semanticInputs(gp, f);
            uploadValue(program, u, semanticValue(*u.semantic, *semantics).data.data());
            continue;
        }
        if (u.value) {
            uploadValue(program, u, u.value->data.data());
            continue;
        }
        uploadPredefined(gp, u, f);
    }
}

}  // namespace rmfx
