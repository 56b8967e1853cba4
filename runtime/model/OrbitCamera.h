#pragma once
// The orbit camera behind the predefined view and projection matrices: yaw and pitch around a
// target point at a distance. The editor drives it with the mouse; headless runs use the
// workspace's <camera> settings.

#include <optional>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "model/Workspace.h"

namespace rmfx {

// The orbit settings (target, distance, yaw, pitch, roll) of a camera at `eye` looking at `target`
// with `up` (any vector not along the view: its part across the view sets the roll); the other
// settings are `base`'s. Nullopt when eye and target coincide. The pitch is kept within ±89°.
std::optional<OrbitCameraSettings> orbitLookingAt(glm::vec3 eye, glm::vec3 target, glm::vec3 up,
                                                  const OrbitCameraSettings& base);

class OrbitCamera {
public:
    explicit OrbitCamera(const OrbitCameraSettings& settings = {}) : settings_(settings) {}

    glm::vec3 position() const;
    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;

    void orbit(float yawDegrees, float pitchDegrees);  // pitch stays within ±89°
    void pan(glm::vec2 viewFractions);                 // moves the target in the view plane
    void zoom(float factor);                           // distance × factor, kept positive
    void reset(const OrbitCameraSettings& settings) { settings_ = settings; }
    const OrbitCameraSettings& settings() const { return settings_; }

private:
    OrbitCameraSettings settings_;
};

}  // namespace rmfx
