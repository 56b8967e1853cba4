#include "run/ReplayRun.h"

#include <filesystem>
#include <optional>

#include "io/image/ImageIO.h"
#include "io/image/InputImage.h"
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

}  // namespace

Result<std::vector<Image>> renderReplayCase(const ReplayCase& c, const MediaOptions& media, HeadlessContexts* contexts) {
    using Rendered = Result<std::vector<Image>>;
    WorkspaceLoadOptions load;
    load.media = media;
    Result<Workspace> loaded = loadWorkspace(c.workspace, {}, load);
    Diagnostics diagnostics = loaded.takeDiagnostics();
    if (!loaded) return Rendered::failure(std::move(diagnostics));
    Workspace& ws = *loaded;
    applySets(c, ws, diagnostics);
    checkTargets(c, ws, diagnostics);
    if (hasErrors(diagnostics)) return Rendered::failure(std::move(diagnostics));
    RunSettings settings = c.run;
    ExecutorOptions options;
    if (!c.inputs.empty()) {
        std::optional<SuppliedInputs> supplied = supplyCaseInputs(c, ws, diagnostics);
        if (!supplied) return Rendered::failure(std::move(diagnostics));
        settings.size = supplied->viewport;
        options.givenInputs = supplied->given;
    }
    if (contexts)
        if (auto context = contexts->use(ws.profile); !context) {
            diagnostics.push_back({Diagnostic::Severity::Error, c.where, "<case name=\"" + c.name + "\">", context.error()});
            return Rendered::failure(std::move(diagnostics));
        }

    // Only what the compares read is computed, as rmfx render would for each target.
    options.effects = c.effects;
    for (const ReplayCompare& compare : c.compares)
        options.outputs.push_back(compare.target.empty() ? ws.outputTargetName() : compare.target);
    auto run = runHeadless(ws, settings, options);
    add(diagnostics, run.diagnostics());
    if (!run) return Rendered::failure(std::move(diagnostics));
    GlExecutor& executor = **run;
    std::vector<Image> images;
    for (const ReplayCompare& compare : c.compares) {
        std::string target = compare.target.empty() ? ws.outputTargetName() : compare.target;
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
