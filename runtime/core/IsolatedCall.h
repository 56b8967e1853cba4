#pragma once
// Runs a function in a forked child process and hands back the bytes it returned, so that a crash
// or a hang inside a library becomes an error rather than the end of rmfx. Debian's glslang
// segfaults in its HLSL front end on some malformed shaders (a null read in addBinaryMath, in
// acceptParameterDeclaration), and no input check can list every such shape.
//
// The child is a copy of the caller: it may read anything the caller had, and everything it
// changes is lost. It must not touch GL or threads of the parent, and it ends with _exit (no
// atexit handlers, no leak check of memory the parent owns). Another thread holding a lock the
// work needs at the moment of the fork would stall the child: the timeout ends that too.

#include <chrono>
#include <functional>
#include <string>

#include "core/Result.h"

namespace rmfx {

// work()'s bytes; an error naming the signal that ended the child ("crashed (signal 11,
// Segmentation fault)"), or the timeout, or why no child could be started.
Result<std::string> callIsolated(const std::function<std::string()>& work, std::chrono::milliseconds timeout);

}  // namespace rmfx
