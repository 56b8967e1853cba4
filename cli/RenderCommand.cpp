#include <cmath>
#include <iostream>
#include <optional>

#include "cli/Commands.h"
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
    WorkspaceLoadOptions load;  // --effect NAME (.rfx files)
    std::optional<DisplayTransform> transform;
    bool quiet = false;
    bool explain = false;
    ExecutorOptions executor;
    MediaOptions media;
};

std::optional<RenderArguments> parseArguments(const std::vector<std::string>& args) {
    RenderArguments a;
    a.run.frameBudgetSeconds = kDefaultFrameBudgetSeconds;
    auto fail = [](const std::string& message) -> std::optional<RenderArguments> {
        std::cerr << "rmfx render: " << message << "\n";
        return std::nullopt;
    };
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        auto next = [&]() -> std::optional<std::string> {
            if (i + 1 >= args.size()) return std::nullopt;
            return args[++i];
        };
        if (auto media = takeMediaArgument(args, i, a.media)) {
            if (!media->empty()) return fail(*media);
        } else if (arg == "-o" || arg == "--output" || arg == "--size" || arg == "--frames" || arg == "--dt" ||
            arg == "--set" || arg == "--target" || arg == "--transform" || arg == "--effects" ||
            arg == "--memory-budget" || arg == "--frame-budget" || arg == "--effect") {
            auto value = next();
            if (!value) return fail(arg + " needs a value");
            if (arg == "-o" || arg == "--output") {
                a.output = *value;
            } else if (arg == "--size") {
                int w = 0, h = 0;
                char x = 0, extra = 0;
                if (std::sscanf(value->c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' || w < 1 || h < 1 ||
                    w > 16384 || h > 16384)
                    return fail("--size: expected WIDTHxHEIGHT between 1x1 and 16384x16384, got '" + *value + "'");
                a.run.size = {w, h};
            } else if (arg == "--frames") {
                char* end = nullptr;
                long n = std::strtol(value->c_str(), &end, 10);
                if (*end || n < 1 || n > 1000000) return fail("--frames: expected a count from 1 to 1000000, got '" + *value + "'");
                a.run.frames = static_cast<int>(n);
            } else if (arg == "--dt") {
                char* end = nullptr;
                double dt = std::strtod(value->c_str(), &end);
                if (*end || !std::isfinite(dt) || dt < 0) return fail("--dt: expected seconds ≥ 0, got '" + *value + "'");
                a.run.deltaTime = static_cast<float>(dt);
            } else if (arg == "--set") {
                auto eq = value->find('=');
                if (eq == std::string::npos || eq == 0) return fail("--set: expected NAME=VALUE, got '" + *value + "'");
                a.overrides.emplace_back(value->substr(0, eq), value->substr(eq + 1));
            } else if (arg == "--target") {
                a.target = *value;
            } else if (arg == "--frame-budget") {
                char* end = nullptr;
                double seconds = std::strtod(value->c_str(), &end);
                if (*end || !std::isfinite(seconds) || seconds < 0)
                    return fail("--frame-budget: expected seconds ≥ 0 (0: no limit), got '" + *value + "'");
                a.run.frameBudgetSeconds = seconds;
            } else if (arg == "--memory-budget") {
                char* end = nullptr;
                double mib = std::strtod(value->c_str(), &end);
                if (*end || !std::isfinite(mib) || mib <= 0 || mib > 1048576)
                    return fail("--memory-budget: expected MiB of render-target memory (up to 1048576), got '" + *value + "'");
                a.executor.memoryBudget = static_cast<std::size_t>(mib * 1048576.0);
            } else if (arg == "--effect") {
                a.load.effect = *value;
            } else if (arg == "--effects") {
                if (value->find_first_not_of(", ") == std::string::npos && !value->empty())
                    return fail("--effects: expected names separated by commas, got '" + *value + "'");
                a.executor.effects = splitNameList(*value);
            } else {
                if (*value == "none") a.transform = DisplayTransform::None;
                else if (*value == "srgb") a.transform = DisplayTransform::Srgb;
                else return fail("--transform: expected none or srgb, got '" + *value + "'");
            }
        } else if (arg == "-q" || arg == "--quiet") {
            a.quiet = true;
        } else if (arg == "--explain") {
            a.explain = true;
        } else if (arg == "--no-pool") {
            a.executor.poolTargets = false;
        } else if (!arg.empty() && arg[0] == '-') {
            return fail("unknown option '" + arg + "' (see rmfx --help)");
        } else if (a.workspace) {
            return fail("one workspace at a time; got '" + *a.workspace + "' and '" + arg + "'");
        } else {
            a.workspace = arg;
        }
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
    ValidationOptions options;
    options.media = a->media;
    Result<Workspace> loaded = a->workspace ? loadWorkspace(*a->workspace, options, a->load) : loadDefaultWorkspace(options);
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
