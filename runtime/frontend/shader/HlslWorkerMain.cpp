// rmfx-hlsl-worker: compiles one HLSL stage with glslang, for rmfx, which starts it (see
// runtime/core/IsolatedProgram.h for why glslang runs apart). Reads a GlslangHlslRequest on
// standard input, writes the GlslangHlslOutcome on standard output, exits 0; a request it cannot
// read is exit status 2. A crash of glslang ends it by the signal, which rmfx reports.

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <string>

#include "frontend/shader/GlslangHlslCompile.h"

int main() {
    // A crash ends the worker by its signal, without the report a sanitizer's handler prints.
    for (int signal : {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT}) ::signal(signal, SIG_DFL);
    std::string bytes;
    char buffer[65536];
    for (;;) {
        ssize_t n = ::read(STDIN_FILENO, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        bytes.append(buffer, static_cast<size_t>(n));
    }
    rmfx::GlslangHlslRequest request;
    if (!rmfx::GlslangHlslRequest::deserialize(bytes, request)) {
        std::fputs("rmfx-hlsl-worker: standard input is not a request from rmfx; this program is started by rmfx\n", stderr);
        ::_exit(2);
    }
    std::string out = rmfx::compileHlslToSpirv(request).serialize();
    size_t written = 0;
    while (written < out.size()) {
        ssize_t n = ::write(STDOUT_FILENO, out.data() + written, out.size() - written);
        if (n <= 0) ::_exit(1);
        written += static_cast<size_t>(n);
    }
    // No exit handlers: glslang's process-wide tables are not worth a leak report.
    ::_exit(0);
}
