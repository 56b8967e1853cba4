#include "core/IsolatedProgram.h"

#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace rmfx {
namespace {

using namespace std::chrono_literals;

TEST(IsolatedProgram, HandsBackWhatTheProgramWroteForItsInput) {
    std::string big(3000000, 'x');  // more than a pipe or a socket holds at once, both ways
    big[12345] = '\0';
    big[2999999] = 'y';
    auto echoed = runIsolatedProgram("/bin/cat", {}, big, 20s);
    ASSERT_TRUE(echoed) << echoed.error();
    EXPECT_EQ(*echoed, big);
    auto empty = runIsolatedProgram("/bin/cat", {}, "", 20s);
    ASSERT_TRUE(empty) << empty.error();
    EXPECT_EQ(*empty, "");
    auto arguments = runIsolatedProgram("/bin/sh", {"-c", "printf '%s|%s' \"$0\" \"$1\"", "a b", "c"}, "", 20s);
    ASSERT_TRUE(arguments) << arguments.error();
    EXPECT_EQ(*arguments, "a b|c");
}

TEST(IsolatedProgram, AProgramThatStopsReadingIsNoSignalForTheCaller) {
    std::string big(3000000, 'x');
    auto result = runIsolatedProgram("/bin/sh", {"-c", "head -c 10"}, big, 20s);
    ASSERT_TRUE(result) << result.error();
    EXPECT_EQ(*result, std::string(10, 'x'));
    auto closed = runIsolatedProgram("/bin/sh", {"-c", "exec 0<&-; printf done"}, big, 20s);
    ASSERT_TRUE(closed) << closed.error();
    EXPECT_EQ(*closed, "done");
}

TEST(IsolatedProgram, ACrashIsAnErrorNamingTheSignal) {
    auto result = runIsolatedProgram("/bin/sh", {"-c", "kill -SEGV $$"}, "", 20s);
    ASSERT_FALSE(result);
    EXPECT_EQ(result.error().rfind("crashed (signal 11", 0), 0u) << result.error();
    auto aborted = runIsolatedProgram("/bin/sh", {"-c", "kill -ABRT $$"}, "", 20s);
    ASSERT_FALSE(aborted);
    EXPECT_EQ(aborted.error().rfind("crashed (signal 6", 0), 0u) << aborted.error();
}

TEST(IsolatedProgram, AFailureStatusAndAMissingProgramAreErrors) {
    auto failed = runIsolatedProgram("/bin/sh", {"-c", "printf partial; exit 3"}, "", 20s);
    ASSERT_FALSE(failed);
    EXPECT_EQ(failed.error(), "ended with exit status 3 before handing back its result");
    auto missing = runIsolatedProgram("/nonexistent/rmfx-worker", {}, "input", 20s);
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error(), "cannot start /nonexistent/rmfx-worker: No such file or directory");
}

TEST(IsolatedProgram, AHangIsStoppedAtTheTimeoutEvenWithItsOutputClosed) {
    for (const char* script : {"exec sleep 30", "exec 1>&-; exec sleep 30"}) {
        auto started = std::chrono::steady_clock::now();
        auto result = runIsolatedProgram("/bin/sh", {"-c", script}, "", 300ms);
        ASSERT_FALSE(result) << script;
        EXPECT_EQ(result.error(), "did not finish within 300 ms and was stopped") << script;
        EXPECT_LT(std::chrono::steady_clock::now() - started, 10s) << script;
    }
}

// The fork this replaced could copy a lock another thread held (the sanitizers' allocator's) into
// the child, which then waited for it forever. A new program shares no lock with the caller.
TEST(IsolatedProgram, OtherThreadsAllocatingAllTheTimeNeverStallIt) {
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
        auto result = runIsolatedProgram("/bin/cat", {}, "call " + std::to_string(i), 20s);
        if (!result || *result != "call " + std::to_string(i)) {
            failures.push_back("call " + std::to_string(i) + ": " + (result ? *result : result.error()));
        }
    }
    stop = true;
    for (std::thread& churner : churners) churner.join();
    EXPECT_TRUE(failures.empty()) << failures.front();
}

}  // namespace
}  // namespace rmfx
