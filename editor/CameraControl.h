#pragma once
// Mouse gestures over the effect image turned into OrbitCamera moves. Pixel deltas are in window
// coordinates (x right, y down), as GLFW and ImGui report them.

#include <glm/vec2.hpp>

#include "model/OrbitCamera.h"

namespace rmfx::editor {

inline constexpr float orbitDegreesPerPixel = 0.3f;
inline constexpr float zoomFactorPerWheelStep = 0.9f;

// Left drag: dragging right turns the scene right (the camera's yaw decreases), dragging down
// raises the camera (pitch increases), orbitDegreesPerPixel each.
void orbitByDrag(OrbitCamera& camera, glm::vec2 deltaPixels);

// Right or middle drag: the point under the cursor in the target's plane follows the cursor.
// viewportHeight is the effect image's height in pixels.
void panByDrag(OrbitCamera& camera, glm::vec2 deltaPixels, int viewportHeight);

// Wheel: each step forward (positive) brings the camera zoomFactorPerWheelStep closer.
void zoomByWheel(OrbitCamera& camera, float wheelSteps);

}  // namespace rmfx::editor
