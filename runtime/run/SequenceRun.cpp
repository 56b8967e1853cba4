#include "run/SequenceRun.h"

#include "compile/CompiledFrame.h"

#include <chrono>
#include <future>
#include <memory>
#include <optional>
#include <system_error>
#include <tuple>

#include "io/image/InputImage.h"
#include "io/media/ImageSequence.h"
#include "io/media/SequenceChunk.h"
#include "run/FrameStepper.h"
#include "validation/ImageInputs.h"

namespace rmfx {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

struct ReadFrame {
    Result<Image> image = Error{""};
    double seconds = 0.0;
};

// One image of the sequence at the size the first one was given at.
ReadFrame readFrame(const std::filesystem::path& file, const std::string& layer, glm::ivec2 size) {
    Clock::time_point start = Clock::now();
    ReadFrame out;
    Result<InputImage> read = readInputImage(file, layer);
    if (!read) {
        out.image = Error{read.error()};
    } else if (read->image.width != size.x || read->image.height != size.y) {
        Result<Image> resampled = resampleImage(read->image, size.x, size.y);
        out.image = resampled ? Result<Image>(std::move(*resampled)) : Result<Image>(Error{file.string() + ": " + resampled.error()});
    } else {
        out.image = std::move(read->image);
    }
    out.seconds = secondsSince(start);
    return out;
}

struct WrittenFrame {
    Result<void> written;
    double seconds = 0.0;
};

WrittenFrame writeFrame(const std::filesystem::path& file, const Image& image, const WriteOptions& options) {
    Clock::time_point start = Clock::now();
    WrittenFrame out{writeImage(file, image, options)};
    out.seconds = secondsSince(start);
    return out;
}

}  // namespace

