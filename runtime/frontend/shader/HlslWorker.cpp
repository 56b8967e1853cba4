#include "frontend/shader/HlslWorker.h"

#include "core/IsolatedProgram.h"
#include "core/ProgramBeside.h"

namespace rmfx {

Result<std::string> hlslWorkerProgram() {
    return findProgram({"rmfx-hlsl-worker", "RMFX_HLSL_WORKER", RMFX_HLSL_WORKER_BUILD_PATH,
                        "the program that runs glslang's HLSL front end"});
}

Result<GlslangHlslOutcome> compileHlslInWorker(const GlslangHlslRequest& request, std::chrono::milliseconds timeout) {
    Result<std::string> program = hlslWorkerProgram();
    if (!program) return Error{program.error()};
    Result<std::string> bytes = runIsolatedProgram(*program, {}, request.serialize(), timeout);
    if (!bytes) return Error{"glslang " + bytes.error()};
    return GlslangHlslOutcome::deserialize(*bytes);
}

}  // namespace rmfx
