// What rmfx render --check (gl/GlHealthCheck.h) costs: the frame time of effects/hdr_lighting.xml
// (or --workspace W) at 512x512 with the check off and on, side by side. Each round renders
// --frames frames with each executor, the two in alternating order, a frame being renderFrame +
// glFinish on the wall clock; the check's frame includes reading back the results of the frames
// before it that the GPU has finished (GlExecutor::renderFrame reads them without waiting).
// Four executors: the check off, the check inspecting each target after its pass (after-pass),
// the passes counting what they write (while-drawing, gl/HealthInstrumentation.h), and the
// default (auto: while-drawing on a GPU; on a software rasteriser while-drawing in the passes that
// share their target with a neighbour, the scene's seven, and in those that record at most two
// inputs, after-pass in the others).
// Printed: each round's medians and ratios against off, then the median ratios over the rounds and
// their spread, the GPU time of a frame and of each pass (timer queries). The issue's target: the
// check costs under 10 % of the frame at 512x512. Then each method's ratio against off again from
// --pairs pairs of adjacent frames (bench/PairedFrames.h), the median with its 95 % interval: on a
// noisy machine the tighter figure; and the same frames' process CPU time, every thread's, which on
// llvmpipe is the work a frame took, whatever else the machine was running.
//
//   rmfx_bench_health_check [--size WxH] [--rounds N] [--frames N] [--pairs N] [--workspace FILE]

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <epoxy/gl.h>

#include "bench/PairedFrames.h"
#include "bench/RoundFigures.h"
#include "bench/RoundsArguments.h"
#include "gl/GlContext.h"
#include "gl/GlExecutor.h"
#include "validation/WorkspaceLoader.h"

namespace {

using namespace rmfx;
using Clock = std::chrono::steady_clock;


using bench::median;

}  // namespace

