#include "frontend/shader/HlslWorker.h"

#include <memory>
#include <mutex>

#include "core/IsolatedWorker.h"
#include "core/ProgramBeside.h"

namespace rmfx {

namespace {

// The run's worker, replaced when hlslWorkerProgram() names another program. Shared, so that a
// replacement waits for the requests the old one is serving; destroyed at exit, which ends it.
struct RunWorker {
    std::mutex mutex;
    std::shared_ptr<IsolatedWorker> worker;

    std::shared_ptr<IsolatedWorker> forProgram(const std::string& program) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!worker || worker->program() != program) worker = std::make_shared<IsolatedWorker>(program);
        return worker;
    }
    std::shared_ptr<IsolatedWorker> current() {
        std::lock_guard<std::mutex> lock(mutex);
        return worker;
    }
};

RunWorker& runWorker() {
    static RunWorker instance;
    return instance;
}

}  // namespace

Result<std::string> hlslWorkerProgram() {
    return findProgram({"rmfx-hlsl-worker", "RMFX_HLSL_WORKER", RMFX_HLSL_WORKER_BUILD_PATH,
                        "the program that runs glslang's HLSL front end", InstallFolder::Libexec});
}

Result<GlslangHlslOutcome> compileHlslInWorker(const GlslangHlslRequest& request, std::chrono::milliseconds timeout) {
    Result<std::string> program = hlslWorkerProgram();
    if (!program) return Error{program.error()};
    Result<std::string> bytes = runWorker().forProgram(*program)->request(request.serialize(), timeout);
    if (!bytes) return Error{"glslang " + bytes.error()};
    return GlslangHlslOutcome::deserialize(*bytes);
}

pid_t hlslWorkerPid() {
    std::shared_ptr<IsolatedWorker> worker = runWorker().current();
    return worker ? worker->pid() : -1;
}

}  // namespace rmfx
