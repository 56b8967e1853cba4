// Frames per second of an EXR sequence through effects/hdr_lighting.xml, rendered by
// renderSequence (run/SequenceRun.h) with its overlap on (the next image read and the last output
// written on other threads while the GPU renders) and off (read, render, write one after the
// other). The runs alternate, on, off, on, off …, so that the machine's load hits both. Prints
// each run and the medians: frames per second, seconds per frame of each stage, and the
// overlapped frame against the larger of its rendering and its IO (reading + writing), which a
// perfect overlap would reach.
//
//   rmfx_bench_sequence [--frames N] [--size WxH] [--repetitions N] [--output exr|png]
//                       [--input PATTERN] [--dir DIR] [--keep]
//
// Without --input it first writes N frames of a synthetic HDR sequence (bench/SyntheticHdrSequence.h)
// as half-float EXR. Everything goes to a temporary folder (about 1.4 GB for the defaults), removed
// at the end unless --keep (an interrupted run leaves it; its path is printed first); --dir DIR uses
// DIR (new or empty) instead and keeps it.

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "bench/WholeNumberArgument.h"
#include "bench/SyntheticHdrSequence.h"
#include "core/Percentile.h"
#include "gl/GlContext.h"
#include "io/image/InputImage.h"
#include "io/media/ImageSequence.h"
#include "run/SequenceRun.h"
#include "validation/WorkspaceLoader.h"

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using rmfx::percentile;

namespace {

constexpr const char* kUsage =
    "usage: rmfx_bench_sequence [--frames N] [--size WxH] [--repetitions N] [--output exr|png]\n"
    "                           [--input PATTERN] [--dir DIR] [--keep]\n"
    "  --frames N        frames of the synthetic sequence, 2 to 1000 (default 60)\n"
    "  --size WxH        its size (default 1920x1080); with --input, the viewport the images are resampled to\n"
    "  --repetitions N   runs with the overlap and as many without, alternating, 1 to 100 (default 2)\n"
    "  --output exr|png  the output files: 32-bit float EXR as rmfx render writes .exr, or 8-bit PNG (default exr)\n"
    "  --input PATTERN   an existing sequence (shot/frame.%04d.exr) instead of the synthetic one\n"
    "  --dir DIR         write the frames and outputs to DIR (new or empty) and keep them\n"
    "  --keep            keep the temporary folder\n";

struct Arguments {
    int frames = 60;
    bool framesGiven = false;
    glm::ivec2 size{1920, 1080};
    bool sizeGiven = false;
    int repetitions = 2;
    std::string outputExtension = "exr";
    std::string input;  // empty: the synthetic sequence
    std::string dir;    // empty: a temporary folder
    bool keep = false;
};

// Prints what is wrong and returns nothing for a bad command line.
std::optional<Arguments> parseArguments(int argc, char** argv) {
    Arguments a;
    auto fail = [](const std::string& message) -> std::optional<Arguments> {
        std::fprintf(stderr, "rmfx_bench_sequence: %s (--help lists the options)\n", message.c_str());
        return std::nullopt;
    };
    for (int i = 1; i < argc; ++i) {
        const std::string option = argv[i];
        if (option == "--keep") {
            a.keep = true;
            continue;
        }
        if (option == "-h" || option == "--help") {
            std::printf("%s", kUsage);
            std::exit(0);
        }
        const bool takesValue = option == "--frames" || option == "--size" || option == "--repetitions" ||
                                option == "--output" || option == "--input" || option == "--dir";
        if (!takesValue) return fail("unknown argument '" + option + "'");
        if (i + 1 >= argc) return fail(option + ": expected a value");
        const std::string value = argv[++i];
        if (option == "--frames") {
            std::optional<int> frames = rmfx::bench::wholeNumberArgument(value, 2, 1000);
            if (!frames) return fail("--frames: expected a whole number from 2 to 1000, got '" + value + "'");
            a.frames = *frames;
            a.framesGiven = true;
        } else if (option == "--size") {
            const size_t x = value.find('x');
            std::optional<int> w = x == std::string::npos ? std::nullopt : rmfx::bench::wholeNumberArgument(value.substr(0, x), 16, rmfx::kMaxInputSide);
            std::optional<int> h = x == std::string::npos ? std::nullopt : rmfx::bench::wholeNumberArgument(value.substr(x + 1), 16, rmfx::kMaxInputSide);
            if (!w || !h)
                return fail("--size: expected WxH, each from 16 to " + std::to_string(rmfx::kMaxInputSide) + ", got '" + value + "'");
            a.size = {*w, *h};
            a.sizeGiven = true;
        } else if (option == "--repetitions") {
            std::optional<int> repetitions = rmfx::bench::wholeNumberArgument(value, 1, 100);
            if (!repetitions) return fail("--repetitions: expected a whole number from 1 to 100, got '" + value + "'");
            a.repetitions = *repetitions;
        } else if (option == "--output") {
            if (value != "exr" && value != "png") return fail("--output: expected exr or png, got '" + value + "'");
            a.outputExtension = value;
        } else if (option == "--input") {
            if (!rmfx::isSequencePattern(value))
                return fail("--input: expected a frame pattern such as shot/frame.%04d.exr, got '" + value + "'");
            a.input = value;
        } else {
            if (value.empty()) return fail("--dir: expected a folder");
            a.dir = value;
        }
    }
    if (!a.input.empty() && a.framesGiven) return fail("--frames applies to the synthetic sequence, not to --input");
    return a;
}

// Removes the benchmark's folder when main returns, unless it is to be kept.
struct FolderRemoval {
    fs::path folder;
    bool keep = false;
    ~FolderRemoval() {
        std::error_code ignored;
        if (!keep && !folder.empty()) fs::remove_all(folder, ignored);
    }
};

std::optional<fs::path> makeTemporaryFolder() {
    std::error_code ec;
    fs::path base = fs::temp_directory_path(ec);
    if (ec) return std::nullopt;
    std::string pattern = (base / "rmfx_bench_sequence.XXXXXX").string();
    if (!mkdtemp(pattern.data())) return std::nullopt;
    return fs::path(pattern);
}

double processCpuSeconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + t.tv_usec / 1e6; };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

