// rmfx_bench_cold_render: where a cold `rmfx render WORKSPACE --size WxH -o OUT.png` spends its
// time and memory. Each run is a fresh process (this program started again with --once, so that
// the dynamic linker's, glslang's and the driver's first-use costs count, as they do for a user),
// which times the phases a render goes through and reads its peak resident memory (VmHWM) after
// each:
//   start     from the parent's spawn to main(): exec, the shared libraries loaded and linked
//   load      parse the workspace, resolve its media, validate it (glslang compiles every pass)
//   compile   plan the frame with validation's programs (compile/RunPreparation.h)
//   context   the headless EGL context
//   codecs wait   what is left of loading OpenImageIO (io/image/ImageCodecs.h), which started with
//             the process on a thread of its own: the wait for it before the first image reads
//   gl build  GlExecutor::create: the driver compiles and links, textures load, targets allocate
//   frame     the first frame, to glFinish
//   write     read the output back and write the PNG
// The parent prints the median of each phase over the runs, and their spread. With --against
// PROGRAM (another build's rmfx), each run also times `rmfx render` of this build and of PROGRAM
// as whole processes, one after the other, with their peak memory: the two builds side by side.
//
//   rmfx_bench_cold_render [--runs N] [--size WxH] [--against OTHER_RMFX] [WORKSPACE]
//   (default: effects/shader_5.xml, 128x128, 7 runs)

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <epoxy/gl.h>

#include "compile/CompiledFrame.h"
#include "compile/RunPreparation.h"
#include "core/Percentile.h"
#include "gl/GlContext.h"
#include "gl/GlExecutor.h"
#include "io/image/ImageCodecs.h"
#include "io/image/ImageIO.h"
#include "validation/WorkspaceLoader.h"

namespace {

using Clock = std::chrono::steady_clock;
const char* const kPhases[] = {"start", "load", "compile", "context", "codecs wait", "gl build", "frame", "write"};

long peakResidentKiB() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmHWM:", 0) == 0) return std::strtol(line.c_str() + 6, nullptr, 10);
    return -1;
}

long long monotonicNanoseconds() {
    timespec t{};
    clock_gettime(CLOCK_MONOTONIC, &t);
    return static_cast<long long>(t.tv_sec) * 1000000000LL + t.tv_nsec;
}

struct Spawned {
    int status = -1;
    double milliseconds = 0.0;  // from the spawn to the exit
    double peakMiB = 0.0;       // the child's largest resident set
    std::string out;            // its standard output
};

// Runs `argv` (no shell) to its end, with its standard output read through a pipe.
Spawned spawnAndWait(const std::vector<std::string>& argv) {
    Spawned result;
    int pipeEnds[2];
    if (pipe(pipeEnds) != 0) return result;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pipeEnds[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, pipeEnds[0]);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const long long started = monotonicNanoseconds();
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(pipeEnds[1]);
    if (spawned != 0) {
        close(pipeEnds[0]);
        return result;
    }
    char buffer[4096];
    for (ssize_t n; (n = read(pipeEnds[0], buffer, sizeof buffer)) > 0;) result.out.append(buffer, static_cast<size_t>(n));
    close(pipeEnds[0]);
    rusage usage{};
    int status = 0;
    wait4(pid, &status, 0, &usage);
    result.milliseconds = (monotonicNanoseconds() - started) / 1e6;
    result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.peakMiB = usage.ru_maxrss / 1024.0;
    return result;
}

// One cold render; prints "phase milliseconds peakKiB" per phase. Non-zero on any error.
// `spawnedAt`: the parent's monotonic clock when it spawned this process.
int renderOnce(const std::filesystem::path& workspace, glm::ivec2 size, const std::filesystem::path& output, long long spawnedAt) {
    using namespace rmfx;
    auto start = Clock::now();
    std::printf("start\t%.3f\t%ld\n", (monotonicNanoseconds() - spawnedAt) / 1e6, peakResidentKiB());
    auto phaseDone = [&](const char* phase) {
        const auto now = Clock::now();
        std::printf("%s\t%.3f\t%ld\n", phase, std::chrono::duration<double, std::milli>(now - start).count(), peakResidentKiB());
        start = now;
    };
    startLoadingImageCodecs(GlContext::prepareHeadlessDisplay);  // as rmfx render does: OpenImageIO loads meanwhile, on a thread
    RunRequest request;
    request.workspace = workspace;
    request.size = size;
    Result<LoadedRun> loaded = loadRun(request);
    if (!loaded) return std::cerr << formatAll(loaded.diagnostics()), 1;
    phaseDone("load");
    const std::string outputTarget = loaded->ws.outputTargetName();
    const GlProfile profile = loaded->ws.profile;
    request.plan.outputs = {outputTarget};
    auto prepared = compileRun(std::move(*loaded), request);
    if (!prepared) return std::cerr << formatAll(prepared.diagnostics()), 1;
    const std::shared_ptr<const CompiledFrame> frame = prepared->frame;
    phaseDone("compile");
    auto context = GlContext::createHeadless(profile);
    if (!context) return std::cerr << context.error() << "\n", 1;
    phaseDone("context");
    if (const auto& codecs = imageCodecs(); !codecs) return std::cerr << codecs.error() << "\n", 1;
    phaseDone("codecs wait");
    auto executor = GlExecutor::create(frame);
    if (!executor) return std::cerr << formatAll(executor.diagnostics()), 1;
    phaseDone("gl build");
    if (auto rendered = (*executor)->renderFrame({0.0f, 1.0f / 60.0f}); !rendered) return std::cerr << formatAll(rendered.diagnostics()), 1;
    glFinish();
    phaseDone("frame");
    auto image = (*executor)->readTarget(outputTarget);
    if (!image) return std::cerr << image.error() << "\n", 1;
    WriteOptions write;
    write.transform = frame->ws().output.transform;
    if (auto written = writeImage(output, *image, write); !written) return std::cerr << written.error() << "\n", 1;
    phaseDone("write");
    return 0;
}

}  // namespace

