// rmfx_bench_cold_render: where a cold `rmfx render WORKSPACE --size WxH -o OUT.png` spends its
// time and memory. Each run is a fresh process (this program started again with --once, so that
// glslang's and the driver's first-use costs count, as they do for a user), which times the phases
// a render goes through and reads its peak resident memory (VmHWM) after each:
//   start     main() reached: the libraries loaded, nothing done
//   load      parse the workspace, resolve its media, validate it (glslang compiles every pass)
//   compile   plan the frame and assemble every runnable pass's program (compile/CompiledFrame.h)
//   context   the headless EGL context
//   gl build  GlExecutor::create: the driver compiles and links, textures load, targets allocate
//   frame     the first frame, to glFinish
//   write     read the output back and write the PNG
// The parent prints the median of each phase over the runs, and their spread.
//
//   rmfx_bench_cold_render [--runs N] [--size WxH] [WORKSPACE]   (default: effects/shader_5.xml, 128x128, 7 runs)

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
#include "core/Percentile.h"
#include "gl/GlContext.h"
#include "gl/GlExecutor.h"
#include "io/image/ImageIO.h"
#include "validation/WorkspaceLoader.h"

namespace {

using Clock = std::chrono::steady_clock;
const char* const kPhases[] = {"start", "load", "compile", "context", "gl build", "frame", "write"};

long peakResidentKiB() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmHWM:", 0) == 0) return std::strtol(line.c_str() + 6, nullptr, 10);
    return -1;
}

// One cold render; prints "phase milliseconds peakKiB" per phase. Non-zero on any error.
int renderOnce(const std::filesystem::path& workspace, glm::ivec2 size, const std::filesystem::path& output) {
    using namespace rmfx;
    auto start = Clock::now();
    auto phaseDone = [&](const char* phase) {
        const auto now = Clock::now();
        std::printf("%s\t%.3f\t%ld\n", phase, std::chrono::duration<double, std::milli>(now - start).count(), peakResidentKiB());
        start = now;
    };
    phaseDone("start");  // the process with its libraries loaded, before any work
    Result<Workspace> loaded = loadWorkspace(workspace);
    if (!loaded) return std::cerr << formatAll(loaded.diagnostics()), 1;
    phaseDone("load");
    const std::string outputTarget = loaded->outputTargetName();
    const GlProfile profile = loaded->profile;
    FramePlanOptions options;
    options.outputs = {outputTarget};
    auto frame = compileFrame(std::make_shared<const Workspace>(std::move(*loaded)), options, size);
    if (!frame) return std::cerr << formatAll(frame.diagnostics()), 1;
    phaseDone("compile");
    auto context = GlContext::createHeadless(profile);
    if (!context) return std::cerr << context.error() << "\n", 1;
    phaseDone("context");
    auto executor = GlExecutor::create(*frame);
    if (!executor) return std::cerr << formatAll(executor.diagnostics()), 1;
    phaseDone("gl build");
    if (auto rendered = (*executor)->renderFrame({0.0f, 1.0f / 60.0f}); !rendered) return std::cerr << formatAll(rendered.diagnostics()), 1;
    glFinish();
    phaseDone("frame");
    auto image = (*executor)->readTarget(outputTarget);
    if (!image) return std::cerr << image.error() << "\n", 1;
    WriteOptions write;
    write.transform = (*frame)->ws().output.transform;
    if (auto written = writeImage(output, *image, write); !written) return std::cerr << written.error() << "\n", 1;
    phaseDone("write");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::filesystem::path workspace = std::filesystem::path(RMFX_SOURCE_DIR) / "effects" / "shader_5.xml";
    glm::ivec2 size{128, 128};
    int runs = 7;
    bool once = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--once") once = true;
        else if (a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
        else if (a == "--size" && i + 1 < argc && std::sscanf(argv[i + 1], "%dx%d", &size.x, &size.y) == 2) ++i;
        else if (!a.empty() && a[0] != '-') workspace = a;
        else return std::cerr << "usage: rmfx_bench_cold_render [--runs N] [--size WxH] [WORKSPACE]\n", 2;
    }
    const std::filesystem::path output = std::filesystem::temp_directory_path() / ("rmfx-cold-" + std::to_string(getpid()) + ".png");
    if (once) return renderOnce(workspace, size, output);

    std::map<std::string, std::vector<double>> ms, peak;
    std::vector<double> total;
    const std::string self = std::filesystem::canonical("/proc/self/exe").string();
    for (int r = 0; r < runs; ++r) {
        const std::string command = "'" + self + "' --once --size " + std::to_string(size.x) + "x" + std::to_string(size.y) + " '" +
                                    workspace.string() + "'";
        FILE* child = popen(command.c_str(), "r");
        if (!child) return std::cerr << "cannot start " << command << "\n", 1;
        char line[512];
        double sum = 0.0;
        while (std::fgets(line, sizeof line, child)) {
            std::istringstream fields(line);
            std::string phase, millis, kib;
            std::getline(fields, phase, '\t');
            std::getline(fields, millis, '\t');
            std::getline(fields, kib);
            ms[phase].push_back(std::stod(millis));
            peak[phase].push_back(std::stod(kib) / 1024.0);
            sum += std::stod(millis);
        }
        if (pclose(child) != 0) return std::cerr << "a run failed: " << command << "\n", 1;
        total.push_back(sum);
    }
    std::filesystem::remove(output);
    std::printf("cold render of %s at %dx%d, %d runs (each a fresh process); median and min … max\n\n", workspace.filename().c_str(),
                size.x, size.y, runs);
    std::printf("| phase | ms | min … max | share | peak resident MiB after it |\n|---|---:|---:|---:|---:|\n");
    const double whole = rmfx::percentile(total, 0.5);
    for (const char* phase : kPhases) {
        std::vector<double>& t = ms[phase];
        std::printf("| %s | %.1f | %.1f … %.1f | %.0f %% | %.1f |\n", phase, rmfx::percentile(t, 0.5), *std::min_element(t.begin(), t.end()),
                    *std::max_element(t.begin(), t.end()), 100.0 * rmfx::percentile(t, 0.5) / whole, rmfx::percentile(peak[phase], 0.5));
    }
    std::printf("| whole render | %.1f | %.1f … %.1f | 100 %% | |\n", whole, *std::min_element(total.begin(), total.end()),
                *std::max_element(total.begin(), total.end()));
    return 0;
}
