#pragma once

namespace rmfx {

// Core: rmfx's own workspaces. Compatibility: a compatibility-profile context, for legacy GLSL
// and the fixed-function matrices and lights it reads (RenderMonkey imports).
enum class GlProfile { Core, Compatibility };

}  // namespace rmfx
