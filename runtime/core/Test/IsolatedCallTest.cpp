#include "core/IsolatedCall.h"

#include <csignal>
#include <string>
#include <thread>

#include <gtest/gtest.h>

namespace rmfx {
namespace {

using namespace std::chrono_literals;

TEST(IsolatedCall, HandsBackTheBytesTheChildReturned) {
    std::string big(300000, 'x');  // more than a pipe holds at once
    big[12345] = '\0';
    auto result = callIsolated([&] { return big; }, 10s);
    ASSERT_TRUE(result) << result.error();
    EXPECT_EQ(*result, big);
    auto empty = callIsolated([] { return std::string(); }, 10s);
    ASSERT_TRUE(empty);
    EXPECT_EQ(*empty, "");
}

TEST(IsolatedCall, WhatTheChildChangesStaysInTheChild) {
    int counter = 1;
    auto result = callIsolated([&] { counter = 2; return std::to_string(counter); }, 10s);
    ASSERT_TRUE(result);
    EXPECT_EQ(*result, "2");
    EXPECT_EQ(counter, 1);
}

TEST(IsolatedCall, ACrashIsAnErrorNamingTheSignal) {
    auto result = callIsolated([]() -> std::string { std::raise(SIGSEGV); return "not reached"; }, 10s);
    ASSERT_FALSE(result);
    EXPECT_EQ(result.error().rfind("crashed (signal 11", 0), 0u) << result.error();
    auto aborted = callIsolated([]() -> std::string { std::abort(); }, 10s);
    ASSERT_FALSE(aborted);
    EXPECT_EQ(aborted.error().rfind("crashed (signal 6", 0), 0u) << aborted.error();
}

TEST(IsolatedCall, AHangIsStoppedAtTheTimeout) {
    auto started = std::chrono::steady_clock::now();
    auto result = callIsolated([]() -> std::string { for (;;) std::this_thread::sleep_for(1s); }, 200ms);
    ASSERT_FALSE(result);
    EXPECT_EQ(result.error(), "did not finish within 200 ms and was stopped");
    EXPECT_LT(std::chrono::steady_clock::now() - started, 5s);
}

}  // namespace
}  // namespace rmfx
