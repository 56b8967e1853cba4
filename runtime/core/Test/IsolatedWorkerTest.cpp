#include "core/IsolatedWorker.h"

#include <signal.h>
#include <sys/wait.h>

#include <atomic>
#include <cerrno>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace rmfx {
namespace {

using namespace std::chrono_literals;

// tests/support/FramedTestWorker.cpp: echoes, or answers "pid", "crash", "hang", "exit N", "garbage".
const char* const kWorker = RMFX_TEST_WORKER;

// True while `pid` is a child of this process that has not ended (or ended and not been reaped).
bool childExists(pid_t pid) { return ::kill(pid, 0) == 0; }

TEST(IsolatedWorker, OneProcessAnswersRequestAfterRequest) {
    IsolatedWorker worker(kWorker);
    EXPECT_EQ(worker.pid(), -1);
    auto first = worker.request("pid", 20s);
    ASSERT_TRUE(first) << first.error();
    EXPECT_EQ(*first, std::to_string(worker.pid()));
    std::string big(3000000, 'x');  // more than a pipe or a socket holds at once, both ways
    big[12345] = '\0';
    for (int i = 0; i < 50; ++i) {
        std::string message = i == 25 ? big : "request " + std::to_string(i);
        auto answer = worker.request(message, 20s);
        ASSERT_TRUE(answer) << i << ": " << answer.error();
        EXPECT_EQ(*answer, message) << i;
    }
    auto empty = worker.request("", 20s);
    ASSERT_TRUE(empty) << empty.error();
    EXPECT_EQ(*empty, "");
    auto last = worker.request("pid", 20s);
    ASSERT_TRUE(last) << last.error();
    EXPECT_EQ(*last, *first);
    EXPECT_EQ(worker.started(), 1);
}

TEST(IsolatedWorker, ACrashIsAnErrorOnItsRequestAndTheNextStartsAFreshProcess) {
    IsolatedWorker worker(kWorker);
    auto before = worker.request("pid", 20s);
    ASSERT_TRUE(before) << before.error();
    auto crashed = worker.request("crash", 20s);
    ASSERT_FALSE(crashed);
    EXPECT_EQ(crashed.error(), "crashed (signal 11, Segmentation fault)");
    EXPECT_EQ(worker.pid(), -1);
    EXPECT_FALSE(childExists(std::stoi(*before))) << "the crashed worker was not reaped";
    auto after = worker.request("pid", 20s);
    ASSERT_TRUE(after) << after.error();
    EXPECT_NE(*after, *before);
    auto echoed = worker.request("still answering", 20s);
    ASSERT_TRUE(echoed) << echoed.error();
    EXPECT_EQ(*echoed, "still answering");
    EXPECT_EQ(worker.started(), 2);
}

TEST(IsolatedWorker, AHangIsStoppedAtTheTimeoutAndTheNextRequestIsAnswered) {
    IsolatedWorker worker(kWorker);
    auto before = worker.request("pid", 20s);
    ASSERT_TRUE(before) << before.error();
    auto started = std::chrono::steady_clock::now();
    auto hung = worker.request("hang", 300ms);
    ASSERT_FALSE(hung);
    EXPECT_EQ(hung.error(), "did not finish within 300 ms and was stopped");
    EXPECT_LT(std::chrono::steady_clock::now() - started, 10s);
    EXPECT_FALSE(childExists(std::stoi(*before))) << "the hung worker was not killed and reaped";
    auto after = worker.request("after the hang", 20s);
    ASSERT_TRUE(after) << after.error();
    EXPECT_EQ(*after, "after the hang");
    EXPECT_EQ(worker.started(), 2);
}

TEST(IsolatedWorker, AnExitAMissingProgramAndBadFramesAreErrors) {
    IsolatedWorker worker(kWorker);
    auto exited = worker.request("exit 3", 20s);
    ASSERT_FALSE(exited);
    EXPECT_EQ(exited.error(), "ended with exit status 3 before handing back its result");
    auto garbage = worker.request("garbage", 20s);
    ASSERT_FALSE(garbage);
    EXPECT_EQ(garbage.error(), "answered with bytes that are not one framed message (core/WorkerFrame.h)");
    EXPECT_EQ(worker.pid(), -1);
    auto fine = worker.request("fine", 20s);
    ASSERT_TRUE(fine) << fine.error();
    EXPECT_EQ(*fine, "fine");

    // A program that ends without reading its input: no SIGPIPE for the caller, its status reported.
    IsolatedWorker failing("/bin/false");
    auto refused = failing.request(std::string(3000000, 'x'), 20s);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error(), "ended with exit status 1 before handing back its result");

