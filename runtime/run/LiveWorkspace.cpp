#include "run/LiveWorkspace.h"

#include <algorithm>

#include "frontend/rfx/RfxImporter.h"
#include "frontend/workspace/WorkspaceParser.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx {
namespace {

Diagnostics withSeverity(const Diagnostics& all, Diagnostic::Severity severity) {
    Diagnostics out;
    for (const Diagnostic& d : all)
        if (d.severity == severity) out.push_back(d);
    return out;
}

Diagnostics& append(Diagnostics& to, const Diagnostics& from) {
    to.insert(to.end(), from.begin(), from.end());
    return to;
}

bool sameCamera(const OrbitCameraSettings& a, const OrbitCameraSettings& b) {
    return a.target == b.target && a.distance == b.distance && a.yawDegrees == b.yawDegrees &&
           a.pitchDegrees == b.pitchDegrees && a.fovYDegrees == b.fovYDegrees && a.nearPlane == b.nearPlane &&
           a.farPlane == b.farPlane;
}

}  // namespace

LiveWorkspace::~LiveWorkspace() {
    executor_.reset();  // refers to workspace_
}

Result<std::unique_ptr<LiveWorkspace>> LiveWorkspace::open(const std::filesystem::path& file, glm::ivec2 viewport,
                                                           const std::vector<std::pair<std::string, std::string>>& overrides,
                                                           const WorkspaceLoadOptions& load,
                                                           std::vector<InputArgument> inputs, std::optional<LoadedRun> loaded) {
    std::unique_ptr<LiveWorkspace> live(new LiveWorkspace);
    live->loadOptions_ = load;
    live->inputs_ = std::move(inputs);
    live->file_ = file;
    live->requestedViewport_ = viewport;
    live->overrides_ = overrides;
    live->givenFirst_ = std::move(loaded);
    Result<Build> build = live->load();
    Diagnostics found = build.diagnostics();
    if (!build) return Result<std::unique_ptr<LiveWorkspace>>::failure(std::move(found));
    live->adopt(std::move(*build), withSeverity(found, Diagnostic::Severity::Warning));
    return {std::move(live), std::move(found)};
}

LiveWorkspace::Build LiveWorkspace::fromLoaded(LoadedRun loaded) const {
    Build build;
    build.argumentsApplied = true;
    build.supplied.viewport = loaded.viewport;
    build.supplied.given = std::move(loaded.givenInputs);
    build.workspace = std::make_shared<Workspace>(std::move(loaded.ws));
    build.programs = std::move(loaded.programs);
    return build;
}

Result<SuppliedInputs> LiveWorkspace::supply(Workspace& ws) const {
    std::optional<glm::ivec2> size;
    if (requestedViewport_ != glm::ivec2(0)) size = requestedViewport_;
    return supplyInputs(ws, inputs_, size);
}

std::string LiveWorkspace::inputName(const InputArgument& input) const {
    if (!input.name.empty()) return input.name;
    return workspace_ && workspace_->inputs.size() == 1 ? workspace_->inputs.front().name : "";
}

