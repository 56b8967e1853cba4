// rmfx-hlsl-worker: compiles HLSL stages with glslang for rmfx, which starts it once and keeps it
// for the run (core/IsolatedWorker.h, which says why glslang runs apart). Reads
// GlslangHlslRequests one after another, each a framed message (core/WorkerFrame.h) on standard
// input, and answers each with its GlslangHlslOutcome on standard output; exits 0 when its input
// ends. Bytes that are no request are exit status 2. A crash of glslang ends it by the signal,
// which rmfx reports against the shader it was compiling.

#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "core/WorkerFrame.h"
#include "frontend/shader/GlslangHlslCompile.h"

namespace {

[[noreturn]] void notFromRmfx() {
    std::fputs("rmfx-hlsl-worker: standard input is not requests from rmfx; this program is started by rmfx\n", stderr);
    ::_exit(2);
}

}  // namespace

int main() {
    // A crash ends the worker by its signal, without the report a sanitizer's handler prints.
    for (int signal : {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT}) ::signal(signal, SIG_DFL);
    std::string message;
    for (;;) {
        switch (rmfx::readFramedMessage(STDIN_FILENO, message)) {
            case rmfx::FrameRead::Message: break;
            // No exit handlers: glslang's process-wide tables are not worth a leak report.
            case rmfx::FrameRead::End: ::_exit(0);
            case rmfx::FrameRead::Broken: notFromRmfx();
        }
        rmfx::GlslangHlslRequest request;
        if (!rmfx::GlslangHlslRequest::deserialize(message, request)) notFromRmfx();
        if (!rmfx::writeAll(STDOUT_FILENO, rmfx::frameMessage(rmfx::compileHlslToSpirv(request).serialize()))) ::_exit(1);
    }
}
