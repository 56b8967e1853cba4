#pragma once
// RmCamera → rmfx's orbit camera settings.

#include "frontend/rfx/detail/RfxElement.h"
#include "model/Workspace.h"

namespace rmfx::rfx {

// The orbit camera that sees what the RmCamera sees: its target is the LOOK_AT point, its distance
// the camera's distance from it, yaw and pitch the direction from the target to the camera, its
// roll UP_VECTOR's (model/OrbitCamera.h orbitLookingAt); the pitch is kept within ±89°. FOV is
// taken as the vertical field of view in degrees.
OrbitCameraSettings orbitFromRmCamera(const RfxElement& camera);

}  // namespace rmfx::rfx