Result<LiveWorkspace::Build> LiveWorkspace::load(const std::set<std::string>& staleTextures) {
    failedDependencies_ = {};
    // Reloads leave the shaders to the GL compiler, whose messages are mapped to file and line
    // just as glslang's are: that halves the time a reload of the workspace file takes.
    ValidationOptions validation;
    validation.compileShaders = !executor_;
    CheckedPrograms programs;
    Result<Workspace> loaded = givenFirst_ ? Result<Workspace>(Workspace{}) : loadWorkspace(file_, validation, loadOptions_, &programs);
    Diagnostics diagnostics = loaded.diagnostics();
    if (!loaded) {
        // Watch what the broken file names too (a texture it names that is not there yet, say).
        Result<Workspace> parsed = isRfxPath(file_) ? importRfxFile(file_, {loadOptions_.effect, loadOptions_.rfxMatrices}) : parseWorkspaceFile(file_);
        if (parsed) failedDependencies_ = findWorkspaceDependencies(*parsed);
        return Result<Build>::failure(std::move(diagnostics));
    }
    Build build;
    if (givenFirst_) {
        build = fromLoaded(std::move(*givenFirst_));
        givenFirst_.reset();
    } else {
        build.workspace = std::make_shared<Workspace>(std::move(*loaded));
        build.programs = std::move(programs);
    }
    // Overrides from the command line: errors the first time; after that a variable the edited
    // file no longer declares only loses its override (the file stays loadable).
    for (const auto& override : build.argumentsApplied ? std::vector<std::pair<std::string, std::string>>{} : overrides_) {
        Diagnostics bad = applyOverrides(*build.workspace, {override}).diagnostics();
        if (!executor_)
            append(diagnostics, bad);
        else
            for (Diagnostic& d : bad) {
                d.severity = Diagnostic::Severity::Warning;
                d.message += " (the override is ignored)";
                diagnostics.push_back(d);
            }
    }
    build.dependencies = findWorkspaceDependencies(*build.workspace);
    if (!hasErrors(diagnostics) && !build.argumentsApplied) {
        Result<SuppliedInputs> supplied = supply(*build.workspace);
        append(diagnostics, supplied.diagnostics());
        if (supplied) build.supplied = std::move(*supplied);
    }
    if (hasErrors(diagnostics)) {
        failedDependencies_ = std::move(build.dependencies);
        return Result<Build>::failure(std::move(diagnostics));
    }
    // Watched before the build reads them: a save during the build is then seen, not lost.
    failedDependencies_ = build.dependencies;
    updateWatches();
    const glm::ivec2 viewport = build.supplied.viewport;
    const ExecutorOptions options = executorOptions(build);
    // Compiled with validation's programs: the file's shaders are assembled once per load.
    auto frame = compileFrame(build.workspace, options, viewport, kGuaranteedMaxTargetSize, &build.programs);
    if (!frame) return Result<Build>::failure(append(diagnostics, frame.takeDiagnostics()));
    if (executor_) {
        // Textures whose files did not change are copied from the running build, not decoded again.
        std::vector<std::string> reusable;
        for (const Texture& t : workspace_->textures)
            if (!pendingTextures_.count(t.name) && !staleTextures.count(t.name)) reusable.push_back(t.name);
        auto created = GlExecutor::createReusing(std::move(*frame), options, *executor_, reusable);
        append(diagnostics, created.diagnostics());
        if (!created) return Result<Build>::failure(std::move(diagnostics));
        build.executor = std::move(*created);
    } else {
        auto created = GlExecutor::create(std::move(*frame), options);
        append(diagnostics, created.diagnostics());
        if (!created) return Result<Build>::failure(std::move(diagnostics));
        build.executor = std::move(*created);
    }
    return {std::move(build), std::move(diagnostics)};
}

void LiveWorkspace::adopt(Build build, Diagnostics warnings) {
    Workspace& ws = *build.workspace;
    GlExecutor& exec = *build.executor;
    // The camera the user moved stays, unless the file's <camera> itself was edited.
    if (executor_ && sameCamera(workspace_->camera, ws.camera)) exec.camera() = executor_->camera();
    for (auto it = tweaks_.begin(); it != tweaks_.end();) {
        const std::string& name = it->first;
        const Variable* v = ws.findVariable(name);
        std::string why;
        if (!v)
            why = "the workspace no longer declares it";
        else if (v->value.type != it->second.type)
            why = std::string("it is now a ") + valueTypeName(v->value.type) + ", not a " + valueTypeName(it->second.type);
        else if (auto set = exec.setVariable(name, it->second); !set)
            why = set.error();
        if (why.empty()) {
            ++it;
            continue;
        }
        warnings.push_back({Diagnostic::Severity::Warning, v ? v->where : SourceLocation{ws.path.string(), 0},
                            "variable " + name, "the value you set (" + formatValue(it->second) + ") is dropped: " + why});
        it = tweaks_.erase(it);
    }
    executor_.reset();
    workspace_ = std::move(build.workspace);
    executor_ = std::move(build.executor);
    dependencies_ = std::move(build.dependencies);
    failedDependencies_ = {};
    // Everything was just read from the files as they are: nothing is left to retry.
    workspacePending_ = false;
    pendingPasses_.clear();
    pendingTextures_.clear();
    pendingModels_.clear();
    pendingInputs_.clear();
    failures_.clear();
    append(warnings_, warnings);
    updateWatches();
    collectErrors();
}