double loadAverage() {
    double load[1] = {0.0};
    return getloadavg(load, 1) == 1 ? load[0] : NAN;
}

struct RunFigures {
    bool overlap = false;
    rmfx::SequenceTimes times;
    // Seconds per frame from the first frame's render to the last one's: what each frame adds
    // once the pipeline is full, without the executor's creation (which SequenceTimes counts in
    // the first read), the first read and the last write (NaN for a single frame).
    double steady = NAN;
    double cpu = 0.0;   // the process's user + system seconds
    double load = 0.0;  // 1-minute load average when the run began

    double perFrame(double seconds) const { return seconds / times.frames; }
    double bound() const { return std::max(perFrame(times.render), perFrame(times.read + times.write)); }
};

std::optional<RunFigures> runOnce(const rmfx::Workspace& ws, rmfx::SequenceSettings settings, bool overlap) {
    settings.overlap = overlap;
    RunFigures figures;
    figures.overlap = overlap;
    figures.load = loadAverage();
    std::vector<double> stamps;  // seconds since the start at each frame's progress call
    const double cpuBefore = processCpuSeconds();
    rmfx::Result<rmfx::SequenceTimes> run = rmfx::renderSequence(ws, settings, {}, [&](const rmfx::SequenceProgress& p) {
        if (p.done < p.total) stamps.push_back(p.seconds);
    });
    figures.cpu = processCpuSeconds() - cpuBefore;
    if (!run) {
        std::fprintf(stderr, "%s", rmfx::formatAll(run.diagnostics()).c_str());
        return std::nullopt;
    }
    figures.times = *run;
    const int n = static_cast<int>(stamps.size());
    if (n >= 2) figures.steady = (stamps[n - 1] - stamps[0]) / (n - 1);
    return figures;
}

const char* modeName(bool overlap) { return overlap ? "overlap" : "sequential"; }

void printHeader() {
    std::printf("%-4s %-10s %6s %7s %7s %7s %7s %7s %7s %7s %6s %5s\n", "run", "mode", "fps", "read", "render",
                "write", "total", "steady", "bound", "CPU", "cores", "load");
    std::printf("%-4s %-10s %6s %55s %6s %5s\n", "", "", "", "------------------ seconds per frame ------------------",
                "busy", "");
}

void printRun(const std::string& label, const RunFigures& r) {
    std::printf("%-4s %-10s %6.3f %7.3f %7.3f %7.3f %7.3f %7.3f %7.3f %7.3f %6.2f %5.1f\n", label.c_str(),
                modeName(r.overlap), r.times.frames / r.times.total, r.perFrame(r.times.read), r.perFrame(r.times.render),
                r.perFrame(r.times.write), r.perFrame(r.times.total), r.steady, r.bound(), r.perFrame(r.cpu),
                r.cpu / r.times.total, r.load);
}

