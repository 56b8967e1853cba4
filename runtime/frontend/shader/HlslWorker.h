#pragma once
// rmfx-hlsl-worker, the program that runs glslang's HLSL front end in a process of its own
// (core/IsolatedWorker.h says why): where it is, and stages compiled by it. One worker serves
// the whole run (core/IsolatedWorker.h), shared by every thread.

#include <sys/types.h>

#include <chrono>
#include <string>

#include "core/Result.h"
#include "frontend/shader/GlslangHlslCompile.h"

namespace rmfx {

// The first that exists of: $RMFX_HLSL_WORKER (which, once set, must name the program), the
// program beside this process's executable (an installed rmfx), the one this build wrote.
// Otherwise an error saying where it looked.
Result<std::string> hlslWorkerProgram();

// Long enough for any real shader on a loaded machine, a sanitizer build's included.
constexpr std::chrono::milliseconds kHlslWorkerTimeout{30000};

// The stage compiled by the worker; an error says what went wrong with the worker ("glslang
// crashed (signal 11, …)", "… did not finish within 30000 ms …"), not with the shader. After
// such an error the next stage starts a fresh worker; so does a change of hlslWorkerProgram().
Result<GlslangHlslOutcome> compileHlslInWorker(const GlslangHlslRequest& request,
                                               std::chrono::milliseconds timeout = kHlslWorkerTimeout);

// The worker process serving compileHlslInWorker now, or -1 when none is running.
pid_t hlslWorkerPid();

}  // namespace rmfx
