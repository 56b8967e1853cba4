// What rmfx render --check (gl/GlHealthCheck.h) costs: the frame time of effects/hdr_lighting.xml
// (or --workspace W) at 512x512 with the check off and on, side by side. Each round renders
// --frames frames with each executor, the two in alternating order, a frame being renderFrame +
// glFinish on the wall clock; the check's frame includes reading its buffer back at the end.
// Printed: each round's medians and ratio, then the median ratio over the rounds and its spread,
// and the GPU time of a frame (timer queries) with and without the check. The issue's target: the
// check costs under 10 % of the frame at 512x512.
//
//   rmfx_bench_health_check [--size WxH] [--rounds N] [--frames N] [--workspace FILE]

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <epoxy/gl.h>

#include "bench/RoundsArguments.h"
#include "core/Percentile.h"
#include "gl/GlContext.h"
#include "gl/GlExecutor.h"
#include "validation/WorkspaceLoader.h"

namespace {

using namespace rmfx;
using Clock = std::chrono::steady_clock;


double median(std::vector<double> v) { return v.empty() ? 0.0 : percentile(std::move(v), 0.5); }

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
    std::unique_ptr<GlExecutor> executors[2];  // check off, on
    for (int on = 0; on < 2; ++on) {
        ExecutorOptions options;
        options.outputs = {ws->outputTargetName()};  // as rmfx render asks for its one image
        options.checkHealth = on == 1;
        auto created = GlExecutor::create(ws, a.size, options);
        if (!created) {
            std::fprintf(stderr, "rmfx_bench_health_check: %s", formatAll(created.diagnostics()).c_str());
            return 1;
        }
        executors[on] = std::move(*created);
    }
    std::string frameError;
    int frameIndex = 0;
    // This thread's CPU time to issue a frame (renderFrame without the check's read-back wait is
    // not separable: the read-back is inside it), per executor over all rounds.
    std::vector<double> issueCpu[2];
    auto threadCpuMilliseconds = [] {
        timespec t{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
        return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
    };
    auto run = [&](int on, int frames) {
        std::vector<double> times;
        for (int k = 0; k < frames; ++k) {
            const float time = static_cast<float>(frameIndex++) / 60.0f;
            glFinish();
            auto start = Clock::now();
            const double cpuStart = threadCpuMilliseconds();
            Diagnostics d = executors[on]->renderFrame({time, 1.0f / 60.0f}).takeDiagnostics();
            issueCpu[on].push_back(threadCpuMilliseconds() - cpuStart);
            glFinish();
            times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
            if (hasErrors(d) && frameError.empty()) frameError = formatAll(d);
        }
        return median(times);
    };

    const auto began = Clock::now();
    std::printf("%s, %s\n", reinterpret_cast<const char*>(glGetString(GL_VERSION)),
                reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
    std::printf("rmfx_bench_health_check: %s at %dx%d, %d rounds of %d frames per executor\n",
                a.workspace.filename().string().c_str(), a.size.x, a.size.y, a.rounds, a.frames);
    run(0, 3), run(1, 3);  // warm-up: llvmpipe compiles at first draws
    if (!frameError.empty()) {
        std::fprintf(stderr, "rmfx_bench_health_check: a frame failed: %s", frameError.c_str());
        return 1;
    }
    std::vector<double> off, on, ratios;
    std::printf("round  off (ms)  on (ms)  on / off\n");
    for (int round = 0; round < a.rounds; ++round) {
        const int first = round % 2;
        double ms[2];
        ms[first] = run(first, a.frames);
        ms[1 - first] = run(1 - first, a.frames);
        off.push_back(ms[0]);
        on.push_back(ms[1]);
        ratios.push_back(ms[1] / ms[0]);
        std::printf("%5d  %8.2f  %7.2f  %8.3f\n", round + 1, ms[0], ms[1], ratios.back());
    }
    // The GPU's own time of a frame (timer queries around every pass, the check's dispatches
    // counted in the pass they follow).
    double gpu[2];
    for (int k = 0; k < 2; ++k) {
        executors[k]->setTimingEnabled(true);
        std::vector<double> samples;
        for (int f = 0; f < 7; ++f) {
            (void)executors[k]->renderFrame({static_cast<float>(frameIndex++) / 60.0f, 1.0f / 60.0f});
            glFinish();
            if (f >= 2) samples.push_back(executors[k]->frameGpuMilliseconds());
        }
        executors[k]->setTimingEnabled(false);
        gpu[k] = median(samples);
    }
    const FrameHealth* health = executors[1]->frameHealth();
    std::printf("\n| frame | check off (ms) | check on (ms) | on / off | target |\n|---|---|---|---|---|\n");
    std::printf("| wall clock, median of rounds | %.2f | %.2f | %.3f (%.3f to %.3f) | ≤ 1.10 |\n", median(off), median(on),
                median(ratios), *std::min_element(ratios.begin(), ratios.end()),
                *std::max_element(ratios.begin(), ratios.end()));
    std::printf("| GPU time (timer queries) | %.2f | %.2f | %.3f | |\n", gpu[0], gpu[1], gpu[1] / gpu[0]);
    std::printf("| CPU time of renderFrame, this thread | %.2f | %.2f | %.3f | |\n", median(issueCpu[0]), median(issueCpu[1]),
                median(issueCpu[1]) / median(issueCpu[0]));
    std::printf("%zu passes inspected a frame; the benchmark took %.0f s\n", health ? health->passes.size() : 0,
                std::chrono::duration<double>(Clock::now() - began).count());
    if (!frameError.empty()) {
        std::fprintf(stderr, "rmfx_bench_health_check: a frame failed: %s", frameError.c_str());
        return 1;
    }
    return 0;
}
