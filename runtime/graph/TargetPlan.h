#pragma once
// Which render targets a frame allocates, and which share memory. A target is allocated only when a
// scheduled pass writes or reads it. Targets of the same size, format, mipmaps and depth whose
// lifetimes (first write to last read, counted in passes) do not overlap share one texture: the
// greedy interval assignment of Filament's frame graph. Outputs live to the end of the frame;
// targets that carry contents from frame to frame get memory of their own. One plan serves several
// graphs (every combination of effect switches), so switching an effect never reallocates: a
// lifetime spans the uses of all of them. Pure: no GL.

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "core/Result.h"
#include "core/Value.h"
#include "graph/PassGraph.h"
#include "model/Workspace.h"

namespace rmfx {

struct PlannedTarget {
    std::string name;
    const RenderTarget* spec = nullptr;  // null for the implicit output
    TargetFormat format = TargetFormat::RGBA16F;
    glm::ivec2 size{1};
    bool mipmaps = false;
    bool depth = false;     // a scheduled pass tests or writes depth in it
    bool history = false;   // read with frame="previous": two buffers
    bool carried = false;   // contents must survive between frames: never shared
    glm::vec4 initial{0.0f};
    SourceLocation where;
    bool used = false;      // a scheduled pass writes or reads it
    int firstUse = -1, lastUse = -1;  // indices of passes (Workspace::passes); the pass count for outputs
    int resource = -1;      // index into TargetPlan::resources; -1 when not allocated
    std::size_t bytes = 0;  // memory it would need on its own
};

struct TargetResource {
    TargetFormat format = TargetFormat::RGBA16F;
    glm::ivec2 size{1};
    bool mipmaps = false, depth = false, history = false;
    glm::vec4 initial{0.0f};
    std::size_t bytes = 0;
    std::vector<int> targets;  // indices into TargetPlan::targets, in order of use
};

struct TargetPlan {
    std::vector<PlannedTarget> targets;  // declared order, then the implicit output
    std::vector<TargetResource> resources;
    std::size_t declaredBytes = 0;   // every declared target with memory of its own
    std::size_t allocatedBytes = 0;  // the resources: the GPU memory the frame holds at its peak

    int find(const std::string& name) const;  // -1 when there is no such target
};

// `values` picks the formats of format-by targets (an error when a value picks none); with `pool`
// off every used target gets memory of its own.
Result<TargetPlan> planTargets(const Workspace& ws, const std::vector<const PassGraph*>& graphs, glm::ivec2 viewport,
                               const std::map<std::string, Value>& values, bool pool);

// Colour levels (with the mip chain) × buffers, plus a 32-bit depth buffer when asked.
std::size_t targetBytes(TargetFormat format, glm::ivec2 size, bool mipmaps, bool depth, bool history);

}  // namespace rmfx