    IsolatedWorker missing("/nonexistent/rmfx-worker");
    auto notStarted = missing.request("input", 20s);
    ASSERT_FALSE(notStarted);
    EXPECT_EQ(notStarted.error(), "cannot start /nonexistent/rmfx-worker: No such file or directory");
    EXPECT_EQ(missing.started(), 0);
}

// A worker that ended between requests (killed from outside, say) never met the next request:
// that one starts a fresh worker and is answered.
TEST(IsolatedWorker, AWorkerThatEndedWhileIdleIsReplacedQuietly) {
    IsolatedWorker worker(kWorker);
    auto before = worker.request("pid", 20s);
    ASSERT_TRUE(before) << before.error();
    pid_t idle = worker.pid();
    ASSERT_EQ(::kill(idle, SIGKILL), 0);
    siginfo_t ended{};
    while (::waitid(P_PID, static_cast<id_t>(idle), &ended, WEXITED | WNOWAIT) < 0 && errno == EINTR) {
    }
    auto after = worker.request("pid", 20s);
    ASSERT_TRUE(after) << after.error();
    EXPECT_NE(*after, *before);
    EXPECT_FALSE(childExists(idle));
}

TEST(IsolatedWorker, ConcurrentRequestsFromTwoThreadsEachGetTheirOwnAnswer) {
    IsolatedWorker worker(kWorker);
    std::vector<std::string> failures[2];
    std::vector<std::thread> threads;
    for (int t = 0; t < 2; ++t) {
        threads.emplace_back([&worker, &failures, t] {
            for (int i = 0; i < 200; ++i) {
                std::string message = "thread " + std::to_string(t) + " request " + std::to_string(i) +
                                      std::string(static_cast<size_t>(i) * 97, static_cast<char>('a' + t));
                auto answer = worker.request(message, 20s);
                if (!answer || *answer != message) failures[t].push_back(std::to_string(i) + ": " + (answer ? "another answer" : answer.error()));
            }
        });
    }
    for (std::thread& thread : threads) thread.join();
    EXPECT_TRUE(failures[0].empty()) << failures[0].front();
    EXPECT_TRUE(failures[1].empty()) << failures[1].front();
    EXPECT_EQ(worker.started(), 1);
}

TEST(IsolatedWorker, DestroyingItEndsTheWorkerAndReapsIt) {
    pid_t pid = -1;
    {
        IsolatedWorker worker(kWorker);
        auto answer = worker.request("pid", 20s);
        ASSERT_TRUE(answer) << answer.error();
        pid = worker.pid();
        ASSERT_TRUE(childExists(pid));
    }
    EXPECT_FALSE(childExists(pid)) << "worker " << pid << " is still running or a zombie";
}

// The fork rmfx once used could copy a lock another thread held (the sanitizers' allocator's) into
// the child, which then waited for it forever. A new program, started with posix_spawn, shares no
// lock with the caller: a fresh worker for each of 40 requests while two threads allocate all the
// time.
TEST(IsolatedWorker, OtherThreadsAllocatingAllTheTimeNeverStallAStart) {
    std::atomic<bool> stop{false};
    std::vector<std::thread> churners;
    for (int t = 0; t < 2; ++t) {
        churners.emplace_back([&stop, t] {
            std::vector<std::string> held(64);
            for (size_t i = 0; !stop.load(std::memory_order_relaxed); ++i) held[i % held.size()] = std::string(16 + (i * 37 + t) % 4000, 'z');
        });
    }
    std::vector<std::string> failures;
    for (int i = 0; i < 40; ++i) {
        IsolatedWorker fresh(kWorker);
        auto result = fresh.request("call " + std::to_string(i), 20s);
        if (!result || *result != "call " + std::to_string(i))
            failures.push_back("call " + std::to_string(i) + ": " + (result ? *result : result.error()));
    }
    stop = true;
    for (std::thread& churner : churners) churner.join();
    EXPECT_TRUE(failures.empty()) << failures.front();
}

}  // namespace
}  // namespace rmfx
