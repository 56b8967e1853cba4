#include "run/ReplayRun.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>

#include "io/file/FileNamePart.h"
#include "io/image/ImageIO.h"
#include "io/image/InputImage.h"
#include "compile/RunPreparation.h"
#include "run/HeadlessRun.h"
#include "validation/ImageInputs.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx {

namespace {

void add(Diagnostics& to, const Diagnostics& from) { to.insert(to.end(), from.begin(), from.end()); }

// <set> values go through applyOverrides one at a time, so that each problem points at its <set>.
void applySets(const ReplayCase& c, Workspace& ws, Diagnostics& diagnostics) {
    for (const ReplaySet& set : c.sets)
        for (const Diagnostic& d : applyOverrides(ws, {{set.name, set.value}}).takeDiagnostics())
            diagnostics.push_back(
                {d.severity, set.where, "<set name=\"" + set.name + "\">", "case '" + c.name + "': " + d.message});
}

// <input>s go through supplyInputs as rmfx render --input does; each problem points at its <input>.
std::optional<SuppliedInputs> supplyCaseInputs(const ReplayCase& c, Workspace& ws, Diagnostics& diagnostics) {
    std::vector<InputArgument> arguments;
    for (const ReplayInput& input : c.inputs) {
        InputArgument a;
        a.name = input.name;
        auto [file, layer] = splitLayerSuffix(input.file.string());
        a.file = file;
        a.layer = layer;
        a.text = input.fileText;
        arguments.push_back(std::move(a));
    }
    const bool sized = c.run.size != glm::ivec2(0);
    Result<SuppliedInputs> supplied = supplyInputs(ws, arguments, sized ? std::optional(c.run.size) : std::nullopt);
    for (const Diagnostic& d : supplied.diagnostics()) {
        const ReplayInput* input = &c.inputs.front();
        for (size_t i = 0; i < arguments.size(); ++i)
            if (d.element == "--input " + arguments[i].text) input = &c.inputs[i];
        diagnostics.push_back({d.severity, input->where, input->label(), "case '" + c.name + "': " + d.message});
    }
    if (!supplied) return std::nullopt;
    return std::move(*supplied);
}

void checkTargets(const ReplayCase& c, const Workspace& ws, Diagnostics& diagnostics) {
    for (const ReplayCompare& compare : c.compares)
        if (!compare.target.empty() && !ws.canReadTarget(compare.target))
            diagnostics.push_back({Diagnostic::Severity::Error, compare.where,
                                   "<compare target=\"" + compare.target + "\">",
                                   "case '" + c.name + "': the workspace has no render target '" + compare.target +
                                       "' (" + ws.describeTargets() + ")"});
}

// The case's workspace loaded, its <set>s and <input>s applied, and the context of its profile
// current: what renderReplayCase and renderReplayTargets share. nullopt when errors stop it.
struct PreparedCase {
    LoadedRun loaded;
    RunSettings settings;
    ExecutorOptions options;

    // Compiles the frame with validation's programs and renders the case's frames.
    Result<std::unique_ptr<GlExecutor>> run() {
        RunRequest request;
        request.size = settings.size;
        request.plan = options;
        Result<PreparedRun> prepared = compileRun(std::move(loaded), request);
        if (!prepared) return Result<std::unique_ptr<GlExecutor>>::failure(prepared.takeDiagnostics());
        return runHeadless(*prepared, settings, options);
    }
};

std::optional<PreparedCase> prepareCase(const ReplayCase& c, const MediaOptions& media, HeadlessContexts* contexts,
                                        Diagnostics& diagnostics) {
    RunRequest request;
    request.workspace = c.workspace;
    request.load.media = media;
    Result<LoadedRun> loaded = loadRun(request);
    add(diagnostics, loaded.takeDiagnostics());
    if (!loaded) return std::nullopt;
    PreparedCase prepared{std::move(*loaded), c.run, {}};
    Workspace& ws = prepared.loaded.ws;
    applySets(c, ws, diagnostics);
    checkTargets(c, ws, diagnostics);
    if (hasErrors(diagnostics)) return std::nullopt;
    if (!c.inputs.empty()) {
        std::optional<SuppliedInputs> supplied = supplyCaseInputs(c, ws, diagnostics);
        if (!supplied) return std::nullopt;
        // Read here, so that each problem names its <input>: the run's own reading is skipped.
        prepared.loaded.inputsRead = true;
        prepared.loaded.viewport = supplied->viewport;
        prepared.loaded.givenInputs = supplied->given;
    }
    if (contexts)
        if (auto context = contexts->use(ws.profile); !context) {
            diagnostics.push_back({Diagnostic::Severity::Error, c.where, "<case name=\"" + c.name + "\">", context.error()});
            return std::nullopt;
        }
    prepared.options.effects = c.effects;
    return prepared;
}

}  // namespace

