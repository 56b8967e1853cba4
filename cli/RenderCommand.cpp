#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <set>

#include "apps/ArgumentParser.h"
#include "cli/Commands.h"
#include "apps/OptionValues.h"
#include "compile/CompiledFrame.h"
#include "compile/RunPreparation.h"
#include "core/FrameWatchdog.h"
#include "frontend/rfx/RfxImporter.h"
#include "gl/GlContext.h"
#include "graph/FrameExplanation.h"
#include "io/image/ImageIO.h"
#include "io/image/ImageMemoryLimit.h"
#include "io/image/ImageOutputPath.h"
#include "io/media/ImageSequence.h"
#include "io/media/MediaArguments.h"
#include "model/EffectSelection.h"
#include "run/HeadlessRun.h"
#include "run/SequenceRun.h"
#include "validation/ImageInputs.h"
#include "validation/TextureArguments.h"
#include "validation/UnreadArguments.h"
#include "validation/WorkspaceLoader.h"
#include "io/image/ImageCodecs.h"

namespace rmfx::cli {

using namespace rmfx::apps;  // the shared argument loop and option values

namespace {

// --check found NaN or an infinity in a target (the image is written all the same).
constexpr int kExitUnhealthy = 4;

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
    std::vector<InputArgument> inputs;  // --input [NAME=]FILE
    double fps = 24.0;                  // a sequence's frame rate: dt = 1 / fps
    bool fpsGiven = false;
    bool dtGiven = false;
    int preroll = 0;                    // a sequence's frames of warm-up before the first output
    std::optional<std::pair<int, int>> frameRange;  // a sequence's frames written, by number
};

// With `names`, fills it with the parser's option names and parses nothing.
std::optional<RenderArguments> parseArguments(const std::vector<std::string>& args, std::vector<std::string>* names = nullptr) {
    RenderArguments a;
    a.run.frameBudgetSeconds = kDefaultFrameBudgetSeconds;
    using Empty = ArgumentParser::EmptyValue;
    ArgumentParser parser;
    parser.own([&](const std::vector<std::string>& all, size_t& i) { return takeMediaArgument(all, i, a.load.media); }, kMediaOptionNames)
        .option({"-o", "--output"}, [&](const std::string& value) { a.output = value; return ""; }, Empty::Allowed)
        .option({"--size"}, sizeValue(a.run.size), Empty::Allowed)
        .option({"--frames"}, frameCountValue(a.run.frames), Empty::Allowed)
        .option({"--dt"}, secondsValue(a.run.deltaTime, &a.dtGiven), Empty::Allowed)
        .option({"--preroll"}, [&](const std::string& value) -> std::string {
            char* end = nullptr;
            const long n = std::strtol(value.c_str(), &end, 10);
            if (value.empty() || *end || n < 0 || n > 100000)
                return "--preroll: expected a count of frames from 0 to 100000, got '" + value + "'";
            a.preroll = static_cast<int>(n);
            return "";
        })
        .option({"--frame-range"}, [&](const std::string& value) -> std::string {
            // A-B or a single frame A: frame numbers as in the file names.
            int first = 0, last = 0;
            char rest = 0;
            const int n = std::sscanf(value.c_str(), "%d-%d%c", &first, &last, &rest);
            const int single = n == 1 && value.find('-') == std::string::npos;
            if (single) last = first;
            if ((n != 2 && !single) || first < 0 || last < 0 || value.find_first_not_of("0123456789-") != std::string::npos)
                return "--frame-range: expected frame numbers FIRST-LAST (as in the file names, e.g. 1001-1012), got '" +
                       value + "'";
            if (first > last) return "--frame-range: " + value + ": the first frame comes after the last";
            a.frameRange = std::make_pair(first, last);
            return "";
        })
        .option({"--set"}, overrideValue(a.overrides), Empty::Allowed)
        .option({"--fps"}, [&](const std::string& value) -> std::string {
            char* end = nullptr;
            double fps = std::strtod(value.c_str(), &end);
            if (value.empty() || *end || !std::isfinite(fps) || fps <= 0 || fps > 10000)
                return "--fps: expected frames per second above 0, got '" + value + "'";
            a.fps = fps;
            a.fpsGiven = true;
            return "";
        })
        .option({"--input"}, inputValue(a.inputs))
        .option({"--texture"}, textureValue(a.load.textures))
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
        .option({"--rfx-matrices"}, rfxMatricesValue(a.load.rfxMatrices))
        .flag({"-q", "--quiet"}, [&] { a.quiet = true; })
        .flag({"--explain"}, [&] { a.explain = true; })
        .flag({"--check"}, [&] { a.executor.checkHealth = true; })
        .option({"--check-method"}, [&](const std::string& value) -> std::string {
            std::optional<HealthCheckMethod> method = parseHealthCheckMethod(value);
            if (!method) return "--check-method: expected auto, while-drawing or after-pass, got '" + value + "'";
            a.executor.healthCheckMethod = *method;
            a.executor.checkHealth = true;
            return "";
        })
        .flag({"--no-pool"}, [&] { a.executor.poolTargets = false; })
        .option({"--content-skip"}, [&](const std::string& value) -> std::string {
            if (value != "on" && value != "off") return "--content-skip: expected on or off, got '" + value + "'";
            a.executor.contentSkip = value == "on";
            return "";
        })
        .positional([&](const std::string& arg) -> std::string {
            if (a.workspace) return "one workspace at a time; got '" + *a.workspace + "' and '" + arg + "'";
            a.workspace = arg;
            return "";
        });
    if (names) {
        *names = parser.names();
        return std::nullopt;
    }
    if (std::string message = parser.parse(args); !message.empty()) {
        std::cerr << "rmfx render: " << message << "\n";
        return std::nullopt;
    }
    return a;
}

// A sequence's output pattern: one frame-number field, a known extension, a folder that takes files.
Result<void> checkSequenceOutput(const std::string& pattern) {
    Result<FramePattern> parsed = parseFramePattern(pattern);
    if (!parsed) return Error{"a sequence is written to a pattern such as out/frame.%04d.png (" + parsed.error() + ")"};
    return checkImageOutputPath(parsed->fileName(0));
}

// "[=======>      ] 12/30 frames, 4.1 fps, 4 s left" rewritten in place on a terminal; a plain
// line per frame otherwise (a log, CI).
void showProgress(const SequenceProgress& p, bool terminal) {
    if (p.done == 0 || p.seconds <= 0.0) return;
    const double fps = p.done / p.seconds;
    const int left = static_cast<int>(std::ceil((p.total - p.done) / fps));
    char line[160];
    if (terminal) {
        constexpr int width = 30;
        const int filled = p.done * width / p.total;
        std::string bar = std::string(static_cast<size_t>(filled), '=') + (filled < width ? ">" : "") +
                          std::string(static_cast<size_t>(std::max(0, width - filled - 1)), ' ');
        std::snprintf(line, sizeof line, "\r[%s] %d/%d frames, %.1f fps, %d s left ", bar.c_str(), p.done, p.total, fps, left);
        std::cerr << line << (p.done == p.total ? "\n" : "") << std::flush;
    } else {
        std::snprintf(line, sizeof line, "rmfx: %d/%d frames, %.1f fps, %d s left\n", p.done, p.total, fps, left);
        std::cerr << line;
    }
}

// rmfx render W --input scene=shot/frame.%04d.exr -o out/frame.%04d.png
// --check: what the passes left in their targets, on stderr (with -q only the errors); whether
// NaN or an infinity was found.
// The file each given <input> was given, as the user wrote it, for --explain.
std::map<std::string, std::string> givenFiles(const Workspace& ws, const std::vector<InputArgument>& inputs) {
    std::map<std::string, std::string> files;
    for (const InputArgument& given : inputs) {
        const std::string name = !given.name.empty() ? given.name : ws.inputs.size() == 1 ? ws.inputs.front().name : "";
        files[name] = given.file.string() + (given.layer.empty() ? "" : ":" + given.layer);
    }
    return files;
}

bool reportHealth(GlExecutor& executor, int frames, bool quiet) {
    const std::vector<HealthFinding>& findings = executor.firstHealthFindings();
    bool errors = false;
    for (const HealthFinding& f : findings) {
        errors = errors || healthKindIsError(f.kind);
        if (quiet && !healthKindIsError(f.kind)) continue;
        std::cerr << "rmfx: check: " << (healthKindIsError(f.kind) ? "error" : "warning") << ": frame " << f.frame
                  << ": " << describeFinding(f) << "\n";
    }
    if (quiet) return errors;
    const FrameHealth* last = executor.frameHealth();
    std::string uninspected;
    if (last)
        for (const PassHealth& p : last->passes)
            if (!p.inspected && uninspected.find("'" + p.target + "'") == std::string::npos)
                uninspected += (uninspected.empty() ? "'" : ", '") + p.target + "'";
    std::string found;
    for (HealthKind kind : allHealthKinds)
        if (std::none_of(findings.begin(), findings.end(), [&](const HealthFinding& f) { return f.kind == kind; }))
            found += (found.empty() ? "" : ", ") + std::string(healthKindName(kind));
    std::cerr << "rmfx: check: " << (last ? last->passes.size() : 0) << " passes a frame, " << frames
              << (frames == 1 ? " frame" : " frames") << (found.empty() ? "" : ": no " + found);
    if (!uninspected.empty())
        std::cerr << "; not inspected, their formats clamp what is written: " << uninspected;
    std::cerr << "\n";
    if (last) {
        long counting = std::count_if(last->passes.begin(), last->passes.end(), [](const PassHealth& p) { return p.countedWhileDrawing; });
        long after = std::count_if(last->passes.begin(), last->passes.end(),
                                   [](const PassHealth& p) { return p.inspected && !p.countedWhileDrawing; });
        std::cerr << "rmfx: check: " << counting << (counting == 1 ? " pass" : " passes")
                  << " counted what they wrote while drawing, " << after << " inspected after they ran\n";
        for (const PassHealth& p : last->passes)
            if (!p.whyNotWhileDrawing.empty())
                std::cerr << "rmfx: check: pass '" << p.pass << "' inspected after it ran: " << p.whyNotWhileDrawing << "\n";
    }
    return errors;
}

int renderSequenceCommand(const RenderArguments& a, const LoadedRun& loaded) {
    const Workspace& ws = loaded.ws;
    std::vector<InputArgument> sequences, statics;
    for (const InputArgument& input : a.inputs) (isSequencePattern(input.file.string()) ? sequences : statics).push_back(input);
    if (sequences.size() != 1) {
        std::cerr << "rmfx render: one --input may be a sequence; got " << sequences[0].text << " and " << sequences[1].text
                  << "\n";
        return 1;
    }
    const InputArgument& sequence = sequences.front();
    if (!a.output || !isSequencePattern(*a.output)) {
        std::cerr << "rmfx render: --input " << sequence.text
                  << " is a sequence: name the output frames with a pattern too (-o out/frame.%04d.png)\n";
        return 1;
    }
    if (Result<void> usable = checkSequenceOutput(*a.output); !usable) {
        std::cerr << "rmfx render: -o " << *a.output << ": " << usable.error() << "\n";
        return 1;
    }
    if (a.run.frames != 1) {
        std::cerr << "rmfx render: --frames does not apply to a sequence: it renders one frame per image "
                     "(--preroll N renders N frames of the first image before the first output)\n";
        return 1;
    }
    if (a.fpsGiven && a.dtGiven) {
        std::cerr << "rmfx render: --fps and --dt both set a sequence's time step (dt = 1 / fps): give one\n";
        return 1;
    }
    SequenceSettings settings;
    settings.input = sequence.name;
    settings.inputPattern = sequence.file.string();
    settings.layer = sequence.layer;
    settings.staticInputs = statics;
    settings.frameBudgetSeconds = a.run.frameBudgetSeconds;
    settings.onFrameBudget = a.run.onFrameBudget;
    settings.outputPattern = *a.output;
    settings.target = a.target.value_or("");
    settings.write.transform = a.transform.value_or(a.target ? DisplayTransform::None : ws.output.transform);
    settings.fps = a.fps;
    if (a.dtGiven) settings.deltaTime = a.run.deltaTime;
    settings.preroll = a.preroll;
    settings.frameRange = a.frameRange;
    settings.programs = &loaded.programs;
    if (a.run.size != glm::ivec2(0)) settings.size = a.run.size;
    auto context = GlContext::createHeadless(ws.profile);
    if (!context) {
        std::cerr << "rmfx render: " << context.error() << "\n";
        return 2;
    }
    const bool terminal = !a.quiet && isatty(STDERR_FILENO);
    Result<SequenceTimes> run = renderSequence(ws, settings, a.executor, [&](const SequenceProgress& p) {
        if (!a.quiet) showProgress(p, terminal);
    });
    if (!run) {
        if (terminal) std::cerr << "\n";
        std::cerr << formatAll(run.diagnostics());
        return 2;
    }
    if (!a.quiet) {
        std::cerr << formatAll(run.diagnostics());  // how the first image was decoded
        char summary[300];
        std::snprintf(summary, sizeof summary,
                      "rmfx: wrote %d frames to %s in %.1f s (%d frames of warm-up before them; reading %.1f s, rendering %.1f s, "
                      "writing %.1f s)\n",
                      run->frames, a.output->c_str(), run->total, run->warmUpFrames, run->read, run->render, run->write);
        std::cerr << summary;
    }
    return 0;
}

}  // namespace

