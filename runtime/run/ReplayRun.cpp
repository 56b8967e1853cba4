#include "run/ReplayRun.h"

#include <filesystem>

#include "io/image/ImageIO.h"
#include "run/HeadlessRun.h"
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
    if (contexts)
        if (auto context = contexts->use(ws.profile); !context) {
            diagnostics.push_back({Diagnostic::Severity::Error, c.where, "<case name=\"" + c.name + "\">", context.error()});
            return Rendered::failure(std::move(diagnostics));
        }

    // Only what the compares read is computed, as rmfx render would for each target.
    ExecutorOptions options;
    options.effects = c.effects;
    for (const ReplayCompare& compare : c.compares)
        options.outputs.push_back(compare.target.empty() ? ws.outputTargetName() : compare.target);
    auto run = runHeadless(ws, c.run, options);
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
