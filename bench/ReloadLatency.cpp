// Hot-reload latency on a real effect: opens a LiveWorkspace on a copy of effects/shader_5.xml
// (20 passes) in a temporary folder, then N times saves a file the way editors do (a temporary
// file renamed over the original) and measures the time from just before the write to the end of
// the rebuild: poll() is called every millisecond until it reports the reload. Prints min,
// median, p95 and max in ms for each kind of file, and the frames: one without a reload, the first
// one after a reload, and the time from the write until that frame is read back.
//
//   rmfx_bench_reload [--iterations N] [--keep]
//
// An editor polls once per displayed frame, so its latency adds up to one frame interval to these.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "core/Percentile.h"
#include "gl/GlContext.h"
#include "run/LiveWorkspace.h"

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using rmfx::percentile;

namespace {

struct Edit {
    std::string label;
    fs::path file;  // relative to the copy of effects/
};

std::string readAll(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

void saveAtomically(const fs::path& file, const std::string& text) {
    fs::path temporary = file.parent_path() / ("." + file.filename().string() + ".tmp");
    {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
    }
    fs::rename(temporary, file);
}

void printRow(const std::string& label, const std::vector<double>& ms) {
    if (ms.empty()) return;
    std::printf("%-44s %5zu %8.1f %8.1f %8.1f %8.1f\n", label.c_str(), ms.size(), percentile(ms, 0.0),
                percentile(ms, 0.5), percentile(ms, 0.95), percentile(ms, 1.0));
}

}  // namespace

int main(int argc, char** argv) {
    int iterations = 50;
    bool keep = false;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--iterations" && i + 1 < argc) {
            iterations = std::max(1, std::atoi(argv[++i]));
        } else if (a == "--keep") {
            keep = true;
        } else {
            std::fprintf(stderr, "usage: rmfx_bench_reload [--iterations N] [--keep]\n");
            return 1;
        }
    }

    auto context = rmfx::GlContext::createHeadless();
    if (!context) {
        std::fprintf(stderr, "error: no GL context: %s\n", context.error().c_str());
        return 2;
    }

    // A copy of effects/ and the media it reads (../samples/media), so the real files stay untouched.
    fs::path source = RMFX_SOURCE_DIR;
    std::string pattern = (fs::temp_directory_path() / "rmfx_bench_reload.XXXXXX").string();
    if (!mkdtemp(pattern.data())) {
        std::fprintf(stderr, "error: cannot create a temporary folder\n");
        return 2;
    }
    fs::path root = pattern;
    fs::create_directories(root / "effects");
    fs::copy(source / "effects" / "shader_5.xml", root / "effects" / "shader_5.xml");
    fs::copy(source / "effects" / "glsl", root / "effects" / "glsl", fs::copy_options::recursive);
    fs::create_directories(root / "samples");
    fs::copy(source / "samples" / "media", root / "samples" / "media", fs::copy_options::recursive);
    fs::path workspaceFile = root / "effects" / "shader_5.xml";

    auto opened = Clock::now();
    auto session = rmfx::LiveWorkspace::open(workspaceFile, {0, 0}, {});
    double openMs = std::chrono::duration<double, std::milli>(Clock::now() - opened).count();
    if (!session) {
        std::fprintf(stderr, "%s", rmfx::formatAll(session.diagnostics()).c_str());
        return 1;
    }
    std::unique_ptr<rmfx::LiveWorkspace> live = std::move(*session);
    (void)live->executor().renderFrame({});
    std::printf("%s\n", context.value()->description().c_str());
    std::printf("workspace %s: %zu passes, %zu watched files; first build %.1f ms\n", workspaceFile.string().c_str(),
                live->workspace().passes.size(), live->watchedFiles().size(), openMs);
    std::printf("%d saves of each file (temporary file + rename), poll() every 1 ms\n\n", iterations);
    std::printf("%-44s %5s %8s %8s %8s %8s\n", "ms from the write to the end of the rebuild", "n", "min", "median", "p95",
                "max");

    std::vector<Edit> edits = {
        {"glsl/all_combine.frag (1 pass)", "glsl/all_combine.frag"},
        {"glsl/environment.glsl, an include (2 passes)", "glsl/environment.glsl"},
        {"glsl/streak.frag (8 passes)", "glsl/streak.frag"},
        {"shader_5.xml (the workspace: everything)", "shader_5.xml"},
    };
    // llvmpipe compiles a program's machine code at its first draw, not at link: the first frame
    // after a reload pays for that. A frame without a reload, for comparison:
    std::vector<double> steadyFrames;
    for (int i = 0; i < 10; ++i) {
        auto frameStart = Clock::now();
        (void)live->executor().renderFrame({});
        (void)live->executor().readTarget(live->workspace().outputTargetName());  // waits for the GPU
        steadyFrames.push_back(std::chrono::duration<double, std::milli>(Clock::now() - frameStart).count());
    }
    std::vector<double> firstFrames, visible;
    int failures = 0;
    for (const Edit& edit : edits) {
        fs::path file = root / "effects" / edit.file;
        std::string original = readAll(file);
        std::vector<double> latencies, reported;
        for (int i = 0; i < iterations; ++i) {
            // A different text each time (a comment), so no shader cache can answer for the compiler.
            std::string text = original + (edit.file.extension() == ".xml" ? "<!-- revision " : "// revision ") +
                               std::to_string(i) + (edit.file.extension() == ".xml" ? " -->\n" : "\n");
            auto written = Clock::now();
            saveAtomically(file, text);
            bool reloaded = false;
            while (!reloaded && Clock::now() - written < std::chrono::seconds(10)) {
                reloaded = live->poll();
                if (!reloaded) std::this_thread::sleep_for(std::chrono::milliseconds(1));
            }
            auto done = Clock::now();
            if (!reloaded || !live->errors().empty()) {
                std::fprintf(stderr, "reload of %s failed: %s\n", edit.file.c_str(),
                             reloaded ? rmfx::formatAll(live->errors()).c_str() : "no reload within 10 s\n");
                ++failures;
                continue;
            }
            latencies.push_back(std::chrono::duration<double, std::milli>(done - written).count());
            reported.push_back(live->lastReloadMilliseconds());
            auto frameStart = Clock::now();
            (void)live->executor().renderFrame({});
            (void)live->executor().readTarget(live->workspace().outputTargetName());  // waits for the GPU
            firstFrames.push_back(std::chrono::duration<double, std::milli>(Clock::now() - frameStart).count());
            visible.push_back(std::chrono::duration<double, std::milli>(Clock::now() - written).count());
        }
        printRow(edit.label, latencies);
        printRow("  as lastReloadMilliseconds() reports it", reported);
    }
    std::printf("\n");
    printRow("a frame without a reload (render + read back)", steadyFrames);
    printRow("the first frame after a reload", firstFrames);
    printRow("from the write to that frame read back", visible);

    if (!keep) fs::remove_all(root);
    else std::printf("\nkept %s\n", root.string().c_str());
    return failures ? 1 : 0;
}