Result<SequenceTimes> renderSequence(const Workspace& source, const SequenceSettings& settings, ExecutorOptions options,
                                     const std::function<void(const SequenceProgress&)>& progress) {
    using Run = Result<SequenceTimes>;
    const Clock::time_point started = Clock::now();
    const std::string argument = (settings.input.empty() ? "" : settings.input + "=") + settings.inputPattern;
    // Errors of the run as a whole name the workspace and the argument, as supplyInputs' do.
    auto runError = [&](std::string element, std::string message) {
        return Run::failure(Diagnostics{{Diagnostic::Severity::Error, {source.path.string(), 0}, std::move(element), std::move(message)}});
    };
    Result<std::vector<SequenceFrame>> frames = findSequenceFrames(settings.inputPattern);
    if (!frames) return runError("--input " + argument, frames.error());
    Result<FramePattern> output = parseFramePattern(settings.outputPattern);
    if (!output)
        return runError("-o " + settings.outputPattern,
                        "a sequence is written to a pattern such as out/frame.%04d.png (" + output.error() + ")");
    if (!(settings.fps > 0.0)) return runError("--fps", "must be above 0");
    if (settings.deltaTime && !(*settings.deltaTime >= 0.0)) return runError("--dt", "must be 0 or more");
    if (settings.preroll < 0) return runError("--preroll", "must be 0 or more");
    // The written frames: indices first … last of the shot; the chunk's warm-up reads before them.
    int first = 0, last = static_cast<int>(frames->size()) - 1;
    if (settings.frameRange) {
        Result<std::pair<int, int>> range = selectFrameRange(*frames, *settings.frameRange);
        if (!range) return runError("--frame-range", range.error());
        std::tie(first, last) = *range;
    }
    const SequenceChunk chunk = planSequenceChunk(first, settings.preroll);

    // The first frame goes through supplyInputs with the static images: it picks the input, sets
    // the viewport and says how each file was decoded.
    Workspace ws = source;
    std::vector<InputArgument> given{{settings.input, (*frames)[size_t(chunk.start)].path, settings.layer, argument, nullptr}};
    given.insert(given.end(), settings.staticInputs.begin(), settings.staticInputs.end());
    const Clock::time_point firstRead = Clock::now();
    Result<SuppliedInputs> supplied = supplyInputs(ws, given, settings.size);
    const double firstReadSeconds = secondsSince(firstRead);
    if (!supplied) return Run::failure(std::move(supplied).diagnostics());
    Diagnostics warnings = supplied.takeDiagnostics();
    const std::string input = settings.input.empty() ? ws.inputs.front().name : settings.input;
    const glm::ivec2 viewport = supplied->viewport;
    // Later frames come at the first one's size as supplied: the viewport's when the input sets
    // it, else its own.
    const Image& firstImage = *ws.findTexture(input)->supplied;
    const glm::ivec2 frameSize(firstImage.width, firstImage.height);
    options.givenInputs = supplied->given;
    const std::string target = settings.target.empty() ? ws.outputTargetName() : settings.target;
    if (!ws.canReadTarget(target)) return runError("--target " + target, "the workspace has no such target (" + ws.describeTargets() + ")");
    if (options.outputs.empty()) options.outputs = {target};
    auto compiled = compileFrame(std::make_shared<const Workspace>(ws), options, viewport, kGuaranteedMaxTargetSize, settings.programs);
    if (!compiled) return Run::failure(compiled.takeDiagnostics());
    auto created = GlExecutor::create(std::move(*compiled), options);
    if (!created) return Run::failure(created.takeDiagnostics());
    std::unique_ptr<GlExecutor> executor = std::move(*created);

    SequenceTimes times;
    times.frames = last - first + 1;
    times.warmUpFrames = settings.preroll;
    times.read = firstReadSeconds;
    const float dt = static_cast<float>(settings.deltaTime.value_or(1.0 / settings.fps));
    const std::launch policy = settings.overlap ? std::launch::async : std::launch::deferred;
    std::future<ReadFrame> next;
    std::future<WrittenFrame> writing;
    std::filesystem::path writingFile;
    // Waits for the write under way; its error ends the run.
    auto finishWrite = [&]() -> Result<void> {
        if (!writing.valid()) return {};
        WrittenFrame done = writing.get();
        times.write += done.seconds;
        if (!done.written) return Error{writingFile.string() + ": " + done.written.error()};
        return {};
    };
    auto fail = [&](const std::string& message) {
        Result<void> pending = finishWrite();  // the frames before this one are written all the same
        std::string all = message;
        if (!pending) all = pending.error() + "\n" + all;
        Diagnostics d = warnings;
        d.push_back({Diagnostic::Severity::Error, {source.path.string(), 0}, "--input " + argument, all});
        return Run::failure(std::move(d));
    };
    FrameStepper stepper(dt, settings.frameBudgetSeconds, settings.onFrameBudget);
    for (int p = 0; p < chunk.preroll; ++p) {
        const std::string label = "pre-roll frame " + std::to_string(p + 1) + " of " + std::to_string(chunk.preroll);
        Clock::time_point renderStart = Clock::now();
        Result<void> rendered = stepper.step(*executor, chunk.start - chunk.preroll + p, label + " of " + ws.path.string());
        if (!rendered) return fail(label + ": " + rendered.error());
        times.render += secondsSince(renderStart);
    }
    for (int k = chunk.start; k <= last; ++k) {
        const SequenceFrame& frame = (*frames)[size_t(k)];
        const bool warmUp = k < first;
        const std::string frameLabel = std::string(warmUp ? "warm-up frame " : "frame ") + std::to_string(frame.frame) + " (" +
                                       frame.path.string() + ")";
        try {
            if (k < last) next = std::async(policy, readFrame, (*frames)[size_t(k) + 1].path, settings.layer, frameSize);
        } catch (const std::system_error& e) {
            return fail(frameLabel + ": cannot start reading the next image: " + e.what());
        }
        Clock::time_point renderStart = Clock::now();
        const std::string label = frameLabel + " of " + ws.path.string();
        if (warmUp) {
            Result<void> rendered = stepper.step(*executor, k, label);
            if (!rendered) return fail(frameLabel + ": " + rendered.error());
            times.render += secondsSince(renderStart);
        } else {
            Result<Image> image = stepper.stepAndRead(*executor, k, label, target);
            if (!image) return fail(frameLabel + ": " + image.error());
            times.render += secondsSince(renderStart);
            if (Result<void> previous = finishWrite(); !previous) return fail(previous.error());
            writingFile = output->fileName(frame.frame);
            try {
                writing = std::async(policy, writeFrame, writingFile, std::move(*image), settings.write);
            } catch (const std::system_error& e) {
                return fail(writingFile.string() + ": cannot start writing: " + e.what());
            }
            if (!settings.overlap) {
                if (Result<void> done = finishWrite(); !done) return fail(done.error());
            }
            // Overlapped, this frame's write is still under way.
            const int written = k - first + (settings.overlap ? 0 : 1);
            if (progress) progress({written, times.frames, secondsSince(started)});
        }
        if (k < last) {
            ReadFrame read = next.get();
            times.read += read.seconds;
            if (!read.image) return fail(read.image.error());
            Clock::time_point uploadStart = Clock::now();
            Result<void> replaced = executor->replaceInputImage(input, std::make_shared<const Image>(std::move(*read.image)));
            if (!replaced) return fail(replaced.error());
            times.render += secondsSince(uploadStart);
        }
    }
    if (Result<void> last = finishWrite(); !last) return fail(last.error());
    times.total = secondsSince(started);
    if (progress) progress({times.frames, times.frames, times.total});
    return Run(times, std::move(warnings));
}

}  // namespace rmfx
