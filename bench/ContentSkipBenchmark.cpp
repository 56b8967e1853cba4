// What content skip (<effect source>, gl/GlContentSkip.h) saves and what it costs, on
// effects/hdr_lighting.xml (or --workspace W) at 512x512: the frame time of four executors of
// one workspace, on three inputs.
//
//   executors   skip on        content skip on (rmfx render's default): the GPU leaves the passes
//                              out, or the CPU where the source's answer has already arrived
//               GPU only       content skip on, the passes left out by the GPU alone
//               skip off       --content-skip off: every effect runs
//               no effects     --effects "": the workspace without its effects (the floor a
//                              skipped effect can reach)
//   inputs      dark           nothing reaches the effects' sources (a dim interior)
//               bright         lights far above 1 in a dim scene: every effect runs
//               alternating    dark and bright frame by frame: each frame is decided by its own
//                              source, so half the frames skip
//
// Each round renders --frames frames with every (executor, input) pair, the pairs in a rotated
// order, so that the machine's load falls on all of them; a frame is renderFrame + glFinish on
// the wall clock, its input image replaced beforehand (untimed). Per round: the median frame of
// each pair and the ratios of the issue's targets; printed at the end: medians over the rounds and
// their spread, as a Markdown table (docs/performance.md).
//
// Then each target's ratio again from --pairs pairs of adjacent frames (bench/PairedFrames.h),
// the median with its 95 % interval: on a noisy machine the tighter figure.
//
//   rmfx_bench_content_skip [--size WxH] [--rounds N] [--frames N] [--pairs N] [--workspace FILE]

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

#include <epoxy/gl.h>

#include "bench/PairedFrames.h"
#include "bench/RoundFigures.h"
#include "bench/RoundsArguments.h"
#include "gl/GlContext.h"
#include "gl/GlExecutor.h"
#include "io/image/ImageIO.h"
#include "validation/ImageInputs.h"
#include "validation/WorkspaceLoader.h"

namespace {

using namespace rmfx;
using Clock = std::chrono::steady_clock;


// A dim interior: smooth, low contrast, far below any bright-pass threshold even once automatic
// exposure has adapted to it. The bright image is the same with eight small lights of 200.
Image sceneImage(glm::ivec2 size, bool bright) {
    Image image{size.x, size.y, 4, true, 32, std::vector<float>(static_cast<size_t>(size.x) * size.y * 4)};
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const float u = static_cast<float>(x) / size.x, v = static_cast<float>(y) / size.y;
            const float base = 0.02f + 0.015f * u + 0.01f * v;
            image.at(x, y, 0) = base;
            image.at(x, y, 1) = base * 0.9f;
            image.at(x, y, 2) = base * 0.8f;
            image.at(x, y, 3) = 1.0f;
        }
    if (bright) {
        const int side = std::max(2, size.x / 64);
        for (int light = 0; light < 8; ++light) {
            const int cx = (light * 2 + 1) * size.x / 16, cy = (light % 2 ? 3 : 1) * size.y / 4;
            for (int y = cy; y < std::min(size.y, cy + side); ++y)
                for (int x = cx; x < std::min(size.x, cx + side); ++x)
                    for (int c = 0; c < 3; ++c) image.at(x, y, c) = 200.0f;
        }
    }
    return image;
}

enum class Executor { SkipOn, GpuOnly, SkipOff, NoEffects };
enum class Input { Dark, Bright, Alternating };
const char* name(Executor e) {
    switch (e) {
        case Executor::SkipOn: return "skip on";
        case Executor::GpuOnly: return "GPU only";
        case Executor::SkipOff: return "skip off";
        case Executor::NoEffects: return "no effects";
    }
    return "?";
}
constexpr Executor kExecutors[] = {Executor::SkipOn, Executor::GpuOnly, Executor::SkipOff, Executor::NoEffects};
const char* name(Input i) { return i == Input::Dark ? "dark" : i == Input::Bright ? "bright" : "alternating"; }

struct Pair {
    Executor executor;
    Input input;
};

using bench::median;
using bench::threadCpuMilliseconds;

}  // namespace

