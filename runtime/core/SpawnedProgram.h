#pragma once
// A program started for rmfx with posix_spawn (core/IsolatedWorker.h says why not fork), its
// standard input and output connected to this process; and what its end status says.

#include <sys/types.h>

#include <string>
#include <vector>

#include "core/Result.h"

namespace rmfx {

// Closes what it holds when it goes out of scope.
class FileDescriptor {
public:
    FileDescriptor() = default;
    explicit FileDescriptor(int fd) : fd_(fd) {}
    FileDescriptor(FileDescriptor&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }
    FileDescriptor& operator=(FileDescriptor&& other) noexcept;
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    ~FileDescriptor() { reset(); }
    int get() const { return fd_; }
    bool open() const { return fd_ >= 0; }
    void reset();

private:
    int fd_ = -1;
};

struct SpawnedProgram {
    pid_t pid = -1;
    // Its standard input: a socket, written with send(MSG_NOSIGNAL), so that writing to a program
    // that has stopped reading is EPIPE, never a SIGPIPE that would end the caller. Non-blocking.
    FileDescriptor input;
    FileDescriptor output;  // its standard output, a pipe; its standard error is this process's
};

// Started with default signal handling and nothing blocked, whatever the caller set; the ends
// kept here are close-on-exec, so no other program started later holds them open.
Result<SpawnedProgram> spawnProgram(const std::string& program, const std::vector<std::string>& arguments);

// Why a program that ended with `status` (as waitpid gives it) handed nothing back:
// "crashed (signal 11, Segmentation fault)" or "ended with exit status 3 before handing back its result".
std::string endedWithoutResult(int status);

// Kills `pid` and waits for it, so that no zombie is left.
void killAndReap(pid_t pid);

}  // namespace rmfx
