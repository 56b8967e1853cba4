#pragma once
// Values the runtime fills every frame. Shaders declare the ones they use, e.g.
// `uniform vec2 rm_ViewportSize;`. Names start with rm_, which workspaces may not use.

#include <optional>
#include <span>
#include <string_view>

#include "model/UniformType.h"

namespace rmfx {

enum class Predefined {
    ViewportSize, InvViewportSize, TargetSize, InvTargetSize, Time, DeltaTime, Frame,
    View, Projection, ViewProjection, InvView, InvProjection, InvViewProjection,
    Model, ModelViewProjection, NormalMatrix, CameraPosition
};

struct PredefinedInfo {
    Predefined id;
    const char* name;
    UniformType type;
    const char* meaning;
};

std::span<const PredefinedInfo> predefinedVariables();
std::optional<PredefinedInfo> findPredefined(std::string_view name);

}  // namespace rmfx
