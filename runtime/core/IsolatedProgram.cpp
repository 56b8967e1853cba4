#include "core/IsolatedProgram.h"

#include <fcntl.h>
#include <poll.h>
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

// Closes what it holds when it goes out of scope.
struct FileDescriptor {
    int fd = -1;
    ~FileDescriptor() { reset(); }
    void reset() {
        if (fd >= 0) ::close(fd);
        fd = -1;
    }
};

std::string systemError(const std::string& what, int err) { return what + ": " + std::strerror(err); }

}  // namespace

Result<std::string> runIsolatedProgram(const std::string& program, const std::vector<std::string>& arguments,
                                       const std::string& input, std::chrono::milliseconds timeout) {
    // Standard input is a socket, so that writing to a program that has stopped reading is EPIPE
    // (MSG_NOSIGNAL), never a SIGPIPE that would end the caller.
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
    posix_spawn_file_actions_adddup2(&actions, inputTheirs.fd, STDIN_FILENO);
    posix_spawn_file_actions_adddup2(&actions, outputTheirs.fd, STDOUT_FILENO);
    // The program starts with default signal handling and nothing blocked, whatever the caller set.
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
    pid_t child = -1;
    int spawned = ::posix_spawn(&child, program.c_str(), &actions, &attributes, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    if (spawned != 0) return Error{systemError("cannot start " + program, spawned)};
    inputTheirs.reset();
    outputTheirs.reset();

    ::fcntl(inputOurs.fd, F_SETFL, ::fcntl(inputOurs.fd, F_GETFL) | O_NONBLOCK);
    size_t written = 0;
    if (input.empty()) inputOurs.reset();
    std::string bytes;
    bool timedOut = false;
    auto deadline = std::chrono::steady_clock::now() + timeout;
    char buffer[65536];
    // Input and output at once: a program may write before it has read everything.
    while (outputOurs.fd >= 0) {
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            timedOut = true;
            break;
        }
        pollfd polled[2] = {{outputOurs.fd, POLLIN, 0}, {inputOurs.fd, POLLOUT, 0}};
        int ready = ::poll(polled, inputOurs.fd >= 0 ? 2 : 1, static_cast<int>(left.count()));
        if (ready < 0 && errno == EINTR) continue;
        if (ready < 0) break;
        if (ready == 0) {
            timedOut = true;
            break;
        }
        if (inputOurs.fd >= 0 && polled[1].revents != 0) {
            ssize_t n = ::send(inputOurs.fd, input.data() + written, input.size() - written, MSG_NOSIGNAL);
            if (n > 0) written += static_cast<size_t>(n);
            // Everything sent, or the program stopped reading: its end of file, either way.
            if (written == input.size() || (n < 0 && errno != EAGAIN && errno != EINTR)) inputOurs.reset();
        }
        if (polled[0].revents != 0) {
            ssize_t n = ::read(outputOurs.fd, buffer, sizeof buffer);
            if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
            if (n <= 0) break;
            bytes.append(buffer, static_cast<size_t>(n));
        }
    }
    inputOurs.reset();
    outputOurs.reset();
    // A program may close its output and go on running: the deadline holds until it has ended.
    int status = 0;
    while (!timedOut) {
        pid_t ended = ::waitpid(child, &status, WNOHANG);
        if (ended == child || (ended < 0 && errno != EINTR)) break;
        if (std::chrono::steady_clock::now() >= deadline) timedOut = true;
        else ::usleep(1000);
    }
    if (timedOut) {
        ::kill(child, SIGKILL);
        while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
        }
    }
    if (timedOut) return Error{"did not finish within " + std::to_string(timeout.count()) + " ms and was stopped"};
    if (WIFSIGNALED(status)) {
        int signal = WTERMSIG(status);
        const char* name = ::strsignal(signal);
        return Error{"crashed (signal " + std::to_string(signal) + (name ? std::string(", ") + name : "") + ")"};
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        return Error{"ended with exit status " + std::to_string(WEXITSTATUS(status)) + " before handing back its result"};
    }
    return bytes;
}

}  // namespace rmfx
