#pragma once
// A workspace that follows its files: hot reload for the editor. Watches every file the
// workspace depends on (WorkspaceDependencies, FileWatcher) and, when one changes, rebuilds only
// what it feeds: a shader or include file recompiles the passes whose programs read it, an image
// reloads its texture, a model its mesh; the workspace file loads, validates and builds a new
// executor, keeping the values the user tweaked and the camera.
//
// A failed rebuild of any kind leaves the running build untouched (its programs, textures and
// the last frame it rendered) and reports why in errors(), with file and line. What failed is
// retried with every later change to its files, so the next good save recovers without a restart.
// Needs the GL context the executor was built in to be current when poll() is called.

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "core/Diagnostic.h"
#include "core/Result.h"
#include "compile/RunPreparation.h"
#include "core/Value.h"
#include "frontend/workspace/WorkspaceDependencies.h"
#include "gl/GlExecutor.h"
#include "io/file/FileWatcher.h"
#include "io/media/MediaResolver.h"
#include "model/Workspace.h"
#include "validation/ImageInputs.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx {

// What the last poll() that found changes did.
struct ReloadReport {
    std::vector<std::filesystem::path> changedFiles;  // as the watcher reported them
    bool workspaceRebuilt = false;                    // a new executor replaced the old one
    std::vector<std::string> recompiledPasses;        // passes whose new programs were swapped in
    std::vector<std::string> reloadedTextures;
    std::vector<std::string> reloadedModels;          // model files, as the passes name them
    std::vector<std::string> reloadedInputs;          // <input>s whose image was read anew
    bool failed = false;                              // something could not be rebuilt: see errors()
};

class LiveWorkspace {
public:
    // Loads (runtime/WorkspaceLoader: loadWorkspace + applyOverrides), validates and builds the
    // workspace for `viewport` (0,0 = the workspace's size), watching every file it depends on.
    // Fails with the diagnostics when the FIRST build fails (nothing good to keep yet); a success
    // carries the first build's warnings. `inputs` are images for the workspace's <input>s (rmfx
    // edit --input), supplied at every build as rmfx render supplies them: a viewport of 0,0 then
    // takes the size of the image that sets it. `loaded`: the file as the caller already loaded it
    // for the same arguments (loadRun and readRunInputs, compile/RunPreparation.h), which the
    // first build takes instead of loading the file again.
    static Result<std::unique_ptr<LiveWorkspace>> open(const std::filesystem::path& file, glm::ivec2 viewport,
                                                       const std::vector<std::pair<std::string, std::string>>& overrides,
                                                       const WorkspaceLoadOptions& load = {},
                                                       std::vector<InputArgument> inputs = {},
                                                       std::optional<LoadedRun> loaded = std::nullopt);
    ~LiveWorkspace();
    LiveWorkspace(const LiveWorkspace&) = delete;
    LiveWorkspace& operator=(const LiveWorkspace&) = delete;

    // errors(): what failed to rebuild and still runs from its last good build (the workspace
    // file, the passes of a shader change, a texture, a model), with file and line; it empties
    // as each is rebuilt from a good save, and once nothing failed it is empty.
    bool poll();                        // non-blocking: handles changes seen since the last call; true if something was rebuilt (or a rebuild failed)
    GlExecutor& executor();             // the last good build
    const Workspace& workspace() const; // the workspace of the last good build
    const Diagnostics& errors() const;  // diagnostics of the last failed reload; empty after a good one
    Result<void> setVariable(const std::string& name, const Value& value);  // as GlExecutor::setVariable, and remembered across reloads
    void resetVariable(const std::string& name);  // back to the file's default, forgets the tweak
    double lastReloadMilliseconds() const;        // from the file event to the end of the rebuild
    std::vector<std::filesystem::path> watchedFiles() const;

