#include "core/IsolatedCall.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <cerrno>
#include <cstring>

namespace rmfx {

namespace {

bool writeAll(int fd, const char* data, size_t size) {
    while (size > 0) {
        ssize_t n = ::write(fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        data += n;
        size -= static_cast<size_t>(n);
    }
    return true;
}

}  // namespace

Result<std::string> callIsolated(const std::function<std::string()>& work, std::chrono::milliseconds timeout) {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) return Error{std::string("cannot create a pipe: ") + std::strerror(errno)};
    pid_t child = ::fork();
    if (child < 0) {
        int err = errno;
        ::close(fds[0]);
        ::close(fds[1]);
        return Error{std::string("cannot start a child process: ") + std::strerror(err)};
    }
    if (child == 0) {
        ::close(fds[0]);
        // A crash ends the child by its signal, without the report a sanitizer's handler prints.
        for (int signal : {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT}) ::signal(signal, SIG_DFL);
        std::string bytes = work();
        ::_exit(writeAll(fds[1], bytes.data(), bytes.size()) ? 0 : 1);
    }
    ::close(fds[1]);
    std::string bytes;
    bool timedOut = false;
    auto deadline = std::chrono::steady_clock::now() + timeout;
    char buffer[65536];
    for (;;) {
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            timedOut = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        int ready = ::poll(&p, 1, static_cast<int>(left.count()));
        if (ready < 0 && errno == EINTR) continue;
        if (ready == 0) {
            timedOut = true;
            break;
        }
        ssize_t n = ::read(fds[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        bytes.append(buffer, static_cast<size_t>(n));
    }
    ::close(fds[0]);
    if (timedOut) ::kill(child, SIGKILL);
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
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