bool LiveWorkspace::rebuildWorkspace(const std::set<std::string>& staleTextures) {
    Result<Build> build = load(staleTextures);
    const Diagnostics& found = build.diagnostics();
    if (!build) {
        workspacePending_ = true;
        failures_["workspace"] = withSeverity(found, Diagnostic::Severity::Error);
        updateWatches();
        return false;
    }
    adopt(std::move(*build), withSeverity(found, Diagnostic::Severity::Warning));
    lastReload_.workspaceRebuilt = true;
    return true;
}

void LiveWorkspace::recompilePendingPasses() {
    std::vector<std::string> names;  // in schedule order
    for (const Pass& pass : workspace_->passes)
        if (pendingPasses_.count(pass.name)) names.push_back(pass.name);
    Diagnostics found = executor_->recompilePasses(names).takeDiagnostics();
    append(warnings_, withSeverity(found, Diagnostic::Severity::Warning));
    if (hasErrors(found)) {
        failures_["passes"] = withSeverity(found, Diagnostic::Severity::Error);
        lastReload_.failed = true;
        return;
    }
    failures_.erase("passes");
    pendingPasses_.clear();
    lastReload_.recompiledPasses = names;
}

void LiveWorkspace::reloadPendingTextures() {
    for (auto it = pendingTextures_.begin(); it != pendingTextures_.end();) {
        Diagnostics found = executor_->reloadTexture(*it).takeDiagnostics();
        if (hasErrors(found)) {
            failures_["texture " + *it] = found;
            lastReload_.failed = true;
            ++it;
            continue;
        }
        failures_.erase("texture " + *it);
        lastReload_.reloadedTextures.push_back(*it);
        it = pendingTextures_.erase(it);
    }
}

void LiveWorkspace::reloadPendingModels() {
    for (auto it = pendingModels_.begin(); it != pendingModels_.end();) {
        Diagnostics found = executor_->reloadModel(*it).takeDiagnostics();
        if (hasErrors(found)) {
            failures_["model " + *it] = found;
            lastReload_.failed = true;
            ++it;
            continue;
        }
        failures_.erase("model " + *it);
        lastReload_.reloadedModels.push_back(*it);
        it = pendingModels_.erase(it);
    }
}

void LiveWorkspace::reloadInputs(const std::set<std::string>& names) {
    Workspace next = *workspace_;
    Result<SuppliedInputs> supplied = supply(next);
    const Diagnostics& found = supplied.diagnostics();
    append(warnings_, withSeverity(found, Diagnostic::Severity::Warning));
    if (!supplied) {
        failures_["inputs"] = withSeverity(found, Diagnostic::Severity::Error);
        lastReload_.failed = true;
        return;
    }
    // An image that sets the viewport came at another size: every target is sized anew.
    if (supplied->viewport != executor_->viewport()) {
        if (rebuildWorkspace({})) lastReload_.reloadedInputs.assign(names.begin(), names.end());
        return;
    }
    for (const std::string& name : names) {
        std::shared_ptr<const Image> image = next.findTexture(name)->supplied;
        Diagnostics replaced = executor_->replaceInputImage(name, image).takeDiagnostics();
        if (hasErrors(replaced)) {
            failures_["inputs"] = std::move(replaced);
            lastReload_.failed = true;
            return;
        }
        // Kept with the build, so that a later build at another size reads the same image.
        workspace_->findTexture(name)->supplied = std::move(image);
        lastReload_.reloadedInputs.push_back(name);
    }
    failures_.erase("inputs");
    pendingInputs_.clear();
}

