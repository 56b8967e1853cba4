#include "model/PredefinedVariables.h"

namespace rmfx {

namespace {
constexpr PredefinedInfo table[] = {
    {Predefined::ViewportSize, "rm_ViewportSize", UniformType::Vec2, "viewport width and height in pixels"},
    {Predefined::InvViewportSize, "rm_InvViewportSize", UniformType::Vec2, "1 / viewport size"},
    {Predefined::TargetSize, "rm_TargetSize", UniformType::Vec2, "size of the target the pass draws into"},
    {Predefined::InvTargetSize, "rm_InvTargetSize", UniformType::Vec2, "1 / target size (one texel)"},
    {Predefined::Time, "rm_Time", UniformType::Float, "seconds since the first frame"},
    {Predefined::DeltaTime, "rm_DeltaTime", UniformType::Float, "seconds since the previous frame"},
    {Predefined::Frame, "rm_Frame", UniformType::Int, "frame index, 0 for the first frame"},
    {Predefined::View, "rm_View", UniformType::Mat4, "world to view"},
    {Predefined::Projection, "rm_Projection", UniformType::Mat4, "view to clip"},
    {Predefined::ViewProjection, "rm_ViewProjection", UniformType::Mat4, "world to clip"},
    {Predefined::InvView, "rm_InvView", UniformType::Mat4, "view to world"},
    {Predefined::InvProjection, "rm_InvProjection", UniformType::Mat4, "clip to view"},
    {Predefined::InvViewProjection, "rm_InvViewProjection", UniformType::Mat4, "clip to world"},
    {Predefined::Model, "rm_Model", UniformType::Mat4, "model to world, from <draw translate rotate scale>"},
    {Predefined::ModelViewProjection, "rm_ModelViewProjection", UniformType::Mat4, "model to clip"},
    {Predefined::NormalMatrix, "rm_NormalMatrix", UniformType::Mat3, "inverse transpose of rm_Model's 3x3"},
    {Predefined::CameraPosition, "rm_CameraPosition", UniformType::Vec3, "camera position in world space"},
};
}  // namespace

std::span<const PredefinedInfo> predefinedVariables() { return table; }

std::optional<PredefinedInfo> findPredefined(std::string_view name) {
    for (const auto& info : table)
        if (name == info.name) return info;
    return std::nullopt;
}

}  // namespace rmfx