int main(int argc, char** argv) {
    bench::RoundsArguments defaults;
    defaults.rounds = 12;
    std::optional<bench::RoundsArguments> arguments = bench::parseRoundsArguments(argc, argv, "rmfx_bench_content_skip", defaults);
    if (!arguments) return 2;
    const bench::RoundsArguments& a = *arguments;

    auto context = GlContext::createHeadless();
    if (!context) {
        std::fprintf(stderr, "rmfx_bench_content_skip: no headless GL context: %s\n", context.error().c_str());
        return 1;
    }
    Result<Workspace> loaded = loadWorkspace(a.workspace);
    if (!loaded) {
        std::fprintf(stderr, "%s", formatAll(loaded.diagnostics()).c_str());
        return 1;
    }
    Workspace ws = std::move(*loaded);
    const auto dark = std::make_shared<const Image>(sceneImage(a.size, false));
    const auto bright = std::make_shared<const Image>(sceneImage(a.size, true));

    // The workspace's scene input is given the dark image as a file, as rmfx render --input does.
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("rmfx-bench-content-skip-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    Result<void> written = writeImage(folder / "dark.exr", *dark);
    Result<SuppliedInputs> supplied =
        written ? supplyInputs(ws, {parseInputArgument((folder / "dark.exr").string())}, a.size) : Result<SuppliedInputs>::failure(written.diagnostics());
    std::filesystem::remove_all(folder);
    if (!supplied || supplied->given.size() != 1) {
        std::fprintf(stderr, "rmfx_bench_content_skip: the workspace takes no input image: %s\n",
                     formatAll(supplied.diagnostics()).c_str());
        return 1;
    }
    const std::string input = *supplied->given.begin();

    std::map<Executor, std::unique_ptr<GlExecutor>> executors;
    for (Executor e : kExecutors) {
        ExecutorOptions options;
        options.outputs = {ws.outputTargetName()};  // as rmfx render asks for its one image
        options.givenInputs = supplied->given;
        options.contentSkip = e != Executor::SkipOff;
        if (e == Executor::GpuOnly) options.contentSkipDecision = ExecutorOptions::ContentSkipDecision::GpuOnly;
        if (e == Executor::NoEffects) options.effects = std::vector<std::string>{};
        auto created = GlExecutor::create(std::make_shared<const Workspace>(ws), supplied->viewport, options);
        if (!created) {
            std::fprintf(stderr, "rmfx_bench_content_skip: %s: %s", name(e), formatAll(created.diagnostics()).c_str());
            return 1;
        }
        executors[e] = std::move(*created);
    }

    std::vector<Pair> pairs;
    for (Input i : {Input::Dark, Input::Bright, Input::Alternating})
        for (Executor e : kExecutors) pairs.push_back({e, i});
    std::map<std::pair<Executor, Input>, std::vector<double>> roundMedians;  // ms
    std::map<std::pair<Executor, Input>, std::vector<double>> issueCpu;      // ms per frame, renderFrame alone
    std::map<Input, std::pair<int, int>> skippedFrames;                       // skip on: frames skipping any effect, frames
    std::map<Input, std::vector<double>> notIssued;                           // skip on: passes the CPU left out, per frame
    std::string frameError;

    // One frame of one executor, in milliseconds; `count` adds it to the per-frame figures.
    auto frame = [&](Executor e, Input in, bool isBright, int k, bool count) -> double {
        GlExecutor& executor = *executors[e];
        (void)executor.replaceInputImage(input, isBright ? bright : dark);
        glFinish();
        const float time = static_cast<float>(k) / 60.0f;
        auto start = Clock::now();
        const double cpuStart = threadCpuMilliseconds();
        Diagnostics d = executor.renderFrame({time, 1.0f / 60.0f}).takeDiagnostics();
        if (count) issueCpu[{e, in}].push_back(threadCpuMilliseconds() - cpuStart);
        glFinish();
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        if (hasErrors(d) && frameError.empty()) frameError = formatAll(d);
        if (count && e == Executor::SkipOn) {
            auto& [skipping, total] = skippedFrames[in];
            skipping += executor.contentSkippedEffects().empty() ? 0 : 1;
            total += 1;
            notIssued[in].push_back(executor.passesNotIssuedByContentSkip());
        }
        return ms;
    };
    auto isBrightFrame = [](Input in, int k) { return in == Input::Bright || (in == Input::Alternating && k % 2 == 1); };
    // One round of one pair: its median frame, in milliseconds.
    auto run = [&](const Pair& pair, int frames, bool count) -> double {
        std::vector<double> times;
        for (int k = 0; k < frames; ++k)
            times.push_back(frame(pair.executor, pair.input, isBrightFrame(pair.input, k), k, count));
        return median(times);
    };

    const auto began = Clock::now();
    std::printf("%s, %s\n", reinterpret_cast<const char*>(glGetString(GL_VERSION)),
                reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
    std::printf("rmfx_bench_content_skip: %s at %dx%d, %d rounds of %d frames per executor and input\n",
                a.workspace.filename().string().c_str(), supplied->viewport.x, supplied->viewport.y, a.rounds, a.frames);
    for (const Pair& pair : pairs) run(pair, 3, false);  // warm-up: llvmpipe compiles at first draws
    if (!frameError.empty()) {
        std::fprintf(stderr, "rmfx_bench_content_skip: a frame failed: %s", frameError.c_str());
        return 1;
    }
    std::printf("round  dark: on/none  bright: on/off  alternating: on/off  dark: GPU only/none  (median frame ms: on, off, none per input)\n");
    for (int round = 0; round < a.rounds; ++round) {
        for (size_t p = 0; p < pairs.size(); ++p) {
            const Pair& pair = pairs[(p + round) % pairs.size()];
            roundMedians[{pair.executor, pair.input}].push_back(run(pair, a.frames, true));
        }
        auto ms = [&](Executor e, Input i) { return roundMedians[{e, i}].back(); };
        std::printf("%5d  %12.3f  %14.3f  %19.3f  %19.3f  ", round + 1, ms(Executor::SkipOn, Input::Dark) / ms(Executor::NoEffects, Input::Dark),
                    ms(Executor::SkipOn, Input::Bright) / ms(Executor::SkipOff, Input::Bright),
                    ms(Executor::SkipOn, Input::Alternating) / ms(Executor::SkipOff, Input::Alternating),
                    ms(Executor::GpuOnly, Input::Dark) / ms(Executor::NoEffects, Input::Dark));
        for (Input i : {Input::Dark, Input::Bright, Input::Alternating})
            std::printf(" %s %.2f %.2f %.2f", name(i), ms(Executor::SkipOn, i), ms(Executor::SkipOff, i), ms(Executor::NoEffects, i));
        std::printf("\n");
    }

    // The ratio of each round (both measured within it), then the median and spread over rounds.
    auto ratios = [&](Executor top, Executor bottom, Input i) {
        std::vector<double> r;
        for (size_t k = 0; k < roundMedians[{top, i}].size(); ++k) r.push_back(roundMedians[{top, i}][k] / roundMedians[{bottom, i}][k]);
        return r;
    };
    const auto spread = bench::medianAndRange;
    std::printf("\n| input | skip on (ms) | skip off (ms) | no effects (ms) | on / off | on / no effects | frames skipping an effect | target |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    for (Input i : {Input::Dark, Input::Bright, Input::Alternating}) {
        const auto [skipping, total] = skippedFrames[i];
        const char* target = i == Input::Dark ? "on / no effects ≤ 1.05" : i == Input::Bright ? "on / off ≤ 1.02" : "(printed)";
        std::printf("| %s | %.2f | %.2f | %.2f | %s | %s | %d of %d | %s |\n", name(i), median(roundMedians[{Executor::SkipOn, i}]),
                    median(roundMedians[{Executor::SkipOff, i}]), median(roundMedians[{Executor::NoEffects, i}]),
                    spread(ratios(Executor::SkipOn, Executor::SkipOff, i)).c_str(),
                    spread(ratios(Executor::SkipOn, Executor::NoEffects, i)).c_str(), skipping, total, target);
    }
    // The same with the passes left out by the GPU alone: what the CPU's side adds, where the
    // source's answer arrives before the passes it decides are issued.
    std::printf("\n| input | GPU only (ms) | GPU only / off | GPU only / no effects | passes the CPU left out (skip on, median a frame) |\n");
    std::printf("|---|---|---|---|---|\n");
    for (Input i : {Input::Dark, Input::Bright, Input::Alternating})
        std::printf("| %s | %.2f | %s | %s | %.0f |\n", name(i), median(roundMedians[{Executor::GpuOnly, i}]),
                    spread(ratios(Executor::GpuOnly, Executor::SkipOff, i)).c_str(),
                    spread(ratios(Executor::GpuOnly, Executor::NoEffects, i)).c_str(), median(notIssued[i]));
    // The targets again from adjacent frames (bench/PairedFrames.h): the tighter estimate.
    if (a.pairs > 0) {
        struct Compared {
            Input input;
            Executor top, bottom;
            const char* target;
        };
        const Compared compared[] = {{Input::Dark, Executor::SkipOn, Executor::NoEffects, "≤ 1.05"},
                                     {Input::Dark, Executor::GpuOnly, Executor::NoEffects, ""},
                                     {Input::Bright, Executor::SkipOn, Executor::SkipOff, "≤ 1.02"},
                                     {Input::Bright, Executor::GpuOnly, Executor::SkipOff, ""},
                                     {Input::Alternating, Executor::SkipOn, Executor::SkipOff, ""}};
        std::printf("\nPaired frames: %d pairs per ratio, each the two executors' frames back to back (order alternating); "
                    "the median ratio and its 95 %% interval:\n\n", a.pairs);
        std::printf("| input | ratio | median (95 %% interval) | target |\n|---|---|---|---|\n");
        for (const Compared& c : compared) {
            // An alternating pair compares a dark and a bright frame of each executor together.
            const std::vector<double> r = bench::pairedRatios(a.pairs, [&](int which, int k) {
                const Executor e = which == 0 ? c.top : c.bottom;
                if (c.input != Input::Alternating) return frame(e, c.input, c.input == Input::Bright, k, false);
                return frame(e, c.input, false, 2 * k, false) + frame(e, c.input, true, 2 * k + 1, false);
            });
            std::printf("| %s | %s / %s | %s | %s |\n", name(c.input), name(c.top), name(c.bottom),
                        bench::medianWithInterval(r).c_str(), c.target);
        }
    }
    // What the calling thread spends issuing a frame (renderFrame, before glFinish): on a GPU whose
    // passes take microseconds, this is most of a small frame.
    std::printf("\nCPU time to issue a frame (ms, this thread, median of all frames):\n");
    std::printf("%-12s %8s %9s %9s %11s\n", "input", "skip on", "GPU only", "skip off", "no effects");
    for (Input i : {Input::Dark, Input::Bright, Input::Alternating})
        std::printf("%-12s %8.3f %9.3f %9.3f %11.3f\n", name(i), median(issueCpu[{Executor::SkipOn, i}]),
                    median(issueCpu[{Executor::GpuOnly, i}]), median(issueCpu[{Executor::SkipOff, i}]),
                    median(issueCpu[{Executor::NoEffects, i}]));
    // Where a dark frame's time goes: each pass's GPU time (timer queries), skip on against no effects.
    std::printf("\nGPU time of each pass on a dark frame (ms, timer queries; median of 5 frames):\n");
    std::map<std::string, std::map<Executor, double>> passMs;
    std::vector<std::string> passOrder;
    for (Executor e : {Executor::SkipOn, Executor::NoEffects}) {
        GlExecutor& executor = *executors[e];
        (void)executor.replaceInputImage(input, dark);
        executor.setTimingEnabled(true);
        std::map<std::string, std::vector<double>> samples;
        for (int k = 0; k < 7; ++k) {
            (void)executor.renderFrame({static_cast<float>(k) / 60.0f, 1.0f / 60.0f});
            glFinish();
            if (k < 2) continue;
            for (const PassTiming& t : executor.passTimings()) {
                if (std::find(passOrder.begin(), passOrder.end(), t.pass) == passOrder.end()) passOrder.push_back(t.pass);
                samples[t.pass].push_back(t.milliseconds);
            }
        }
        executor.setTimingEnabled(false);
        for (auto& [pass, v] : samples) passMs[pass][e] = median(v);
    }
    std::printf("%-20s %8s %11s\n", "pass", "skip on", "no effects");
    for (const std::string& pass : passOrder) {
        auto& m = passMs[pass];
        auto cell = [&](Executor e) { return m.count(e) ? std::to_string(m[e]).substr(0, 7) : std::string("-"); };
        std::printf("%-20s %8s %11s\n", pass.c_str(), cell(Executor::SkipOn).c_str(), cell(Executor::NoEffects).c_str());
    }
    std::printf("the benchmark took %.0f s\n", std::chrono::duration<double>(Clock::now() - began).count());
    if (!frameError.empty()) {
        std::fprintf(stderr, "rmfx_bench_content_skip: a frame failed: %s", frameError.c_str());
        return 1;
    }
    return 0;
}
