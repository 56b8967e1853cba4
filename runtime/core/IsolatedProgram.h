#pragma once
// Runs a program in a process of its own, hands it `input` on its standard input and hands back
// what it wrote to its standard output, so that a crash or a hang inside a library that program
// runs becomes an error rather than the end of rmfx. Debian's glslang segfaults in its HLSL front
// end on some malformed shaders (a null read in addBinaryMath, in acceptParameterDeclaration), and
// no input check can list every such shape.
//
// A new program, not a fork of this one: a forked child is a copy of the caller with every lock
// its other threads held at that moment (llvmpipe's threads, the sanitizers' allocator), and a
// child that needs one of them waits forever. That stalled an HLSL test of a CI run until its
// 30 s timeout. posix_spawn runs nothing of the caller's in the child before the program starts.
//
// One input per process; a program that answers many inputs in one process, started once for the
// run, is core/IsolatedWorker.h (rmfx-hlsl-worker's).

#include <chrono>
#include <string>
#include <vector>

#include "core/Result.h"

namespace rmfx {

// What the program wrote on its standard output when it exits with status 0. Otherwise an error:
// the signal that ended it ("crashed (signal 11, Segmentation fault)"), its exit status, the
// timeout (after which it is killed), or why it could not be started. Its standard error is this
// process's. Nothing here changes the caller's signal handling: a program that stops reading its
// input early is no SIGPIPE for the caller.
Result<std::string> runIsolatedProgram(const std::string& program, const std::vector<std::string>& arguments,
                                       const std::string& input, std::chrono::milliseconds timeout);

}  // namespace rmfx
