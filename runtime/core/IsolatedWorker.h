#pragma once
// A helper program that lives for the run, handed request after request, each a framed message
// (core/WorkerFrame.h) on its standard input answered by one on its standard output.
//
// In a process of its own, so that a crash or a hang inside a library that program runs becomes
// an error rather than the end of rmfx: Debian's glslang segfaults in its HLSL front end on some
// malformed shaders (a null read in addBinaryMath, in acceptParameterDeclaration), and no input
// check can list every such shape. A crash or a hang is an error on the request that met it, and
// the next request starts a fresh program; between them the one program serves every request,
// without a process start and the library's initialisation each time.
//
// A new program, not a fork of this one (core/SpawnedProgram.h): a forked child is a copy of the
// caller with every lock its other threads held at that moment (llvmpipe's threads, the
// sanitizers' allocator), and a child that needs one of them waits forever. That stalled an HLSL
// test of a CI run until its 30 s timeout. posix_spawn runs nothing of the caller's in the child
// before the program starts.

#include <sys/types.h>

#include <chrono>
#include <mutex>
#include <string>
#include <vector>

#include "core/Result.h"
#include "core/SpawnedProgram.h"

namespace rmfx {

class IsolatedWorker {
public:
    IsolatedWorker(std::string program, std::vector<std::string> arguments = {});
    // Closes the program's input, which ends it, and waits for it (killed if it does not end).
    ~IsolatedWorker();
    IsolatedWorker(const IsolatedWorker&) = delete;
    IsolatedWorker& operator=(const IsolatedWorker&) = delete;

    // The program's answer to `message`. Otherwise an error: the signal that ended it ("crashed (signal 11, Segmentation fault)"), its exit status, the
    // timeout (after which it is killed), or why it could not be started; the program is gone
    // then, and the next request starts another. One request at a time: concurrent callers wait
    // their turn. Nothing here changes the caller's signal handling.
    Result<std::string> request(const std::string& message, std::chrono::milliseconds timeout);

    const std::string& program() const { return program_; }
    // The process serving requests now, or -1 when none is running.
    pid_t pid() const;
    // How many processes have been started so far.
    int started() const;

private:
    // The running program, or nothing when it has ended since the last request (a quiet restart:
    // the request about to be sent never met it).
    void reapIfEnded();
    void stop();

    const std::string program_;
    const std::vector<std::string> arguments_;
    mutable std::mutex mutex_;
    SpawnedProgram process_;
    int started_ = 0;
};

}  // namespace rmfx
