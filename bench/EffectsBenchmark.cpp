// What the pass graph saves and what the interpreter costs, on the chapter's combined workspace
// (effects/shader_5.xml: glare, streak and ghost; 20 passes with all three). Google Benchmark
// cases, all at one size (512x512 unless --size=N or --size=WxH, or RMFX_BENCH_SIZE):
//
//   effects/<subset>      shader_5 asking for a subset of its effects (ExecutorOptions::effects,
//                         outputs {"output"}): the time of renderFrame + glFinish, with counters for
//                         the passes run, the target memory allocated and declared, and the GPU
//                         time of a frame from timer queries (taken after the timed loop).
//   workspace/shader_N    the workspaces of one effect each (shader_2 glare, shader_3 streak,
//                         shader_4 ghost), measured the same way: the summary divides the time of
//                         shader_5 with only that effect by theirs.
//   overhead/interpreter_vs_hand
//                         GlExecutor::renderFrame against HandWrittenShader5 (the same 20 passes
//                         in straight-line GL), frames interleaved (ABBA) in one loop: the CPU time
//                         to issue a frame (clock read before and after the GL calls, glFinish
//                         outside), as wall time and as the thread's CPU time, and the full frame.
//
// After the Google Benchmark report it prints the summary as Markdown tables (--markdown=FILE
// also writes them to FILE). bench/run-effects-bench.sh runs it the way docs/performance.md
// reports. One headless GL context serves the whole process.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <benchmark/benchmark.h>
#include <epoxy/gl.h>

#include "bench/HandWrittenShader5.h"
#include "core/Percentile.h"
#include "gl/GlContext.h"
#include "gl/GlExecutor.h"
#include "io/file/AtomicFile.h"
#include "validation/WorkspaceLoader.h"

