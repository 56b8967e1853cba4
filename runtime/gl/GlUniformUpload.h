#pragma once
// Uploads a pass's uniforms before it draws: effect switches, semantics, variables and constants,
// and the predefined matrices and sizes. Needs a current GL context.

#include <set>
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "gl/GpuPass.h"
#include "model/OrbitCamera.h"

namespace rmfx {

struct FrameClock {
    float time = 0.0f;       // seconds since the first frame
    float deltaTime = 0.0f;  // seconds since the previous frame
};

// The camera's matrices, computed once per frame for every pass that uploads them.
struct FrameCamera {
    glm::mat4 view, projection, viewProjection, inverseView, inverseProjection, inverseViewProjection;
    glm::vec3 position;
    OrbitCameraSettings lens;

    FrameCamera(const OrbitCamera& camera, glm::ivec2 viewport);
};

// What a frame gives every pass.
struct FrameInputs {
    FrameClock clock;
    int frame = 0;
    const FrameCamera* camera = nullptr;
    glm::ivec2 viewport{1};
    glm::dvec2 mouse{0.0};
    glm::ivec3 mouseButtons{0};
    const std::set<std::string>* switchedOff = nullptr;  // effects off this frame
};

void uploadUniforms(const GpuPass& pass, const FrameInputs& frame);

}  // namespace rmfx
