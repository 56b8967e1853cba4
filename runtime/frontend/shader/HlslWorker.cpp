#include "frontend/shader/HlslWorker.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "core/IsolatedProgram.h"

namespace rmfx {

namespace {
const char kWorkerName[] = "rmfx-hlsl-worker";

bool executable(const std::string& path) { return !path.empty() && ::access(path.c_str(), X_OK) == 0; }
}  // namespace

Result<std::string> hlslWorkerProgram() {
    if (const char* chosen = std::getenv("RMFX_HLSL_WORKER"); chosen && *chosen) {
        if (executable(chosen)) return std::string(chosen);
        return Error{"RMFX_HLSL_WORKER names '" + std::string(chosen) + "', which is not a program that can be run"};
    }
    std::error_code error;
    std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    std::string beside = error ? std::string() : (self.parent_path() / kWorkerName).string();
    if (executable(beside)) return beside;
    std::string built = RMFX_HLSL_WORKER_BUILD_PATH;
    if (executable(built)) return built;
    return Error{"cannot find " + std::string(kWorkerName) + ", the program that runs glslang's HLSL front end: not at " +
                 (beside.empty() ? std::string() : "'" + beside + "' (beside this program) nor at ") + "'" + built +
                 "' (where this build put it); set RMFX_HLSL_WORKER to its path"};
}

Result<GlslangHlslOutcome> compileHlslInWorker(const GlslangHlslRequest& request, std::chrono::milliseconds timeout) {
    Result<std::string> program = hlslWorkerProgram();
    if (!program) return Error{program.error()};
    Result<std::string> bytes = runIsolatedProgram(*program, {}, request.serialize(), timeout);
    if (!bytes) return Error{"glslang " + bytes.error()};
    return GlslangHlslOutcome::deserialize(*bytes);
}

}  // namespace rmfx
