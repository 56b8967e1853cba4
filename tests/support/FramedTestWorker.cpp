// rmfx-test-worker: a helper program that lives for the run (core/IsolatedWorker.h), for
// IsolatedWorkerTest. Answers each framed message (core/WorkerFrame.h) by what it asks:
//   "pid"        this process's id
//   "crash"      ends by SIGSEGV without answering
//   "hang"       never answers
//   "exit N"     exits with status N without answering
//   "garbage"    answers with bytes that are no framed message
//   anything else, echoed back
// and exits 0 when its input ends.

#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

#include "core/WorkerFrame.h"

int main() {
    // "crash" ends it by the signal, not by the report a sanitizer's handler would print instead.
    ::signal(SIGSEGV, SIG_DFL);
    std::string message;
    while (rmfx::readFramedMessage(STDIN_FILENO, message) == rmfx::FrameRead::Message) {
        std::string answer = message;
        if (message == "pid") answer = std::to_string(::getpid());
        if (message == "crash") ::kill(::getpid(), SIGSEGV);
        if (message == "hang") {
            for (;;) ::pause();
        }
        if (message.rfind("exit ", 0) == 0) ::_exit(std::atoi(message.c_str() + 5));
        if (message == "garbage") {
            rmfx::writeAll(STDOUT_FILENO, std::string(8, '\xff'));
            continue;
        }
        if (!rmfx::writeAll(STDOUT_FILENO, rmfx::frameMessage(answer))) return 1;
    }
    return 0;
}
