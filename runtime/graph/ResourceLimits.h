#pragma once
// Limits a workspace is held to before anything is allocated: a workspace (or a --size) that asks
// for a target larger than the GL can make, or for more GPU memory than the budget, fails with an
// error naming the target instead of exhausting the machine or tripping a GL error half-way.
#include <cstddef>

#include <glm/vec2.hpp>

#include "core/Diagnostic.h"
#include "core/Result.h"
#include "graph/TargetPlan.h"

namespace rmfx {

struct ResourceLimits {
    int maxTargetSize = 16384;  // the largest side of a texture or viewport (from the GL's GL_MAX_*)
    std::size_t memoryBudget = std::size_t(4) << 30;  // bytes of render-target memory a frame may hold
};

// The budget a run gets unless the user gives one (--memory-budget).
constexpr std::size_t kDefaultMemoryBudget = std::size_t(4) << 30;

// An error for a viewport with a side beyond the limit.
Result<void> checkViewportLimits(glm::ivec2 viewport, const ResourceLimits& limits, const SourceLocation& where);

// Errors for each planned target with a side beyond the limit, and for a plan whose memory
// exceeds the budget (naming the largest targets).
Result<void> checkPlanLimits(const TargetPlan& plan, const ResourceLimits& limits, const SourceLocation& workspace);

}  // namespace rmfx
