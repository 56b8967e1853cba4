#include "gl/GlUniformUpload.h"

#include <epoxy/gl.h>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace rmfx {
namespace {

glm::dmat4 toDouble(const glm::mat4& m) { return glm::dmat4(m); }

// A value's first components into a uniform of the given type (a vec3 takes a vec4's xyz).
void uploadValue(GLuint program, GLint location, UniformType type, const float* data, bool transposed = false) {
    const GLboolean transpose = transposed ? GL_TRUE : GL_FALSE;
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
    auto mat4 = [&](const glm::mat4& m) { glProgramUniformMatrix4fv(program, u.location, 1, GL_FALSE, glm::value_ptr(m)); };
    auto vec2 = [&](glm::vec2 v) { glProgramUniform2f(program, u.location, v.x, v.y); };
    switch (p.info.id) {
        case Predefined::ViewportSize: vec2(glm::vec2(f.viewport)); break;
        case Predefined::InvViewportSize: vec2(1.0f / glm::vec2(f.viewport)); break;
        case Predefined::TargetSize: vec2(targetSize); break;
        case Predefined::InvTargetSize: vec2(1.0f / targetSize); break;
        case Predefined::Time: glProgramUniform1f(program, u.location, f.clock.time); break;
        case Predefined::DeltaTime: glProgramUniform1f(program, u.location, f.clock.deltaTime); break;
        case Predefined::Frame: glProgramUniform1i(program, u.location, f.frame); break;
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
            glProgramUniformMatrix3fv(program, u.location, 1, GL_FALSE, glm::value_ptr(n));
            break;
        }
        case Predefined::CameraPosition: {
            const glm::vec3& c = camera.position;
            glProgramUniform3f(program, u.location, c.x, c.y, c.z);
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
            glProgramUniform1i(program, u.location, f.switchedOff->count(u.effectSwitch) ? 0 : 1);
            continue;
        }
        if (u.semantic) {
            if (!semantics) semantics = semanticInputs(gp, f);
            uploadValue(program, u.location, u.type, semanticValue(*u.semantic, *semantics).data.data(), u.transposed);
            continue;
        }
        if (u.value) {
            uploadValue(program, u.location, u.type, u.value->data.data());
            continue;
        }
        uploadPredefined(gp, u, f);
    }
}

}  // namespace rmfx