void printMedianRow(const char* name, std::vector<double> values, double whole, double peakMiB) {
    std::printf("| %s | %.1f | %.1f … %.1f | %.0f %% | %.1f |\n", name, rmfx::percentile(values, 0.5),
                *std::min_element(values.begin(), values.end()), *std::max_element(values.begin(), values.end()),
                100.0 * rmfx::percentile(values, 0.5) / whole, peakMiB);
}

int main(int argc, char** argv) {
    std::filesystem::path workspace = std::filesystem::path(RMFX_SOURCE_DIR) / "effects" / "shader_5.xml";
    glm::ivec2 size{128, 128};
    int runs = 7;
    bool once = false;
    long long spawnedAt = 0;
    std::string against;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--once" && i + 1 < argc) once = true, spawnedAt = std::atoll(argv[++i]);
        else if (a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
        else if (a == "--size" && i + 1 < argc && std::sscanf(argv[i + 1], "%dx%d", &size.x, &size.y) == 2) ++i;
        else if (a == "--against" && i + 1 < argc) against = std::filesystem::absolute(argv[++i]).string();
        else if (!a.empty() && a[0] != '-') workspace = a;
        else return std::cerr << "usage: rmfx_bench_cold_render [--runs N] [--size WxH] [--against OTHER_RMFX] [WORKSPACE]\n", 2;
    }
    const std::filesystem::path output = std::filesystem::temp_directory_path() / ("rmfx-cold-" + std::to_string(getpid()) + ".png");
    if (once) return renderOnce(workspace, size, output, spawnedAt);

    const std::filesystem::path self = std::filesystem::canonical("/proc/self/exe");
    const std::string sizeText = std::to_string(size.x) + "x" + std::to_string(size.y);
    const std::string thisRmfx = (self.parent_path() / "rmfx").string();
    std::map<std::string, std::vector<double>> ms, peak;
    std::vector<double> total;
    std::map<std::string, std::vector<double>> whole, wholePeak;  // by build: whole `rmfx render` processes
    for (int r = 0; r < runs; ++r) {
        Spawned child = spawnAndWait({self.string(), "--once", std::to_string(monotonicNanoseconds()), "--size", sizeText, workspace.string()});
        if (child.status != 0) return std::cerr << "a run failed: " << self << " --once … " << workspace << "\n", 1;
        std::istringstream lines(child.out);
        double sum = 0.0;
        for (std::string line; std::getline(lines, line);) {
            std::istringstream fields(line);
            std::string phase, millis, kib;
            std::getline(fields, phase, '\t');
            std::getline(fields, millis, '\t');
            std::getline(fields, kib);
            ms[phase].push_back(std::stod(millis));
            peak[phase].push_back(std::stod(kib) / 1024.0);
            sum += std::stod(millis);
        }
        total.push_back(sum);
        if (against.empty()) continue;
        // The two builds one after the other in each round, so that the machine's load falls on both.
        for (const std::string& rmfx : {thisRmfx, against}) {
            Spawned render = spawnAndWait({rmfx, "render", workspace.string(), "--size", sizeText, "-o", output.string(), "-q"});
            if (render.status != 0) return std::cerr << "a run failed: " << rmfx << " render " << workspace << "\n", 1;
            whole[rmfx].push_back(render.milliseconds);
            wholePeak[rmfx].push_back(render.peakMiB);
        }
    }
    std::filesystem::remove(output);
    std::printf("cold render of %s at %dx%d, %d runs (each a fresh process); median and min … max\n\n", workspace.filename().c_str(),
                size.x, size.y, runs);
    std::printf("| phase | ms | min … max | share | peak resident MiB after it |\n|---|---:|---:|---:|---:|\n");
    const double median = rmfx::percentile(total, 0.5);
    for (const char* phase : kPhases) printMedianRow(phase, ms[phase], median, rmfx::percentile(peak[phase], 0.5));
    std::printf("| whole render | %.1f | %.1f … %.1f | 100 %% | |\n", median, *std::min_element(total.begin(), total.end()),
                *std::max_element(total.begin(), total.end()));
    if (against.empty()) return 0;
    std::printf("\n`rmfx render %s --size %s -o OUT.png -q` as a whole process, the two builds alternating\n\n",
                workspace.filename().c_str(), sizeText.c_str());
    std::printf("| rmfx | ms | min … max | peak resident MiB | time against this build |\n|---|---:|---:|---:|---:|\n");
    const double ours = rmfx::percentile(whole[thisRmfx], 0.5);
    for (const std::string& rmfx : {thisRmfx, against}) {
        const std::vector<double>& t = whole[rmfx];
        std::printf("| %s | %.1f | %.1f … %.1f | %.1f | %.2f |\n", rmfx.c_str(), rmfx::percentile(t, 0.5),
                    *std::min_element(t.begin(), t.end()), *std::max_element(t.begin(), t.end()),
                    rmfx::percentile(wholePeak[rmfx], 0.5), rmfx::percentile(t, 0.5) / ours);
    }
    return 0;
}
