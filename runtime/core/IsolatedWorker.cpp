#include "core/IsolatedWorker.h"

#include <poll.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/WorkerFrame.h"

namespace rmfx {

namespace {
// How long a worker whose input has closed may take to end before it is killed.
constexpr std::chrono::milliseconds kEndGrace{2000};
}  // namespace

IsolatedWorker::IsolatedWorker(std::string program, std::vector<std::string> arguments)
    : program_(std::move(program)), arguments_(std::move(arguments)) {}

IsolatedWorker::~IsolatedWorker() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (process_.pid < 0) return;
    process_.input.reset();
    process_.output.reset();
    auto deadline = std::chrono::steady_clock::now() + kEndGrace;
    int status = 0;
    for (;;) {
        pid_t ended = ::waitpid(process_.pid, &status, WNOHANG);
        if (ended == process_.pid || (ended < 0 && errno != EINTR)) return;
        if (std::chrono::steady_clock::now() >= deadline) break;
        ::usleep(1000);
    }
    killAndReap(process_.pid);
}

pid_t IsolatedWorker::pid() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return process_.pid;
}

int IsolatedWorker::started() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return started_;
}

void IsolatedWorker::reapIfEnded() {
    if (process_.pid < 0) return;
    int status = 0;
    pid_t ended = ::waitpid(process_.pid, &status, WNOHANG);
    if (ended == process_.pid || (ended < 0 && errno == ECHILD)) {
        process_ = SpawnedProgram{};
    }
}

void IsolatedWorker::stop() {
    if (process_.pid >= 0) killAndReap(process_.pid);
    process_ = SpawnedProgram{};
}

Result<std::string> IsolatedWorker::request(const std::string& message, std::chrono::milliseconds timeout) {
    std::lock_guard<std::mutex> lock(mutex_);
    reapIfEnded();
    if (process_.pid < 0) {
        Result<SpawnedProgram> spawned = spawnProgram(program_, arguments_);
        if (!spawned) return Error{spawned.error()};
        process_ = std::move(*spawned);
        ++started_;
    }

    const std::string framed = frameMessage(message);
    size_t written = 0;
    bool writing = true;
    std::string received;
    auto deadline = std::chrono::steady_clock::now() + timeout;
    char buffer[65536];
    // Input and output at once: a program may answer before it has read all.
    for (;;) {
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) break;
        pollfd polled[2] = {{process_.output.get(), POLLIN, 0}, {process_.input.get(), POLLOUT, 0}};
        int ready = ::poll(polled, writing ? 2 : 1, static_cast<int>(left.count()));
        if (ready < 0 && errno == EINTR) continue;
        if (ready < 0) {
            int err = errno;
            stop();
            return Error{std::string("cannot wait for ") + program_ + ": " + std::strerror(err)};
        }
        if (ready == 0) break;
        if (writing && polled[1].revents != 0) {
            ssize_t n = ::send(process_.input.get(), framed.data() + written, framed.size() - written, MSG_NOSIGNAL);
            if (n > 0) written += static_cast<size_t>(n);
            // Everything sent, or the program stopped reading (it has ended, or is about to).
            if (written == framed.size() || (n < 0 && errno != EAGAIN && errno != EINTR)) writing = false;
        }
        if (polled[0].revents == 0) continue;
        ssize_t n = ::read(process_.output.get(), buffer, sizeof buffer);
        if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
        if (n > 0) {
            received.append(buffer, static_cast<size_t>(n));
            bool broken = false;
            std::optional<std::string> answer = takeFramedMessage(received, broken);
            if (broken || (answer && !received.empty())) {
                stop();
                return Error{"answered with bytes that are not one framed message (core/WorkerFrame.h)"};
            }
            if (answer) return std::move(*answer);
            continue;
        }
        // Its output closed: it has ended or is ending. The deadline holds until it has.
        process_.input.reset();
        process_.output.reset();
        int status = 0;
        for (;;) {
            pid_t ended = ::waitpid(process_.pid, &status, WNOHANG);
            if (ended == process_.pid || (ended < 0 && errno != EINTR)) {
                process_ = SpawnedProgram{};
                return Error{endedWithoutResult(status)};
            }
            if (std::chrono::steady_clock::now() >= deadline) break;
            ::usleep(1000);
        }
        break;
    }
    stop();
    return Error{"did not finish within " + std::to_string(timeout.count()) + " ms and was stopped"};
}

}  // namespace rmfx
