#pragma once
// One way from a request to a run: the workspace loaded and validated (validation keeps the
// programs it assembled and compiled), the overrides applied, the input images read, the frame
// compiled with validation's programs. What rmfx render, sequences, replay, the editor, bench and
// the library's callers all do before any GL object exists, so each shader is read, assembled and
// compiled by glslang once per run. No GL: a prepared run goes to GlExecutor::create.
//
//   Result<PreparedRun> run = prepareRun(request);         // all at once, or step by step with
//   Result<LoadedRun> loaded = loadRun(request);           // a caller's own checks between the
//   ... check loaded->ws against its arguments ...         // steps (rmfx render refuses a --target
//   readRunInputs(*loaded, request);                       // the workspace lacks before it reads
//   Result<PreparedRun> run = compileRun(std::move(*loaded), request);   // any image)

#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "compile/CompiledFrame.h"
#include "core/Result.h"
#include "graph/FramePlan.h"
#include "model/Workspace.h"
#include "validation/ImageInputs.h"
#include "validation/Validation.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx {

struct RunRequest {
    std::optional<std::filesystem::path> workspace;  // none: the built-in default workspace
    WorkspaceLoadOptions load;                        // --effect, --media, --sandbox, --texture, --rfx-matrices
    ValidationOptions validation;
    std::vector<std::pair<std::string, std::string>> overrides;  // --set NAME=VALUE
    std::vector<InputArgument> inputs;                // --input [NAME=]FILE: single images
    glm::ivec2 size{0};                               // --size; 0: the first scene image's, else the workspace's
    FramePlanOptions plan;                            // outputs, --effects, --memory-budget, --check …
};

// A workspace as loaded, validated and overridden, with validation's programs.
struct LoadedRun {
    Workspace ws;
    CheckedPrograms programs;
    bool inputsRead = false;        // readRunInputs ran
    glm::ivec2 viewport{0};         // then: the size the run renders at
    std::set<std::string> givenInputs;  // and the inputs an image was given for
};

struct PreparedRun {
    std::shared_ptr<const CompiledFrame> frame;  // its workspace holds the input images
    FramePlanOptions plan;                       // as asked, with the inputs given images

    const Workspace& ws() const { return frame->ws(); }
    glm::ivec2 viewport() const { return frame->viewport; }
};

// Loads and validates the workspace and applies the overrides. Errors and warnings of each step,
// each said once.
Result<LoadedRun> loadRun(const RunRequest& request);

// Reads the input images into their textures (how each file decoded comes back as a warning) and
// decides the run's size: request.size, else the first scene image's, else the workspace's.
Result<void> readRunInputs(LoadedRun& loaded, const RunRequest& request);

// Compiles the frame at the run's size with validation's programs (reading the inputs first
// where readRunInputs has not).
Result<PreparedRun> compileRun(LoadedRun loaded, const RunRequest& request);

Result<PreparedRun> prepareRun(const RunRequest& request);

}  // namespace rmfx