Result<void> LiveWorkspace::setInput(const InputArgument& input) {
    const std::vector<InputArgument> previous = inputs_;
    const std::string name = inputName(input);
    auto same = std::find_if(inputs_.begin(), inputs_.end(),
                             [&](const InputArgument& given) { return !name.empty() && inputName(given) == name; });
    if (same != inputs_.end())
        *same = input;
    else
        inputs_.push_back(input);
    Result<Build> build = load();
    Diagnostics found = build.diagnostics();
    if (!build) {
        inputs_ = previous;
        updateWatches();
        return Result<void>::failure(std::move(found));
    }
    warnings_.clear();
    adopt(std::move(*build), withSeverity(found, Diagnostic::Severity::Warning));
    lastReload_ = {};
    lastReload_.workspaceRebuilt = true;
    if (!name.empty()) lastReload_.reloadedInputs = {name};
    return found;
}

void LiveWorkspace::updateWatches() {
    // The workspace file as named too: when it is a symbolic link, replacing the link is a change.
    std::vector<std::filesystem::path> files{dependencyPath(file_), std::filesystem::absolute(file_).lexically_normal()};
    for (const InputArgument& input : inputs_) files.push_back(dependencyPath(input.file));
    for (const auto* deps : {&dependencies_, &failedDependencies_})
        for (const FileDependency& d : deps->files)
            if (std::find(files.begin(), files.end(), d.file) == files.end()) files.push_back(d.file);
    watcher_.watch(files);
}

void LiveWorkspace::collectErrors() {
    errors_.clear();
    if (auto it = failures_.find("workspace"); it != failures_.end()) append(errors_, it->second);
    for (const auto& [unit, found] : failures_)
        if (unit != "workspace") append(errors_, found);
}

bool LiveWorkspace::poll() {
    std::vector<std::filesystem::path> changed = watcher_.poll();
    // A file appearing next to the watched ones may be what a failed build was missing (a new
    // #include, say): retry what failed.
    bool retry = watcher_.sawOtherFileAppear() && !failures_.empty();
    if (changed.empty() && !retry) return false;
    FileWatcher::Clock::time_point start = watcher_.lastChangeTime();
    if (start == FileWatcher::Clock::time_point{}) start = FileWatcher::Clock::now();

    std::set<std::string> passes, textures, models, inputs;
    bool workspaceChanged = false;
    std::filesystem::path self = dependencyPath(file_);
    for (const auto& file : changed) {
        if (dependencyPath(file) == self) {
            workspaceChanged = true;
            continue;
        }
        for (const InputArgument& input : inputs_)
            if (dependencyPath(input.file) == dependencyPath(file)) inputs.insert(inputName(input));
        // Files only the broken workspace file names matter through its retry below.
        const FileDependency* dep = dependencies_.find(file);
        if (!dep) continue;
        switch (dep->kind) {
            case DependencyKind::Workspace: workspaceChanged = true; break;
            case DependencyKind::Shader:
            case DependencyKind::Include: passes.insert(dep->passes.begin(), dep->passes.end()); break;
            case DependencyKind::Texture: textures.insert(dep->textures.begin(), dep->textures.end()); break;
            case DependencyKind::Model:
                for (const std::string& pass : dep->passes)
                    if (const Pass* p = workspace_->findPass(pass)) models.insert(p->draw.file);
                break;
        }
    }
    bool workspaceRetry = workspacePending_ && (!changed.empty() || retry);
    bool attempted = workspaceChanged || workspaceRetry || !passes.empty() || !textures.empty() || !models.empty() ||
                     !inputs.empty() ||
                     (retry && (!pendingPasses_.empty() || !pendingTextures_.empty() || !pendingModels_.empty() ||
                                !pendingInputs_.empty()));
    if (!attempted) return false;

    lastReload_ = {};
    lastReload_.changedFiles = changed;
    warnings_.clear();
    bool rebuilt = (workspaceChanged || workspaceRetry) && rebuildWorkspace(textures);
    if (!rebuilt) {
        // The running build is kept; what else changed is rebuilt into it.
        pendingPasses_.insert(passes.begin(), passes.end());
        pendingTextures_.insert(textures.begin(), textures.end());
        pendingModels_.insert(models.begin(), models.end());
        if (!pendingPasses_.empty() && (!passes.empty() || retry)) recompilePendingPasses();
        if (!pendingTextures_.empty() && (!textures.empty() || retry)) reloadPendingTextures();
        if (!pendingModels_.empty() && (!models.empty() || retry)) reloadPendingModels();
        pendingInputs_.insert(inputs.begin(), inputs.end());
        // Last: an image of a new size builds the workspace anew, which reads everything else too.
        if (!pendingInputs_.empty() && (!inputs.empty() || retry)) reloadInputs(pendingInputs_);
        // Shaders may include other files now.
        dependencies_ = findWorkspaceDependencies(*workspace_);
        updateWatches();
    }
    collectErrors();
    lastReload_.failed = lastReload_.failed || (!rebuilt && workspacePending_);
    lastReloadMilliseconds_ =
        std::chrono::duration<double, std::milli>(FileWatcher::Clock::now() - start).count();
    return true;
}

