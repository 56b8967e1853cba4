// Renders a workspace headless through rmfx's public API, as a program outside the project does
// (docs/library.md), and checks what it read back:
//   outside WORKSPACE REFERENCE_EXR PREFIX
// renders WORKSPACE (effects/shader_1.xml) at 64x64 with Exposure_Level 0.25 and 0.5, then checks
//  - the effect's maths: every colour is the environment times Exposure_Level (glsl/sky.frag,
//    glsl/teapot.frag), so where neither render is clipped the second is twice the first;
//  - the rmfx command's render of the same workspace at Exposure_Level 0.5 (REFERENCE_EXR, read
//    through the installed image codecs module): the same pixels;
//  - that the codecs module and the HLSL worker were found in the installed package under PREFIX;
//  - that a broken request comes back as diagnostics naming the file.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "compile/RunPreparation.h"
#include "core/ProgramBeside.h"
#include "gl/GlContext.h"
#include "io/image/ImageIO.h"
#include "run/HeadlessRun.h"

namespace {

int failures = 0;

void check(bool ok, const std::string& what) {
    std::cout << (ok ? "ok:   " : "FAIL: ") << what << "\n";
    if (!ok) ++failures;
}

// Loads, validates and compiles the workspace with Exposure_Level set, renders one frame at 64x64
// and reads its output back (float RGBA, row 0 at the top).
rmfx::Result<rmfx::Image> render(const std::string& workspace, const std::string& exposure) {
    rmfx::RunRequest request;
    request.workspace = workspace;
    request.size = {64, 64};
    request.overrides = {{"Exposure_Level", exposure}};
    rmfx::Result<rmfx::LoadedRun> loaded = rmfx::loadRun(request);
    if (!loaded) return rmfx::Error{rmfx::formatAll(loaded.diagnostics())};
    request.plan.outputs = {loaded->ws.outputTargetName()};
    rmfx::Result<rmfx::PreparedRun> prepared = rmfx::compileRun(std::move(*loaded), request);
    if (!prepared) return rmfx::Error{rmfx::formatAll(prepared.diagnostics())};

    auto context = rmfx::GlContext::createHeadless(prepared->ws().profile);
    if (!context) return rmfx::Error{context.error()};
    auto executor = rmfx::runHeadless(*prepared, rmfx::RunSettings(prepared->viewport(), 1));
    if (!executor) return rmfx::Error{rmfx::formatAll(executor.diagnostics())};
    return (*executor)->readTarget(prepared->ws().outputTargetName());
}

bool under(const std::string& path, const std::string& prefix) { return path.rfind(prefix + "/", 0) == 0; }

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: outside WORKSPACE REFERENCE_EXR PREFIX\n";
        return 2;
    }
    const std::string workspace = argv[1], reference = argv[2], prefix = argv[3];

    rmfx::Result<rmfx::Image> quarter = render(workspace, "0.25");
    rmfx::Result<rmfx::Image> half = render(workspace, "0.5");
    if (!quarter || !half) {
        std::cerr << (quarter ? half.error() : quarter.error()) << "\n";
        return 1;
    }
    check(half->width == 64 && half->height == 64 && half->channels == 4, "the output is 64x64 RGBA");

    // Exposure_Level scales the whole scene: twice the exposure, twice the colour (half floats in
    // the scene target: within 2^-10 of each, relative).
    int compared = 0, lit = 0;
    double worst = 0.0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            for (int c = 0; c < 3; ++c) {
                const float a = quarter->at(x, y, c), b = half->at(x, y, c);
                if (b > 1e-3f) ++lit;
                if (b < 1e-3f || b > 0.99f) continue;  // dark, or clipped where the screen clips
                worst = std::max(worst, std::abs(double(b) - 2.0 * a) / b);
                ++compared;
            }
    check(lit > 64 * 64, "the render is not black (" + std::to_string(lit) + " lit channels)");
    check(compared > 1000 && worst < 4e-3, "Exposure_Level 0.5 is twice 0.25 (" + std::to_string(compared) +
                                               " channels, worst relative difference " + std::to_string(worst) + ")");

    rmfx::Result<rmfx::Image> command = rmfx::readImage(reference);
    if (!command) {
        check(false, "read the rmfx command's render: " + command.error());
    } else {
        double most = 0.0;
        bool sameSize = command->width == 64 && command->height == 64 && command->channels >= 3;
        for (int y = 0; sameSize && y < 64; ++y)
            for (int x = 0; x < 64; ++x)
                for (int c = 0; c < 3; ++c) most = std::max(most, double(std::abs(command->at(x, y, c) - half->at(x, y, c))));
        check(sameSize && most < 1e-3, "the rmfx command's render is the same (largest difference " + std::to_string(most) + ")");
    }

    // The codecs module this process loaded is the installed one (found from librmfx.so by dladdr).
    std::ifstream maps("/proc/self/maps");
    std::string line, codecs;
    while (std::getline(maps, line))
        if (auto at = line.find('/'); at != std::string::npos && line.find("rmfx-image-codecs.so") != std::string::npos)
            codecs = line.substr(at);
    check(under(codecs, prefix), "the image codecs module came from the install: '" + codecs + "'");

    // The HLSL worker is found in the package too, with no build folder to fall back on.
    rmfx::Result<std::string> worker = rmfx::findProgram(
        {"rmfx-hlsl-worker", "RMFX_HLSL_WORKER", "/nonexistent/rmfx-hlsl-worker", "the HLSL worker", rmfx::InstallFolder::Libexec});
    check(worker && under(*worker, prefix), "the HLSL worker is the installed one: '" + (worker ? *worker : worker.error()) + "'");

    // Errors come back as diagnostics with the file (and line and element where there is one).
    rmfx::RunRequest missing;
    missing.workspace = prefix + "/no-such-workspace.xml";
    rmfx::Result<rmfx::LoadedRun> broken = rmfx::loadRun(missing);
    check(!broken && !broken.diagnostics().empty() &&
              broken.diagnostics().front().where.file.find("no-such-workspace.xml") != std::string::npos,
          "a missing workspace is a diagnostic naming it: " + (broken ? std::string("loaded") : rmfx::formatAll(broken.diagnostics())));

    std::cout << (failures ? "FAILED\n" : "passed\n");
    return failures ? 1 : 0;
}