Result<std::vector<Image>> renderReplayCase(const ReplayCase& c, const MediaOptions& media, HeadlessContexts* contexts) {
    using Rendered = Result<std::vector<Image>>;
    Diagnostics diagnostics;
    std::optional<PreparedCase> prepared = prepareCase(c, media, contexts, diagnostics);
    if (!prepared) return Rendered::failure(std::move(diagnostics));
    const std::string outputTarget = prepared->loaded.ws.outputTargetName();
    // Only what the compares read is computed, as rmfx render would for each target.
    for (const ReplayCompare& compare : c.compares)
        prepared->options.outputs.push_back(compare.target.empty() ? outputTarget : compare.target);
    prepared->options.checkHealth = c.check;
    auto run = prepared->run();
    add(diagnostics, run.diagnostics());
    if (!run) return Rendered::failure(std::move(diagnostics));
    GlExecutor& executor = **run;
    for (const HealthFinding& f : executor.firstHealthFindings())
        diagnostics.push_back({healthKindIsError(f.kind) ? Diagnostic::Severity::Error : Diagnostic::Severity::Warning,
                               c.where, "<case name=\"" + c.name + "\" check=\"true\">",
                               "frame " + std::to_string(f.frame) + ": " + describeFinding(f)});
    if (hasErrors(diagnostics)) return Rendered::failure(std::move(diagnostics));
    std::vector<Image> images;
    for (const ReplayCompare& compare : c.compares) {
        std::string target = compare.target.empty() ? outputTarget : compare.target;
        auto image = executor.readTarget(target);
        if (!image) {
            diagnostics.push_back({Diagnostic::Severity::Error, compare.where, "<compare>",
                                   "case '" + c.name + "': " + image.error()});
            return Rendered::failure(std::move(diagnostics));
        }
        images.push_back(std::move(*image));
    }
    return Rendered(std::move(images), std::move(diagnostics));
}

Result<std::vector<CaseTarget>> renderReplayTargets(const ReplayCase& c, const MediaOptions& media,
                                                    HeadlessContexts* contexts) {
    using Rendered = Result<std::vector<CaseTarget>>;
    Diagnostics diagnostics;
    std::optional<PreparedCase> prepared = prepareCase(c, media, contexts, diagnostics);
    if (!prepared) return Rendered::failure(std::move(diagnostics));
    // No outputs named: every target a running pass writes can be read, and none shares memory.
    auto run = prepared->run();
    add(diagnostics, run.diagnostics());
    if (!run) return Rendered::failure(std::move(diagnostics));
    GlExecutor& executor = **run;
    const Workspace& ws = executor.workspace();
    std::map<std::string, std::pair<size_t, std::string>> lastWriter;  // target → (position, pass)
    const std::vector<std::string>& passes = executor.passesRun();
    for (size_t i = 0; i < passes.size(); ++i)
        if (const Pass* pass = ws.findPass(passes[i])) lastWriter[ws.passTargetName(*pass)] = {i, passes[i]};
    std::vector<std::pair<size_t, CaseTarget>> ordered;
    for (const auto& [target, writer] : lastWriter) {
        auto image = executor.readTarget(target);
        if (!image) {
            diagnostics.push_back({Diagnostic::Severity::Error, c.where, "<case name=\"" + c.name + "\">",
                                   "target '" + target + "': " + image.error()});
            return Rendered::failure(std::move(diagnostics));
        }
        ordered.push_back({writer.first, {target, writer.second, std::move(*image), target == ws.outputTargetName()}});
    }
    std::sort(ordered.begin(), ordered.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<CaseTarget> targets;
    for (auto& [position, target] : ordered) targets.push_back(std::move(target));
    return Rendered(std::move(targets), std::move(diagnostics));
}

std::filesystem::path caseTargetsFolder(const ReplayCase& c) {
    std::filesystem::path first = c.compares.empty() ? c.workspace : c.compares.front().reference;
    return first.parent_path() / (c.name + ".targets");
}

std::filesystem::path caseTargetFile(const ReplayCase& c, const std::string& target) {
    return caseTargetsFolder(c) / (fileNamePart(target) + ".exr");
}

FirstDifference findFirstDifference(const ReplayCase& c, const std::vector<CaseTarget>& targets,
                                    const CompareLimits& limits) {
    FirstDifference found;
    for (size_t i = 0; i < targets.size(); ++i) {
        const CaseTarget& t = targets[i];
        std::filesystem::path file = caseTargetFile(c, t.target);
        if (!std::filesystem::exists(file)) {
            found.unstored.push_back(t.target);
            continue;
        }
        const CompareLimits* own = &limits;
        for (const ReplayCompare& compare : c.compares)
            if (compare.target.empty() ? t.isOutput : compare.target == t.target) own = &compare.limits;
        ImageComparison comparison;
        if (auto reference = readImage(file); !reference) {
            comparison.metric = own->metric;
            comparison.problem = "cannot read the stored target: " + reference.error();
        } else {
            comparison = compareImages(t.image, *reference, *own);
        }
        if (comparison.passed()) {
            found.matched.push_back(t.target);
            continue;
        }
        found.target = &t;
        found.comparison = std::move(comparison);
        found.position = static_cast<int>(i) + 1;
        return found;
    }
    return found;
}

ImageComparison compareWithReference(const Image& actual, const ReplayCompare& compare) {
    auto reference = readImage(compare.reference);
    if (!reference) {
        ImageComparison failed;
        failed.metric = compare.limits.metric;
        failed.problem = "cannot read the reference: " + reference.error() +
                         (std::filesystem::exists(compare.reference) ? "" : " (rmfx replay --update writes it)");
        return failed;
    }
    return compareImages(actual, *reference, compare.limits);
}

Result<void> storeReference(const Image& actual, const ReplayCompare& compare) {
    std::error_code ec;
    if (compare.reference.has_parent_path()) std::filesystem::create_directories(compare.reference.parent_path(), ec);
    if (ec) return Error{compare.reference.string() + ": cannot create the folder: " + ec.message()};
    WriteOptions options;
    options.exrHalf = compare.storeHalf;
    return writeImage(compare.reference, actual, options);
}

}  // namespace rmfx