namespace {

using namespace rmfx;
using WallClock = std::chrono::steady_clock;

glm::ivec2 frameSize{512, 512};
std::map<std::string, std::unique_ptr<Workspace>> workspaces;

double median(std::vector<double> values) { return values.empty() ? 0.0 : percentile(std::move(values), 0.5); }

double minimum(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }
double maximum(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

double threadCpuMilliseconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

double wallMilliseconds(WallClock::time_point from, WallClock::time_point to) {
    return std::chrono::duration<double, std::milli>(to - from).count();
}

// Google Benchmark calls a case several times (to find the iteration count, then once per
// repetition): executors are built, compiled and warmed up once per case and kept.
std::map<std::string, std::unique_ptr<GlExecutor>> executors;
std::unique_ptr<bench::HandWrittenShader5> handWritten, secondHandWritten;

// Frames before timing: llvmpipe compiles shader variants at their first draws.
bool warmUp(benchmark::State& state, GlExecutor& executor, int frames) {
    for (int i = 0; i < frames; ++i) {
        Diagnostics d = executor.renderFrame({}).takeDiagnostics();
        if (!d.empty()) {
            state.SkipWithError(("frame: " + formatAll(d)).c_str());
            return false;
        }
    }
    glFinish();
    return true;
}

GlExecutor* executorFor(benchmark::State& state, const std::string& key, const Workspace& ws,
                        const std::optional<std::vector<std::string>>& effects, bool poolTargets = true) {
    if (auto it = executors.find(key); it != executors.end()) return it->second.get();
    ExecutorOptions options;
    options.outputs = {"output"};
    options.effects = effects;
    options.poolTargets = poolTargets;
    auto created = GlExecutor::create(std::make_shared<const Workspace>(ws), frameSize, options);
    if (!created) {
        state.SkipWithError(("executor: " + formatAll(created.diagnostics())).c_str());
        return nullptr;
    }
    std::unique_ptr<GlExecutor> executor = std::move(*created);
    if (!warmUp(state, *executor, 3)) return nullptr;
    return (executors[key] = std::move(executor)).get();
}

// One executor, timed per frame (renderFrame + glFinish), then its counters.
void frameTime(benchmark::State& state, std::string key, const Workspace* ws,
               std::optional<std::vector<std::string>> effects) {
    GlExecutor* executor = executorFor(state, key, *ws, effects);
    if (!executor) return;
    FrameClock clock{0.0f, 1.0f / 60.0f};
    for (auto _ : state) {
        (void)executor->renderFrame(clock);
        glFinish();
        clock.time += clock.deltaTime;
    }
    // GPU time from timer queries, outside the timed loop: the queries cost a little.
    executor->setTimingEnabled(true);
    std::vector<double> gpu;
    for (int i = 0; i < 10; ++i) {
        (void)executor->renderFrame(clock);
        glFinish();  // the frame's queries are complete: passTimings collects this frame
        executor->passTimings();
        if (i >= 2) gpu.push_back(executor->frameGpuMilliseconds());
    }
    executor->setTimingEnabled(false);
    state.counters["gpu_ms"] = median(gpu);
    state.counters["passes"] = static_cast<double>(executor->passesRun().size());
    state.counters["alloc_KiB"] = static_cast<double>(executor->targetPlan().allocatedBytes) / 1024.0;
    state.counters["declared_KiB"] = static_cast<double>(executor->targetPlan().declaredBytes) / 1024.0;
}

// Per-frame samples, in milliseconds: the wall time to issue the frame's GL calls (no glFinish),
// the calling thread's CPU time over the same span, and the wall time to glFinish.
struct FrameSamples {
    std::vector<double> issue, cpu, frame;
};

void timeFrame(const std::function<void()>& render, FrameSamples& out) {
    auto start = WallClock::now();
    double cpuStart = threadCpuMilliseconds();
    render();
    double cpuEnd = threadCpuMilliseconds();
    auto issued = WallClock::now();
    glFinish();
    auto finished = WallClock::now();
    out.issue.push_back(wallMilliseconds(start, issued));
    out.cpu.push_back(cpuEnd - cpuStart);
    out.frame.push_back(wallMilliseconds(start, finished));
}

// Frames of the renderers interleaved, the first of each round rotating (a b c, b c a, c a b, …),
// so that none always runs first (caches, the rasteriser threads' state) and all see the same
// load on a shared machine.
void interleave(benchmark::State& state, const std::vector<std::function<void()>>& renderers,
                std::vector<FrameSamples>& samples) {
    samples.assign(renderers.size(), {});
    size_t first = 0;
    for (auto _ : state) {
        for (size_t k = 0; k < renderers.size(); ++k) {
            size_t i = (first + k) % renderers.size();
            timeFrame(renderers[i], samples[i]);
        }
        first = (first + 1) % renderers.size();
    }
    state.SetLabel(std::to_string(samples.front().frame.size()) + " frames each");
}

double overheadPercent(double measured, double reference) { return 100.0 * (measured - reference) / reference; }

// shader_5 asking for one effect against the workspace of only that effect, frames interleaved.
void oneEffectVsWorkspace(benchmark::State& state, std::string effect, std::string workspace) {
    GlExecutor* combined = executorFor(state, "effects/" + effect, *workspaces.at("shader_5"),
                                       std::vector<std::string>{effect});
    GlExecutor* single = executorFor(state, "workspace/" + workspace, *workspaces.at(workspace), std::nullopt);
    if (!combined || !single) return;
    FrameClock clock{0.0f, 1.0f / 60.0f};
    std::vector<FrameSamples> samples;
    interleave(state, {[&] { (void)combined->renderFrame(clock); }, [&] { (void)single->renderFrame(clock); }}, samples);
    double ms5 = median(samples[0].frame), msN = median(samples[1].frame);
    state.counters["shader_5_ms"] = ms5;
    state.counters["workspace_ms"] = msN;
    state.counters["ratio"] = ms5 / msN;
}

// The interpreter against the hand-written loop, frames interleaved: the executor as rmfx runs it
// (targets whose lifetimes do not overlap share memory) and with a texture per target, as the
// hand-written loop has.
void interpreterVsHand(benchmark::State& state) {
    const Workspace& ws = *workspaces.at("shader_5");
    GlExecutor* pooled = executorFor(state, "overhead", ws, std::nullopt);
    GlExecutor* ownMemory = executorFor(state, "overhead, no pooling", ws, std::nullopt, false);
    if (!pooled || !ownMemory) return;
    for (auto* hand : {&handWritten, &secondHandWritten}) {
        if (*hand) continue;
        auto created = bench::HandWrittenShader5::create(ws, frameSize);
        if (!created) {
            state.SkipWithError(("hand-written loop: " + created.error()).c_str());
            return;
        }
        *hand = std::move(*created);
        for (int i = 0; i < 3; ++i) (*hand)->renderFrame();
        glFinish();
    }
    bench::HandWrittenShader5& hand = *handWritten;
    bench::HandWrittenShader5& secondHand = *secondHandWritten;
    FrameClock clock{0.0f, 1.0f / 60.0f};
    std::vector<FrameSamples> samples;
    // A second, identical hand-written loop measures the method's own noise: its "overhead" over
    // the first would be 0 with perfect timing.
    interleave(state,
               {[&] { hand.renderFrame(); }, [&] { (void)pooled->renderFrame(clock); }, [&] { (void)ownMemory->renderFrame(clock); },
                [&] { secondHand.renderFrame(); }},
               samples);
    const char* names[4] = {"hand", "interp", "interp_own", "hand2"};
    const char* overheads[4] = {nullptr, "", "own_", "hand2_"};
    for (const auto& [what, member] : {std::pair<const char*, std::vector<double> FrameSamples::*>{"issue", &FrameSamples::issue},
                                       {"cpu", &FrameSamples::cpu}, {"frame", &FrameSamples::frame}}) {
        double ms[4];
        for (int i = 0; i < 4; ++i) {
            ms[i] = median(samples[static_cast<size_t>(i)].*member);
            state.counters[std::string(names[i]) + "_" + what + "_ms"] = ms[i];
            if (overheads[i])
                state.counters[std::string(overheads[i]) + what + "_overhead_pct"] = overheadPercent(ms[i], ms[0]);
        }
    }
    state.counters["passes"] = static_cast<double>(hand.passCount());
}

// The runs as the summary needs them: per benchmark, the median over repetitions (or the one
// run), the min and max of the repetitions, and the counters' medians.
struct Summary {
    double median = 0.0, min = 0.0, max = 0.0;
    std::map<std::string, double> counters, countersMin, countersMax;
    int repetitions = 1;
    std::string error;
};

class SummaryReporter : public benchmark::ConsoleReporter {
public:
    std::map<std::string, Summary> runs;

    void ReportRuns(const std::vector<Run>& report) override {
        ConsoleReporter::ReportRuns(report);
        for (const Run& run : report) {
            Summary& s = runs[run.run_name.function_name];
            if (run.error_occurred) s.error = run.error_message;
            double time = run.GetAdjustedRealTime();
            auto counters = [&](std::map<std::string, double>& out) {
                for (const auto& [name, counter] : run.counters) out[name] = counter.value;
            };
            if (run.run_type == Run::RT_Iteration) {
                if (run.repetitions > 1) continue;  // the aggregates follow
                s.median = s.min = s.max = time;
                counters(s.counters);
                counters(s.countersMin);
                counters(s.countersMax);
            } else if (run.aggregate_name == "median") {
                s.median = time;
                s.repetitions = static_cast<int>(run.repetitions);
                counters(s.counters);
            } else if (run.aggregate_name == "min") {
                s.min = time;
                counters(s.countersMin);
            } else if (run.aggregate_name == "max") {
                s.max = time;
                counters(s.countersMax);
            }
        }
    }
};

std::string fixed(double value, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
}

std::string mib(double kib) { return fixed(kib / 1024.0, 2); }

std::string markdownSummary(const std::map<std::string, Summary>& runs, const std::string& machine) {
    std::ostringstream out;
    auto find = [&](const std::string& name) -> const Summary* {
        auto it = runs.find(name);
        return it == runs.end() || !it->second.error.empty() ? nullptr : &it->second;
    };
    int repetitions = 1;
    for (const auto& [name, s] : runs) repetitions = std::max(repetitions, s.repetitions);
    out << "Machine: " << machine << "; frame size " << frameSize.x << "x" << frameSize.y << "; " << repetitions
        << (repetitions == 1 ? " repetition" : " repetitions")
        << (repetitions == 1 ? "" : " (the median of them; min–max their spread)") << ".\n\n";

    std::ostringstream rows;
    for (const char* subset : {"none", "glare", "streak", "ghost", "glare+streak", "glare+ghost", "streak+ghost",
                               "glare+streak+ghost"}) {
        const Summary* s = find(std::string("effects/") + subset);
        if (!s) continue;
        rows << "| " << subset << " | " << fixed(s->counters.at("passes"), 0) << " | "
             << mib(s->counters.at("alloc_KiB")) << " | " << mib(s->counters.at("declared_KiB")) << " | "
             << fixed(s->median, 2) << " | " << fixed(s->min, 2) << "–" << fixed(s->max, 2) << " | "
             << fixed(s->counters.at("gpu_ms"), 2) << " |\n";
    }

    if (!rows.str().empty())
        out << "### shader_5: frame time per subset of effects\n\n"
            << "Frame ms: renderFrame + glFinish, the median and min–max of the repetitions. GPU ms: the frame's "
               "span in timer queries, the median of 8 frames after the timed loop.\n\n"
            << "| effects asked for | passes run | target memory allocated (MiB) | declared (MiB) | frame ms "
               "(renderFrame + glFinish) | min–max | GPU ms (timer queries) |\n"
            << "|---|---:|---:|---:|---:|---:|---:|\n"
            << rows.str() << "\n";

    rows.str("");
    for (auto [effect, workspace] : {std::pair<const char*, const char*>{"glare", "shader_2"}, {"streak", "shader_3"},
                                     {"ghost", "shader_4"}}) {
        const Summary* paired = find(std::string("paired/") + effect + "_vs_" + workspace);
        if (!paired) continue;
        const Summary* a = find(std::string("effects/") + effect);
        const Summary* b = find(std::string("workspace/") + workspace);
        auto pair = [&](const char* counter, int decimals, double scale) {
            if (!a || !b) return std::string("?");
            return fixed(a->counters.at(counter) * scale, decimals) + ", " + fixed(b->counters.at(counter) * scale, decimals);
        };
        double ratio = paired->counters.at("ratio");
        rows << "| " << effect << " | " << workspace << " | " << pair("passes", 0, 1.0) << " | "
             << pair("alloc_KiB", 2, 1.0 / 1024.0) << " | " << fixed(paired->counters.at("shader_5_ms"), 2) << " | "
             << fixed(paired->counters.at("workspace_ms"), 2) << " | " << fixed(ratio, 3) << " | "
             << fixed(paired->countersMin.at("ratio"), 3) << "–" << fixed(paired->countersMax.at("ratio"), 3) << " | "
             << (ratio <= 1.10 ? "yes" : "no") << " | " << (a && b ? fixed(a->median / b->median, 3) : "?") << " |\n";
    }
    if (!rows.str().empty())
        out << "### One effect of shader_5 against the workspace of only that effect\n\n"
            << "Frames of the two interleaved in one loop (paired/…): the ratio of their median frame times "
               "(renderFrame + glFinish) per repetition; its median and min–max over the repetitions. The last "
               "column divides the medians of the separate effects/… and workspace/… cases instead.\n\n"
            << "| effect | workspace | passes (shader_5, workspace) | allocated MiB (shader_5, workspace) | "
               "shader_5 ms | workspace ms | ratio shader_5 / workspace | min–max | ≤ 1.10 | ratio of separate runs |\n"
            << "|---|---|---:|---:|---:|---:|---:|---:|---|---:|\n"
            << rows.str() << "\n";

    if (const Summary* s = find("overhead/interpreter_vs_hand")) {
        auto overhead = [&](const std::string& pct) {
            return fixed(s->counters.at(pct), 1) + " % | " + fixed(s->countersMin.at(pct), 1) + " … " +
                   fixed(s->countersMax.at(pct), 1) + " %";
        };
        auto row = [&](const char* label, const std::string& what) {
            out << "| " << label << " | " << fixed(s->counters.at("hand_" + what + "_ms"), 3) << " | "
                << fixed(s->counters.at("interp_" + what + "_ms"), 3) << " | " << overhead(what + "_overhead_pct")
                << " | " << fixed(s->counters.at("interp_own_" + what + "_ms"), 3) << " | "
                << overhead("own_" + what + "_overhead_pct") << " | " << overhead("hand2_" + what + "_overhead_pct")
                << " |\n";
        };
        out << "### Interpreter (GlExecutor::renderFrame) against a hand-written GL loop, shader_5 with all "
            << fixed(s->counters.at("passes"), 0) << " passes\n\n"
            << "Each repetition interleaves the four frame by frame and takes the median of each over its frames; "
               "an overhead is (interpreter - hand) / hand of those medians. The table gives the median over the "
               "repetitions of each column, so an overhead need not be the ratio of the medians beside it (they may "
               "come from different repetitions); min … max is the spread of the per-repetition overheads. The "
               "hand loop has a texture per target; the interpreter runs as rmfx does (targets whose lifetimes do "
               "not overlap share memory) and with a texture per target (poolTargets off). The last two columns "
               "time a second, identical hand-written loop against the first: the noise of the method.\n\n"
            << "| per frame | hand loop ms | interpreter ms | overhead | min … max | interpreter, a texture per "
               "target, ms | overhead | min … max | second hand loop: \"overhead\" | min … max |\n"
            << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
        row("CPU time to issue (wall clock, no glFinish)", "issue");
        row("CPU time to issue (thread CPU time)", "cpu");
        row("full frame (issue + glFinish, wall)", "frame");
    }
    return out.str();
}

bool parseSize(const std::string& text, glm::ivec2& size) {
    int w = 0, h = 0;
    char x = 0;
    std::istringstream in(text);
    if (!(in >> w)) return false;
    if (in >> x) {
        if ((x != 'x' && x != 'X') || !(in >> h)) return false;
    } else {
        h = w;
    }
    if (w < 4 || h < 4 || w > 8192 || h > 8192) return false;
    size = {w, h};
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    std::string markdownFile;
    if (const char* env = std::getenv("RMFX_BENCH_SIZE"); env && !parseSize(env, frameSize)) {
        std::fprintf(stderr, "RMFX_BENCH_SIZE='%s': expected N or WxH (4 to 8192)\n", env);
        return 1;
    }
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a.rfind("--size=", 0) == 0) {
            if (!parseSize(a.substr(7), frameSize)) {
                std::fprintf(stderr, "%s: expected --size=N or --size=WxH (4 to 8192)\n", a.c_str());
                return 1;
            }
        } else if (a.rfind("--markdown=", 0) == 0) {
            markdownFile = a.substr(11);
        } else {
            std::fprintf(stderr,
                         "unknown argument '%s'\nusage: rmfx_bench_effects [--size=N|WxH] [--markdown=FILE] "
                         "[Google Benchmark flags, e.g. --benchmark_repetitions=5]\n",
                         a.c_str());
            return 1;
        }
    }

