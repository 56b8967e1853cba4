#include "core/SpawnedProgram.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

extern char** environ;

namespace rmfx {

namespace {
std::string systemError(const std::string& what, int err) { return what + ": " + std::strerror(err); }
}  // namespace

FileDescriptor& FileDescriptor::operator=(FileDescriptor&& other) noexcept {
    if (this != &other) {
        reset();
        fd_ = other.fd_;
        other.fd_ = -1;
    }
    return *this;
}

void FileDescriptor::reset() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
}

Result<SpawnedProgram> spawnProgram(const std::string& program, const std::vector<std::string>& arguments) {
    int inputPair[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, inputPair) != 0) {
        return Error{systemError("cannot create a socket for the input of " + program, errno)};
    }
    FileDescriptor inputOurs{inputPair[0]}, inputTheirs{inputPair[1]};
    int outputPipe[2];
    if (::pipe2(outputPipe, O_CLOEXEC) != 0) return Error{systemError("cannot create a pipe for " + program, errno)};
    FileDescriptor outputOurs{outputPipe[0]}, outputTheirs{outputPipe[1]};

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, inputTheirs.get(), STDIN_FILENO);
    posix_spawn_file_actions_adddup2(&actions, outputTheirs.get(), STDOUT_FILENO);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t none, all;
    sigemptyset(&none);
    sigfillset(&all);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setsigdefault(&attributes, &all);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);

    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(program.c_str()));
    for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);
    SpawnedProgram out;
    int spawned = ::posix_spawn(&out.pid, program.c_str(), &actions, &attributes, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    if (spawned != 0) return Error{systemError("cannot start " + program, spawned)};
    ::fcntl(inputOurs.get(), F_SETFL, ::fcntl(inputOurs.get(), F_GETFL) | O_NONBLOCK);
    out.input = std::move(inputOurs);
    out.output = std::move(outputOurs);
    return out;
}

std::string endedWithoutResult(int status) {
    if (WIFSIGNALED(status)) {
        int signal = WTERMSIG(status);
        const char* name = ::strsignal(signal);
        return "crashed (signal " + std::to_string(signal) + (name ? std::string(", ") + name : "") + ")";
    }
    return "ended with exit status " + std::to_string(WEXITSTATUS(status)) + " before handing back its result";
}

void killAndReap(pid_t pid) {
    ::kill(pid, SIGKILL);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
}

}  // namespace rmfx