// Of the values that are numbers (a single-frame sequence has no steady period); NaN if none is.
double median(const std::vector<RunFigures>& runs, double (*of)(const RunFigures&)) {
    std::vector<double> values;
    for (const RunFigures& r : runs)
        if (std::isfinite(of(r))) values.push_back(of(r));
    return values.empty() ? NAN : percentile(values, 0.5);
}

// The median of a figure with its smallest and largest value; "-" without values.
std::string spread(std::vector<double> values, const char* format = "%.3f") {
    std::erase_if(values, [](double v) { return !std::isfinite(v); });
    if (values.empty()) return "-";
    char text[96], low[24], mid[24], high[24];
    std::snprintf(mid, sizeof mid, format, percentile(values, 0.5));
    std::snprintf(low, sizeof low, format, percentile(values, 0.0));
    std::snprintf(high, sizeof high, format, percentile(values, 1.0));
    std::snprintf(text, sizeof text, "%s (%s … %s)", mid, low, high);
    return text;
}

int benchmark(const Arguments& a) {
    const Clock::time_point began = Clock::now();
    if (!a.input.empty()) {
        if (rmfx::Result<std::vector<rmfx::SequenceFrame>> frames = rmfx::findSequenceFrames(a.input); !frames) {
            std::fprintf(stderr, "%s", rmfx::formatAll(frames.diagnostics()).c_str());
            return 1;
        }
    }
    FolderRemoval removal;
    fs::path root;
    if (!a.dir.empty()) {
        root = a.dir;
        std::error_code ec;
        if (fs::exists(root, ec) && !(fs::is_directory(root, ec) && fs::is_empty(root, ec))) {
            std::fprintf(stderr, "rmfx_bench_sequence: --dir %s: expected a new or empty folder\n", a.dir.c_str());
            return 1;
        }
        fs::create_directories(root, ec);
        if (ec) {
            std::fprintf(stderr, "rmfx_bench_sequence: --dir %s: %s\n", a.dir.c_str(), ec.message().c_str());
            return 1;
        }
    } else {
        std::optional<fs::path> temporary = makeTemporaryFolder();
        if (!temporary) {
            std::fprintf(stderr, "rmfx_bench_sequence: cannot create a temporary folder\n");
            return 2;
        }
        root = *temporary;
        removal.folder = root;
        removal.keep = a.keep;
    }
    std::error_code ec;
    for (const char* folder : {"input", "overlap", "sequential"}) fs::create_directories(root / folder, ec);
    if (ec) {
        std::fprintf(stderr, "rmfx_bench_sequence: %s: %s\n", root.c_str(), ec.message().c_str());
        return 2;
    }

    rmfx::Result<rmfx::Workspace> ws = rmfx::loadWorkspace(fs::path(RMFX_SOURCE_DIR) / "effects" / "hdr_lighting.xml");
    if (!ws) {
        std::fprintf(stderr, "%s", rmfx::formatAll(ws.diagnostics()).c_str());
        return 2;
    }
    auto context = rmfx::GlContext::createHeadless(ws->profile);
    if (!context) {
        std::fprintf(stderr, "rmfx_bench_sequence: no GL context: %s\n", context.error().c_str());
        return 2;
    }

    rmfx::SequenceSettings settings;
    settings.inputPattern = a.input;
    double generation = 0.0;
    if (a.input.empty()) {
        std::fprintf(stderr, "writing %d frames of %dx%d to %s …\n", a.frames, a.size.x, a.size.y, (root / "input").c_str());
        const Clock::time_point start = Clock::now();
        rmfx::Result<std::string> pattern = rmfx::bench::writeSyntheticHdrSequence(root / "input", a.frames, a.size);
        generation = std::chrono::duration<double>(Clock::now() - start).count();
        if (!pattern) {
            std::fprintf(stderr, "rmfx_bench_sequence: %s\n", pattern.error().c_str());
            return 2;
        }
        settings.inputPattern = *pattern;
    } else if (a.sizeGiven) {
        settings.size = a.size;
    }
    if (a.outputExtension == "png") settings.write.transform = ws->output.transform;

    std::printf("%s; %u hardware threads\n", context.value()->description().c_str(), std::thread::hardware_concurrency());
    std::printf("effects/hdr_lighting.xml on %s%s; outputs: %s\n", settings.inputPattern.c_str(),
                a.input.empty() ? " (synthetic, half-float RGBA EXR)" : "",
                a.outputExtension == "exr" ? "32-bit float RGBA EXR" : "8-bit PNG");
    if (a.input.empty()) std::printf("writing the input frames took %.1f s\n", generation);
    std::printf("%d runs with the overlap and %d without, alternating\n\n", a.repetitions, a.repetitions);
    printHeader();

    std::vector<RunFigures> overlapped, sequential;
    for (int i = 0; i < a.repetitions; ++i) {
        for (bool overlap : {true, false}) {
            settings.outputPattern = (root / modeName(overlap) / ("frame.%04d." + a.outputExtension)).string();
            std::optional<RunFigures> run = runOnce(*ws, settings, overlap);
            if (!run) return 2;
            printRun(std::to_string(i + 1), *run);
            std::fflush(stdout);
            (overlap ? overlapped : sequential).push_back(*run);
        }
    }

    std::printf("\nmedians\n");
    for (const std::vector<RunFigures>* runs : {&overlapped, &sequential}) {
        RunFigures m;
        m.overlap = runs->front().overlap;
        m.times.frames = 1;  // the medians below are already per frame
        m.times.read = median(*runs, [](const RunFigures& r) { return r.perFrame(r.times.read); });
        m.times.render = median(*runs, [](const RunFigures& r) { return r.perFrame(r.times.render); });
        m.times.write = median(*runs, [](const RunFigures& r) { return r.perFrame(r.times.write); });
        m.times.total = median(*runs, [](const RunFigures& r) { return r.perFrame(r.times.total); });
        m.steady = median(*runs, [](const RunFigures& r) { return r.steady; });
        m.cpu = median(*runs, [](const RunFigures& r) { return r.perFrame(r.cpu); });
        m.load = median(*runs, [](const RunFigures& r) { return r.load; });
        printRun("", m);
    }

    // Each overlapped run against the sequential run after it, whose stages had the machine to
    // themselves; and against its own stages, which ran beside each other.
    std::vector<double> speedUp, totalToBound, steadyToBound, totalToOwnBound, totalToCpuFloor;
    const double cores = std::max(1u, std::thread::hardware_concurrency());
    for (size_t i = 0; i < overlapped.size(); ++i) {
        const RunFigures& on = overlapped[i];
        const RunFigures& off = sequential[i];
        speedUp.push_back(off.times.total / on.times.total);
        totalToBound.push_back(on.perFrame(on.times.total) / off.bound());
        steadyToBound.push_back(on.steady / off.bound());
        totalToOwnBound.push_back(on.perFrame(on.times.total) / on.bound());
        totalToCpuFloor.push_back(on.times.total / (on.cpu / cores));
    }
    std::printf("\nIO = read (decoding an input EXR%s) + write (encoding and writing an output file);\n"
                "render = uploading the image, the passes, reading the output back; read also holds the\n"
                "executor's creation. total: the run's wall clock over its frames; steady: per frame once the\n"
                "pipeline is full. bound = max(render, IO): what a perfect overlap would take. CPU: the process's\n"
                "user + system time; cores busy: CPU / wall; load: 1-minute load average at the start.\n"
                "Over the pairs (overlap run, the sequential run after it), the median (min … max):\n\n",
                !a.input.empty() && a.sizeGiven ? ", resampling it to the viewport" : "");
    std::printf("  sequential total / overlapped total (speed-up)           %s\n", spread(speedUp).c_str());
    std::printf("  overlapped total per frame / bound of the sequential run %s\n", spread(totalToBound).c_str());
    std::printf("  overlapped steady per frame / that bound                 %s\n", spread(steadyToBound).c_str());
    std::printf("  overlapped total per frame / its own bound               %s\n", spread(totalToOwnBound).c_str());
    std::printf("  overlapped total / (its CPU seconds / %.0f cores)          %s\n", cores, spread(totalToCpuFloor).c_str());
    const double ratio = percentile(totalToBound, 0.5);
    std::printf("\ntarget: an overlapped frame within 1.10 x max(rendering, IO): %s (median ratio %.3f)\n",
                ratio <= 1.10 ? "met" : "not met", ratio);
    if (!removal.folder.empty() && a.keep) std::printf("kept %s\n", root.c_str());
    if (!a.dir.empty()) std::printf("frames and outputs in %s\n", root.c_str());
    std::printf("the benchmark took %.0f s\n", std::chrono::duration<double>(Clock::now() - began).count());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::optional<Arguments> arguments = parseArguments(argc, argv);
    if (!arguments) return 1;
    try {
        return benchmark(*arguments);
    } catch (const std::exception& e) {  // out of memory at a large --size, a filesystem error
        std::fprintf(stderr, "rmfx_bench_sequence: %s\n", e.what());
        return 2;
    }
}