std::vector<std::string> renderOptionNames() {
    std::vector<std::string> names;
    (void)parseArguments({}, &names);
    return names;
}

int renderCommand(const std::vector<std::string>& args) {
    auto a = parseArguments(args);
    if (!a) return 1;
    // The GL driver, then OpenImageIO, load on a thread of their own while the workspace parses
    // and validates; --explain alone needs neither (OpenImageIO only to read --input images).
    const bool explainOnly = a->explain && !a->output && !a->executor.checkHealth;
    if (!explainOnly) startLoadingImageCodecs(GlContext::prepareHeadlessDisplay);
    else if (!a->inputs.empty()) startLoadingImageCodecs();
    // An --input image too large to read is refused from its header before the workspace loads.
    for (const InputArgument& input : a->inputs) {
        if (isSequencePattern(input.file.string())) continue;
        if (Result<void> fits = checkImageFileMemory(input.file); !fits) {
            std::cerr << "rmfx render: --input " << input.text << ": " << fits.error() << "\n";
            return 1;
        }
    }
    // A given output is checked before anything is loaded; the default one (the workspace's
    // name) once it is known, still before any frame renders.
    if (a->output && !isSequencePattern(*a->output)) {
        if (Result<void> usable = checkImageOutputPath(*a->output); !usable) {
            std::cerr << "rmfx render: -o: " << usable.error() << "\n";
            return 1;
        }
    }
    if (!a->workspace && !a->load.effect.empty()) {
        std::cerr << "rmfx render: --effect chooses an effect of a RenderMonkey .rfx file; name the file\n";
        return 1;
    }
    RunRequest request;
    if (a->workspace) request.workspace = *a->workspace;
    request.load = a->load;
    request.overrides = a->overrides;
    request.inputs = a->inputs;
    request.size = a->run.size;
    Result<LoadedRun> loaded = loadRun(request);
    if (!loaded) {
        std::cerr << formatAll(loaded.diagnostics());
        return 1;
    }
    if (!a->quiet) std::cerr << formatAll(loaded.diagnostics());  // warnings
    Workspace& ws = loaded->ws;
    const bool sequence = std::any_of(a->inputs.begin(), a->inputs.end(),
                                      [](const InputArgument& i) { return isSequencePattern(i.file.string()); });
    if (sequence && a->executor.checkHealth) {
        std::cerr << "rmfx render: --check inspects a single run; for a sequence, check a frame of it on its own\n";
        return 1;
    }
    if (Result<std::set<std::string>> effects = selectEffects(ws, a->executor.effects); !effects) {
        std::cerr << "rmfx render: --effects: " << effects.error() << "\n";
        return 1;
    }
    // The names the arguments give, checked before any image is read or frame rendered.
    Result<std::vector<const ImageInput*>> named = resolveInputArguments(ws, a->inputs);
    if (!named) {
        std::cerr << formatAll(named.diagnostics());
        return 1;
    }
    if (a->target && !ws.canReadTarget(*a->target)) {
        std::cerr << "rmfx render: --target " << *a->target << ": the workspace has no such target ("
                  << ws.describeTargets() << ")\n";
        return 1;
    }
    if (!a->quiet) {
        FramePlanOptions planned = a->executor;
        for (const ImageInput* given : *named) planned.givenInputs.insert(given->name);
        std::cerr << formatAll(unreadArgumentWarnings(ws, planned, a->load.textures, a->inputs));
    }
    if (sequence) return renderSequenceCommand(*a, *loaded);
    if (a->preroll > 0) {
        std::cerr << "rmfx render: --preroll is for sequences (an --input frame pattern); a single render "
                     "runs --frames N frames and writes the last\n";
        return 1;
    }
    if (a->frameRange) {
        std::cerr << "rmfx render: --frame-range chooses frames of a sequence (an --input frame pattern)\n";
        return 1;
    }
    if (a->fpsGiven) {
        std::cerr << "rmfx render: --fps is a sequence's frame rate; a single render steps by --dt\n";
        return 1;
    }
    std::string targetName = a->target.value_or(ws.outputTargetName());
    std::string output = a->output.value_or(ws.name + ".png");
    if (isSequencePattern(output)) {
        std::cerr << "rmfx render: -o " << output << " is a frame pattern, but no --input is a sequence\n";
        return 1;
    }
    // A given -o was checked on the way in; the default is checked once its name is known
    // (--explain alone writes no image).
    if (!a->output && !a->explain) {
        if (Result<void> usable = checkImageOutputPath(output); !usable) {
            std::cerr << "rmfx render: -o: " << usable.error() << "\n";
            return 1;
        }
    }
    if (Result<void> read = readRunInputs(*loaded, request); !read) {
        std::cerr << formatAll(read.diagnostics());
        return 1;
    } else if (!a->quiet) {
        std::cerr << formatAll(read.diagnostics());  // how each file was decoded
    }
    a->executor.outputs = {targetName};
    request.plan = a->executor;
    Result<PreparedRun> prepared = compileRun(std::move(*loaded), request);  // `ws` is the prepared run's from here
    if (!prepared) {
        std::cerr << formatAll(prepared.diagnostics());
        return 2;
    }
    // --explain alone (no image, no --check) prints the plan: no GL context, no frame.
    if (a->explain && !a->output && !a->executor.checkHealth) {
        const CompiledFrame& frame = *prepared->frame;
        FrameExplanationInput explained = explanationOf(frame, switchedOffEffects(frame.ws(), frame.plan.askedEffects, frame.values));
        explained.inputFiles = givenFiles(frame.ws(), a->inputs);
        std::cout << explainFrame(explained);
        return 0;
    }

    auto context = GlContext::createHeadless(prepared->ws().profile);
    if (!context) {
        std::cerr << "rmfx render: " << context.error() << "\n";
        return 2;
    }
    RunSettings settings = a->run;
    settings.size = prepared->viewport();
    auto run = runHeadless(*prepared, settings, a->executor);
    if (!run) {
        std::cerr << formatAll(run.diagnostics());
        return 2;
    }
    if (!a->quiet) std::cerr << formatAll(run.diagnostics());  // warnings (streams no shader reads…)
    std::unique_ptr<GlExecutor>& executor = *run;
    const bool unhealthy = a->executor.checkHealth && reportHealth(*executor, a->run.frames, a->quiet);
    if (a->explain) {
        FrameExplanationInput explained = explanationOf(executor->compiledFrame(), executor->switchedOffEffects());
        explained.frameRan = true;
        explained.contentSkipped = executor->contentSkippedEffects(true);
        explained.inputFiles = givenFiles(prepared->ws(), a->inputs);
        std::cout << explainFrame(explained);
        if (!a->output) return unhealthy ? kExitUnhealthy : 0;  // --explain alone writes no image
    }
    auto image = executor->readTarget(targetName);
    if (!image) {
        std::cerr << "rmfx render: " << image.error() << "\n";
        return 2;
    }
    DisplayTransform transform = a->transform.value_or(a->target ? DisplayTransform::None : prepared->ws().output.transform);
    WriteOptions write;
    write.transform = transform;
    // RenderMonkey's window showed the back buffer's colour only; the alpha an imported effect's
    // shaders wrote would turn into transparency in an image viewer.
    write.integerOpaque = isRfxPath(prepared->ws().path) && !a->target;
    if (auto written = writeImage(output, *image, write); !written) {
        std::cerr << "rmfx render: " << written.error() << "\n";
        return 2;
    }
    if (!a->quiet)
        std::cerr << "rmfx: wrote " << output << " (" << image->width << "x" << image->height << ", target '"
                  << targetName << "', " << a->run.frames << (a->run.frames == 1 ? " frame" : " frames") << ", "
                  << (*context)->description() << ")\n";
    return unhealthy ? kExitUnhealthy : 0;
}

}  // namespace rmfx::cli