    // Additions to the editor's API.
    // Warnings of the last rebuild: a tweaked value dropped because its variable is gone or
    // changed type, validation warnings. Errors are in errors().
    const Diagnostics& warnings() const { return warnings_; }
    const ReloadReport& lastReload() const { return lastReload_; }
    const std::map<std::string, Value>& tweakedValues() const { return tweaks_; }
    // Builds the workspace anew for another viewport size (0,0 = the workspace's size), keeping
    // tweaks and camera; on failure the old build stays and the diagnostics say why.
    Result<void> setViewport(glm::ivec2 viewport);
    // The numeric health check (rmfx render --check) in this build and the next ones: builds the
    // workspace anew as setViewport does; on failure the check stays as it was.
    Result<void> setHealthCheck(bool on);
    bool healthCheck() const { return checkHealth_; }
    // The input images. Their files are watched like textures: a changed file replaces its input's
    // image without a rebuild, unless the image sets the viewport and its size changed (then the
    // workspace is built anew at the new size); an unreadable one keeps the last image, with the
    // error in errors() until a good save.
    const std::vector<InputArgument>& inputs() const { return inputs_; }
    // Gives an input an image (a file dropped on the editor): replaces the argument for the same
    // input, or adds one, and builds the workspace anew. On failure nothing changes and the
    // diagnostics say why; on success they carry the warnings (how the file was decoded).
    Result<void> setInput(const InputArgument& input);
    // Which input an argument names (an empty name: the workspace's only input); "" for none.
    std::string inputName(const InputArgument& input) const;
    // The watcher's own problems (inotify limits), one sentence each; watching goes on by time stamp.
    const std::vector<std::string>& watcherErrors() const { return watcher_.errors(); }

private:
    bool checkHealth_ = false;
    struct Build {
        std::shared_ptr<Workspace> workspace;  // shared with the executor
        std::unique_ptr<GlExecutor> executor;
        WorkspaceDependencies dependencies;
        SuppliedInputs supplied;  // what the input images gave: the viewport, the inputs given
        CheckedPrograms programs;  // validation's, for the compile step
        bool argumentsApplied = false;  // the overrides and input images are in `workspace` already
    };
    std::optional<LoadedRun> givenFirst_;  // open()'s `loaded`, until the first build takes it

    LiveWorkspace() = default;
    // Loads, validates and builds the workspace file; on failure fills failedDependencies_ with
    // what the broken file names, so that those files are watched too.
    // Textures named in staleTextures changed on disk: not copied from the running build.
    Result<Build> load(const std::set<std::string>& staleTextures = {});
    // The first build's workspace from what open() was given.
    Build fromLoaded(LoadedRun loaded) const;
    bool rebuildWorkspace(const std::set<std::string>& staleTextures);
    void adopt(Build build, Diagnostics warnings);
    void recompilePendingPasses();
    void reloadPendingTextures();
    void reloadPendingModels();
    void reloadInputs(const std::set<std::string>& names);
    // Reads the input images into `ws`, as the run's viewport asks (supplyInputs).
    Result<SuppliedInputs> supply(Workspace& ws) const;
    // What every executor of this session is built with: the inputs the build was given, the check.
    ExecutorOptions executorOptions(const Build& build) const;

    void updateWatches();
    void collectErrors();

    std::filesystem::path file_;
    glm::ivec2 requestedViewport_{0};
    std::vector<std::pair<std::string, std::string>> overrides_;
    WorkspaceLoadOptions loadOptions_;  // the .rfx effect chosen with --effect; media as the first load
    std::vector<InputArgument> inputs_;

    std::shared_ptr<Workspace> workspace_;  // shared with executor_
    std::unique_ptr<GlExecutor> executor_;
    WorkspaceDependencies dependencies_;
    WorkspaceDependencies failedDependencies_;  // of a workspace file that failed to build
    FileWatcher watcher_;

    std::map<std::string, Value> tweaks_;
    // What failed and is retried with the next change: the workspace file, passes (as one group,
    // all or nothing), textures, model files.
    bool workspacePending_ = false;
    std::set<std::string> pendingPasses_, pendingTextures_, pendingModels_, pendingInputs_;
    std::map<std::string, Diagnostics> failures_;  // "workspace", "passes", "texture NAME", "model FILE", "input NAME"
    Diagnostics errors_, warnings_;
    ReloadReport lastReload_;
    double lastReloadMilliseconds_ = 0.0;
};

}  // namespace rmfx