GlExecutor& LiveWorkspace::executor() { return *executor_; }
const Workspace& LiveWorkspace::workspace() const { return *workspace_; }
const Diagnostics& LiveWorkspace::errors() const { return errors_; }
double LiveWorkspace::lastReloadMilliseconds() const { return lastReloadMilliseconds_; }
std::vector<std::filesystem::path> LiveWorkspace::watchedFiles() const { return watcher_.files(); }

Result<void> LiveWorkspace::setVariable(const std::string& name, const Value& value) {
    Result<void> set = executor_->setVariable(name, value);
    if (set) tweaks_[name] = value;
    return set;
}

void LiveWorkspace::resetVariable(const std::string& name) {
    tweaks_.erase(name);
    if (const Variable* v = workspace_->findVariable(name)) (void)executor_->setVariable(name, v->value);
}

ExecutorOptions LiveWorkspace::executorOptions(const Build& build) const {
    ExecutorOptions options;
    options.givenInputs = build.supplied.given;
    options.checkHealth = checkHealth_;
    return options;
}

Result<void> LiveWorkspace::setHealthCheck(bool on) {
    if (on == checkHealth_) return {};
    checkHealth_ = on;
    Result<void> rebuilt = setViewport(requestedViewport_);
    if (!rebuilt) checkHealth_ = !on;
    return rebuilt;
}

Result<void> LiveWorkspace::setViewport(glm::ivec2 viewport) {
    Diagnostics found;
    glm::ivec2 previous = requestedViewport_;
    requestedViewport_ = viewport;
    Build build;
    build.workspace = std::make_shared<Workspace>(*workspace_);
    build.dependencies = dependencies_;
    // The input images are read again: one that sets the viewport is resampled to the new size.
    Result<SuppliedInputs> supplied = supply(*build.workspace);
    found = supplied.takeDiagnostics();
    if (!supplied) {
        requestedViewport_ = previous;
        return Result<void>::failure(std::move(found));
    }
    build.supplied = std::move(*supplied);
    const ExecutorOptions options = executorOptions(build);
    auto created = GlExecutor::create(build.workspace, build.supplied.viewport, options);
    append(found, created.takeDiagnostics());
    if (!created) {
        requestedViewport_ = previous;
        return Result<void>::failure(std::move(found));
    }
    build.executor = std::move(*created);
    // The new build read every shader, image and model as they are now, but not the workspace
    // file: a failure of that stays.
    bool workspaceFailed = workspacePending_;
    Diagnostics workspaceErrors = failures_.count("workspace") ? failures_["workspace"] : Diagnostics{};
    WorkspaceDependencies failed = failedDependencies_;
    warnings_.clear();
    adopt(std::move(build), withSeverity(found, Diagnostic::Severity::Warning));
    if (workspaceFailed) {
        workspacePending_ = true;
        failures_["workspace"] = workspaceErrors;
        failedDependencies_ = std::move(failed);
        updateWatches();
        collectErrors();
    }
    return found;
}

}  // namespace rmfx
