#include "core/IsolatedProgram.h"

#include <poll.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>

#include "core/SpawnedProgram.h"

namespace rmfx {

Result<std::string> runIsolatedProgram(const std::string& program, const std::vector<std::string>& arguments,
                                       const std::string& input, std::chrono::milliseconds timeout) {
    Result<SpawnedProgram> spawned = spawnProgram(program, arguments);
    if (!spawned) return Error{spawned.error()};
    pid_t child = spawned->pid;
    FileDescriptor& inputOurs = spawned->input;
    FileDescriptor& outputOurs = spawned->output;

    size_t written = 0;
    if (input.empty()) inputOurs.reset();
    std::string bytes;
    bool timedOut = false;
    auto deadline = std::chrono::steady_clock::now() + timeout;
    char buffer[65536];
    // Input and output at once: a program may write before it has read everything.
    while (outputOurs.open()) {
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            timedOut = true;
            break;
        }
        pollfd polled[2] = {{outputOurs.get(), POLLIN, 0}, {inputOurs.get(), POLLOUT, 0}};
        int ready = ::poll(polled, inputOurs.open() ? 2 : 1, static_cast<int>(left.count()));
        if (ready < 0 && errno == EINTR) continue;
        if (ready < 0) break;
        if (ready == 0) {
            timedOut = true;
            break;
        }
        if (inputOurs.open() && polled[1].revents != 0) {
            ssize_t n = ::send(inputOurs.get(), input.data() + written, input.size() - written, MSG_NOSIGNAL);
            if (n > 0) written += static_cast<size_t>(n);
            // Everything sent, or the program stopped reading: its end of file, either way.
            if (written == input.size() || (n < 0 && errno != EAGAIN && errno != EINTR)) inputOurs.reset();
        }
        if (polled[0].revents != 0) {
            ssize_t n = ::read(outputOurs.get(), buffer, sizeof buffer);
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
        killAndReap(child);
        return Error{"did not finish within " + std::to_string(timeout.count()) + " ms and was stopped"};
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return Error{endedWithoutResult(status)};
    return bytes;
}

}  // namespace rmfx
