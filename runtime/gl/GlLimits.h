#pragma once
// The current context's own limits, for ResourceLimits (graph/), which checks a plan against them.

namespace rmfx {

// The smallest of GL_MAX_TEXTURE_SIZE, GL_MAX_RENDERBUFFER_SIZE and GL_MAX_VIEWPORT_DIMS.
// Needs a current GL context.
int queryMaxTargetSize();

}  // namespace rmfx