    auto context = GlContext::createHeadless();
    if (!context) {
        std::fprintf(stderr, "no headless GL context: %s\n", context.error().c_str());
        return 1;
    }
    for (const char* name : {"shader_2", "shader_3", "shader_4", "shader_5"}) {
        Result<Workspace> loaded = loadWorkspace(std::filesystem::path(RMFX_SOURCE_DIR) / "effects" / (std::string(name) + ".xml"));
        if (!loaded.ok()) {
            std::fprintf(stderr, "%s", formatAll(loaded.diagnostics()).c_str());
            return 1;
        }
        workspaces[name] = std::make_unique<Workspace>(std::move(*loaded));
    }

    auto statistics = [](benchmark::internal::Benchmark* b) {
        b->Unit(benchmark::kMillisecond)->UseRealTime();
        b->ComputeStatistics("min", [](const std::vector<double>& v) { return minimum(v); });
        b->ComputeStatistics("max", [](const std::vector<double>& v) { return maximum(v); });
    };
    const Workspace* shader5 = workspaces.at("shader_5").get();
    std::vector<std::pair<std::string, std::vector<std::string>>> subsets = {
        {"none", {}},
        {"glare", {"glare"}},
        {"streak", {"streak"}},
        {"ghost", {"ghost"}},
        {"glare+streak", {"glare", "streak"}},
        {"glare+ghost", {"glare", "ghost"}},
        {"streak+ghost", {"streak", "ghost"}},
        {"glare+streak+ghost", {"glare", "streak", "ghost"}}};
    for (const auto& [name, effects] : subsets)
        statistics(benchmark::RegisterBenchmark(("effects/" + name).c_str(), frameTime, "effects/" + name, shader5,
                                                std::optional<std::vector<std::string>>(effects)));
    for (const char* name : {"shader_2", "shader_3", "shader_4"})
        statistics(benchmark::RegisterBenchmark((std::string("workspace/") + name).c_str(), frameTime,
                                                std::string("workspace/") + name, workspaces.at(name).get(),
                                                std::optional<std::vector<std::string>>()));
    for (auto [effect, workspace] : {std::pair<const char*, const char*>{"glare", "shader_2"}, {"streak", "shader_3"},
                                     {"ghost", "shader_4"}})
        statistics(benchmark::RegisterBenchmark((std::string("paired/") + effect + "_vs_" + workspace).c_str(),
                                                oneEffectVsWorkspace, std::string(effect), std::string(workspace))
                       ->MinTime(3.0));
    statistics(benchmark::RegisterBenchmark("overhead/interpreter_vs_hand", interpreterVsHand)->MinTime(10.0));

    SummaryReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);

    std::string machine = (*context)->description() + ", " + std::to_string(std::thread::hardware_concurrency()) +
                          " CPU threads";
    std::string summary = markdownSummary(reporter.runs, machine);
    std::printf("\n%s", summary.c_str());
    if (!markdownFile.empty()) {
        if (Result<void> written = writeFileAtomically(markdownFile, summary, false); !written) {
            std::fprintf(stderr, "%s\n", written.error().c_str());
            return 1;
        }
    }
    executors.clear();
    handWritten.reset();
    secondHandWritten.reset();
    benchmark::Shutdown();
    return 0;
}