int main(int argc, char** argv) {
    bench::RoundsArguments defaults;
    defaults.rounds = 10;
    std::optional<bench::RoundsArguments> arguments = bench::parseRoundsArguments(argc, argv, "rmfx_bench_health_check", defaults);
    if (!arguments) return 2;
    const bench::RoundsArguments& a = *arguments;
    auto context = GlContext::createHeadless();
    if (!context) {
        std::fprintf(stderr, "rmfx_bench_health_check: no headless GL context: %s\n", context.error().c_str());
        return 1;
    }
    Result<Workspace> loaded = loadWorkspace(a.workspace);
    if (!loaded) {
        std::fprintf(stderr, "%s", formatAll(loaded.diagnostics()).c_str());
        return 1;
    }
    auto ws = std::make_shared<const Workspace>(std::move(*loaded));
    // Check off; the check inspecting each target after its pass; the passes counting what they
    // write (where they can: the others are inspected after them); auto.
    constexpr int kExecutors = 4;
    const char* const names[kExecutors] = {"off", "after-pass", "while-drawing", "auto"};
    const HealthCheckMethod methods[kExecutors] = {HealthCheckMethod::Automatic, HealthCheckMethod::AfterPass,
                                                   HealthCheckMethod::WhileDrawing, HealthCheckMethod::Automatic};
    std::unique_ptr<GlExecutor> executors[kExecutors];
    for (int e = 0; e < kExecutors; ++e) {
        ExecutorOptions options;
        options.outputs = {ws->outputTargetName()};  // as rmfx render asks for its one image
        options.checkHealth = e > 0;
        options.healthCheckMethod = methods[e];
        auto created = GlExecutor::create(ws, a.size, options);
        if (!created) {
            std::fprintf(stderr, "rmfx_bench_health_check: %s", formatAll(created.diagnostics()).c_str());
            return 1;
        }
        executors[e] = std::move(*created);
    }
    std::string frameError;
    int frameIndex = 0;
    // This thread's CPU time to issue a frame (renderFrame, with the check's reading of the results
    // of earlier frames, which waits for nothing), per executor over all rounds.
    std::vector<double> issueCpu[kExecutors];
    // The whole process's CPU time of the last frame run (llvmpipe's rasteriser threads included).
    double lastFrameProcessCpu = 0.0;
    using bench::threadCpuMilliseconds;
    auto run = [&](int e, int frames) {
        std::vector<double> times;
        for (int k = 0; k < frames; ++k) {
            const float time = static_cast<float>(frameIndex++) / 60.0f;
            glFinish();
            auto start = Clock::now();
            const double cpuStart = threadCpuMilliseconds(), processStart = bench::processCpuMilliseconds();
            Diagnostics d = executors[e]->renderFrame({time, 1.0f / 60.0f}).takeDiagnostics();
            issueCpu[e].push_back(threadCpuMilliseconds() - cpuStart);
            glFinish();
            times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
            lastFrameProcessCpu = bench::processCpuMilliseconds() - processStart;
            if (hasErrors(d) && frameError.empty()) frameError = formatAll(d);
        }
        return median(times);
    };

    const auto began = Clock::now();
    std::printf("%s, %s\n", reinterpret_cast<const char*>(glGetString(GL_VERSION)),
                reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
    std::printf("rmfx_bench_health_check: %s at %dx%d, %d rounds of %d frames per executor\n",
                a.workspace.filename().string().c_str(), a.size.x, a.size.y, a.rounds, a.frames);
    for (int e = 0; e < kExecutors; ++e) run(e, 3);  // warm-up: llvmpipe compiles at first draws
    if (!frameError.empty()) {
        std::fprintf(stderr, "rmfx_bench_health_check: a frame failed: %s", frameError.c_str());
        return 1;
    }
    std::vector<double> ms[kExecutors], ratios[kExecutors];  // ratios against off, per round
    std::printf("round");
    for (int e = 0; e < kExecutors; ++e) std::printf("  %s (ms)", names[e]);
    for (int e = 1; e < kExecutors; ++e) std::printf("  %s / off", names[e]);
    std::printf("\n");
    for (int round = 0; round < a.rounds; ++round) {
        double t[kExecutors];
        for (int k = 0; k < kExecutors; ++k) {  // the order rotates each round
            const int e = (round + k) % kExecutors;
            t[e] = run(e, a.frames);
        }
        for (int e = 0; e < kExecutors; ++e) {
            ms[e].push_back(t[e]);
            ratios[e].push_back(t[e] / t[0]);
        }
        std::printf("%5d", round + 1);
        for (int e = 0; e < kExecutors; ++e) std::printf("  %*.2f", static_cast<int>(std::string(names[e]).size()) + 5, t[e]);
        for (int e = 1; e < kExecutors; ++e) std::printf("  %*.3f", static_cast<int>(std::string(names[e]).size()) + 6, t[e] / t[0]);
        std::printf("\n");
    }
    // Each method against off again from adjacent frames (bench/PairedFrames.h): the tighter estimate.
    // From the same frames, their process CPU time: on llvmpipe the work a frame took, which other
    // programs running on the machine change far less than they change the wall clock.
    std::string paired[kExecutors], pairedProcessCpu[kExecutors];
    for (int e = 1; e < kExecutors && a.pairs > 0; ++e) {
        const auto ratios = bench::pairedRatiosOf<2>(a.pairs, [&](int which, int) {
            const double wall = run(which == 0 ? e : 0, 1);
            return std::array<double, 2>{wall, lastFrameProcessCpu};
        });
        paired[e] = bench::medianWithInterval(ratios[0]);
        pairedProcessCpu[e] = bench::medianWithInterval(ratios[1]);
    }
    // The GPU's own time of a frame and of each pass (timer queries around every pass, the
    // check's draws after a pass counted in the pass they follow).
    double gpu[kExecutors];
    std::vector<std::vector<double>> passGpu[kExecutors];  // per pass, its samples
    std::vector<std::string> passNames;
    for (int e = 0; e < kExecutors; ++e) {
        executors[e]->setTimingEnabled(true);
        std::vector<double> samples;
        for (int f = 0; f < 7; ++f) {
            (void)executors[e]->renderFrame({static_cast<float>(frameIndex++) / 60.0f, 1.0f / 60.0f});
            glFinish();
            if (f < 2) continue;
            samples.push_back(executors[e]->frameGpuMilliseconds());
            const std::vector<PassTiming>& timings = executors[e]->passTimings();
            passGpu[e].resize(timings.size());
            for (size_t p = 0; p < timings.size(); ++p) passGpu[e][p].push_back(timings[p].milliseconds);
            if (e == 0 && passNames.empty())
                for (const PassTiming& t : timings) passNames.push_back(t.pass);
        }
        executors[e]->setTimingEnabled(false);
        gpu[e] = median(samples);
    }
    const auto spread = bench::medianAndRange;
    auto row = [&](const char* label, const double* values, const std::vector<double>* roundRatios, const char* target) {
        std::printf("| %s |", label);
        for (int e = 0; e < kExecutors; ++e) std::printf(" %.2f |", values[e]);
        for (int e = 1; e < kExecutors; ++e)
            std::printf(" %s |", roundRatios ? spread(roundRatios[e]).c_str() : std::to_string(values[e] / values[0]).substr(0, 5).c_str());
        std::printf(" %s |\n", target);
    };
    std::printf("\n| frame |");
    for (int e = 0; e < kExecutors; ++e) std::printf(" %s%s |", e == 0 ? "check " : "", names[e]);
    for (int e = 1; e < kExecutors; ++e) std::printf(" %s / off |", names[e]);
    std::printf(" target |\n|---|");
    for (int e = 1; e < 2 * kExecutors; ++e) std::printf("---|");
    std::printf("---|\n");
    double wall[kExecutors], cpu[kExecutors];
    for (int e = 0; e < kExecutors; ++e) {
        wall[e] = median(ms[e]);
        cpu[e] = median(issueCpu[e]);
    }
    row("wall clock (ms), median of rounds", wall, ratios, "≤ 1.10");
    if (a.pairs > 0) {
        std::printf("| paired frames (%d pairs): median ratio (95 %% interval) |", a.pairs);
        for (int e = 0; e < kExecutors; ++e) std::printf(" |");
        for (int e = 1; e < kExecutors; ++e) std::printf(" %s |", paired[e].c_str());
        std::printf(" ≤ 1.10 |\n");
        std::printf("| the same frames' process CPU time, every thread (llvmpipe: its rasteriser's work) |");
        for (int e = 0; e < kExecutors; ++e) std::printf(" |");
        for (int e = 1; e < kExecutors; ++e) std::printf(" %s |", pairedProcessCpu[e].c_str());
        std::printf(" |\n");
    }
    row("GPU time (ms, timer queries)", gpu, nullptr, "");
    row("CPU time of renderFrame (ms), this thread", cpu, nullptr, "");
    bool samePasses = true;
    for (int e = 1; e < kExecutors; ++e) samePasses = samePasses && passGpu[e].size() == passGpu[0].size();
    if (samePasses) {
        std::printf("\n| pass |");
        for (int e = 0; e < kExecutors; ++e) std::printf(" GPU %s (ms) |", names[e]);
        std::printf("\n|---|");
        for (int e = 0; e < kExecutors; ++e) std::printf("---|");
        std::printf("\n");
        for (size_t p = 0; p < passGpu[0].size() && p < passNames.size(); ++p) {
            std::printf("| %s |", passNames[p].c_str());
            for (int e = 0; e < kExecutors; ++e) std::printf(" %.3f |", median(passGpu[e][p]));
            std::printf("\n");
        }
    }
    auto counting = [&](int e) {
        size_t n = 0;
        if (const FrameHealth* health = executors[e]->frameHealth())
            for (const PassHealth& p : health->passes) n += p.countedWhileDrawing ? 1 : 0;
        return n;
    };
    const FrameHealth* health = executors[2]->frameHealth();
    std::printf("%zu passes a frame; %zu of them count what they write while drawing, %zu with auto (the others are "
                "inspected after they ran)\n", health ? health->passes.size() : 0, counting(2), counting(3));
    std::printf("the benchmark took %.0f s\n", std::chrono::duration<double>(Clock::now() - began).count());
    if (!frameError.empty()) {
        std::fprintf(stderr, "rmfx_bench_health_check: a frame failed: %s", frameError.c_str());
        return 1;
    }
    return 0;
}
