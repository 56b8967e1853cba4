#include <cmath>
#include <iostream>
#include <optional>

#include "cli/ArgumentParser.h"
#include "cli/Commands.h"
#include "cli/OptionValues.h"
#include "core/FrameWatchdog.h"
#include "frontend/rfx/RfxImporter.h"
#include "gl/GlContext.h"
#include "graph/FrameExplanation.h"
#include "io/image/ImageIO.h"
#include "io/media/MediaArguments.h"
#include "model/EffectSelection.h"
#include "run/HeadlessRun.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::cli {

namespace {

struct RenderArguments {
    std::optional<std::string> workspace;
    std::optional<std::string> output;
    RunSettings run;
    std::vector<std::pair<std::string, std::string>> overrides;
    std::optional<std::string> target;
    WorkspaceLoadOptions load;  // --effect NAME (.rfx files), --media, --sandbox
    std::optional<DisplayTransform> transform;
    bool quiet = false;
    bool explain = false;
    ExecutorOptions executor;
};

std::optional<RenderArguments> parseArguments(const std::vector<std::string>& args) {
    RenderArguments a;
    a.run.frameBudgetSeconds = kDefaultFrameBudgetSeconds;
    using Empty = ArgumentParser::EmptyValue;
    ArgumentParser parser;
    parser.own([&](const std::vector<std::string>& all, size_t& i) { return takeMediaArgument(all, i, a.load.media); })
        .option({"-o", "--output"}, [&](const std::string& value) { a.output = value; return ""; }, Empty::Allowed)
        .option({"--size"}, sizeValue(a.run.size), Empty::Allowed)
        .option({"--frames"}, frameCountValue(a.run.frames), Empty::Allowed)
        .option({"--dt"}, secondsValue(a.run.deltaTime), Empty::Allowed)
        .option({"--set"}, overrideValue(a.overrides), Empty::Allowed)
        .option({"--target"}, [&](const std::string& value) { a.target = value; return ""; }, Empty::Allowed)
        .option({"--transform"}, [&](const std::string& value) -> std::string {
            if (value == "none") a.transform = DisplayTransform::None;
            else if (value == "srgb") a.transform = DisplayTransform::Srgb;
            else return "--transform: expected none or srgb, got '" + value + "'";
            return "";
        }, Empty::Allowed)
        .option({"--effects"}, [&](const std::string& value) -> std::string {
            if (value.find_first_not_of(", ") == std::string::npos && !value.empty())
                return "--effects: expected names separated by commas, got '" + value + "'";
            a.executor.effects = splitNameList(value);
            return "";
        }, Empty::Allowed)
        .option({"--memory-budget"}, [&](const std::string& value) -> std::string {
            char* end = nullptr;
            double mib = std::strtod(value.c_str(), &end);
            if (*end || !std::isfinite(mib) || mib <= 0 || mib > 1048576)
                return "--memory-budget: expected MiB of render-target memory (up to 1048576), got '" + value + "'";
            a.executor.memoryBudget = static_cast<std::size_t>(mib * 1048576.0);
            return "";
        }, Empty::Allowed)
        .option({"--frame-budget"}, [&](const std::string& value) -> std::string {
            char* end = nullptr;
            double seconds = std::strtod(value.c_str(), &end);
            if (*end || !std::isfinite(seconds) || seconds < 0)
                return "--frame-budget: expected seconds ≥ 0 (0: no limit), got '" + value + "'";
            a.run.frameBudgetSeconds = seconds;
            return "";
        }, Empty::Allowed)
        .option({"--effect"}, [&](const std::string& value) { a.load.effect = value; return ""; }, Empty::Allowed)
        .flag({"-q", "--quiet"}, [&] { a.quiet = true; })
        .flag({"--explain"}, [&] { a.explain = true; })
        .flag({"--no-pool"}, [&] { a.executor.poolTargets = false; })
        .positional([&](const std::string& arg) -> std::string {
            if (a.workspace) return "one workspace at a time; got '" + *a.workspace + "' and '" + arg + "'";
            a.workspace = arg;
            return "";
        });
    if (std::string message = parser.parse(args); !message.empty()) {
        std::cerr << "rmfx render: " << message << "\n";
        return std::nullopt;
    }
    return a;
}

}  // namespace

int renderCommand(const std::vector<std::string>& args) {
    auto a = parseArguments(args);
    if (!a) return 1;
    if (!a->workspace && !a->load.effect.empty()) {
        std::cerr << "rmfx render: --effect chooses an effect of a RenderMonkey .rfx file; name the file\n";
        return 1;
    }
    Result<Workspace> loaded = a->workspace ? loadWorkspace(*a->workspace, {}, a->load) : loadDefaultWorkspace({}, a->load.media);
    if (!loaded) {
        std::cerr << formatAll(loaded.diagnostics());
        return 1;
    }
    if (!a->quiet) std::cerr << formatAll(loaded.diagnostics());  // warnings
    Workspace& ws = *loaded;
    if (Result<void> set = applyOverrides(ws, a->overrides); !set) {
        std::cerr << formatAll(set.diagnostics());
        return 1;
    }
    std::string targetName = a->target.value_or(ws.outputTargetName());
    if (a->target && !ws.canReadTarget(*a->target)) {
        std::cerr << "rmfx render: --target " << *a->target << ": the workspace has no such target ("
                  << ws.describeTargets() << ")\n";
        return 1;
    }
    std::string output = a->output.value_or(ws.name + ".png");
    a->executor.outputs = {targetName};

    auto context = GlContext::createHeadless(ws.profile);
    if (!context) {
        std::cerr << "rmfx render: " << context.error() << "\n";
        return 2;
    }
    auto run = runHeadless(ws, a->run, a->executor);
    if (!run) {
        std::cerr << formatAll(run.diagnostics());
        return 2;
    }
    if (!a->quiet) std::cerr << formatAll(run.diagnostics());  // warnings (streams no shader reads…)
    std::unique_ptr<GlExecutor>& executor = *run;
    if (a->explain) {
        FrameExplanationInput explained{&ws, &executor->graph(), &executor->targetPlan(), executor->askedEffects(),
                                        executor->switchedOffEffects(), a->executor.poolTargets};
        std::cout << explainFrame(explained);
        if (!a->output) return 0;  // --explain alone writes no image
    }
    auto image = executor->readTarget(targetName);
    if (!image) {
        std::cerr << "rmfx render: " << image.error() << "\n";
        return 2;
    }
    DisplayTransform transform = a->transform.value_or(a->target ? DisplayTransform::None : ws.output.transform);
    WriteOptions write;
    write.transform = transform;
    // RenderMonkey's window showed the back buffer's colour only; the alpha an imported effect's
    // shaders wrote would turn into transparency in an image viewer.
    write.integerOpaque = isRfxPath(ws.path) && !a->target;
    if (auto written = writeImage(output, *image, write); !written) {
        std::cerr << "rmfx render: " << written.error() << "\n";
        return 2;
    }
    if (!a->quiet)
        std::cerr << "rmfx: wrote " << output << " (" << image->width << "x" << image->height << ", target '"
                  << targetName << "', " << a->run.frames << (a->run.frames == 1 ? " frame" : " frames") << ", "
                  << (*context)->description() << ")\n";
    return 0;
}

}  // namespace rmfx::cli
