// rmfx-hlsl-worker lives for the run (core/IsolatedWorker.h): one process compiles stage after
// stage, a glslang crash is an error on the stage that met it, and the next stage is compiled by
// a fresh worker. (IsolatedWorkerTest covers hangs, exits and the protocol with a test program.)

#include "frontend/shader/HlslWorker.h"

#include <signal.h>

#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace rmfx {
namespace {

constexpr unsigned kSpirvMagic = 0x07230203;

// A pixel shader that compiles, different for each `i` (so that no cache could answer for it).
GlslangHlslRequest pixelShader(int i) {
    return {false, "main", "float4 main() : COLOR0 { return float4(" + std::to_string(i) + ".0, 0, 0, 1); }"};
}

// One that fails, naming an identifier of its own in glslang's log.
GlslangHlslRequest failingShader(const std::string& identifier) {
    return {false, "main", "float4 main() : COLOR0 { return " + identifier + "; }"};
}

// What crashes Debian's glslang (HlslTranslatorTest's ShadersThatCrashGlslangAreErrorsOnTheirElement).
const GlslangHlslRequest crashingShader{false, "n",
                                        "float i=float4(5,5,0,0);cbuffer:register(b){float s;}float n(float Tangent:D):R{"
                                        "float3 r=abs(Tangent)s.b+b++()}"};

TEST(HlslWorker, OneProcessCompilesStageAfterStage) {
    auto first = compileHlslInWorker(pixelShader(0));
    ASSERT_TRUE(first) << first.error();
    pid_t pid = hlslWorkerPid();
    ASSERT_GT(pid, 0);
    for (int i = 1; i <= 30; ++i) {
        auto compiled = compileHlslInWorker(pixelShader(i));
        ASSERT_TRUE(compiled) << i << ": " << compiled.error();
        ASSERT_EQ(compiled->kind, GlslangHlslOutcome::Compiled) << i << ": " << compiled->log;
        ASSERT_FALSE(compiled->spirv.empty()) << i;
        EXPECT_EQ(compiled->spirv[0], kSpirvMagic) << i;
        EXPECT_EQ(hlslWorkerPid(), pid) << "stage " << i << " was compiled by another process";
    }
    auto failed = compileHlslInWorker(failingShader("notDeclaredAnywhere"));
    ASSERT_TRUE(failed) << failed.error();
    EXPECT_EQ(failed->kind, GlslangHlslOutcome::Failed);
    EXPECT_NE(failed->log.find("notDeclaredAnywhere"), std::string::npos) << failed->log;
    auto noEntry = compileHlslInWorker({true, "absent", "float4 main() : POSITION { return 0; }"});
    ASSERT_TRUE(noEntry) << noEntry.error();
    EXPECT_EQ(noEntry->kind, GlslangHlslOutcome::NoEntryPoint);
    EXPECT_EQ(hlslWorkerPid(), pid);
}

TEST(HlslWorker, AGlslangCrashIsAnErrorOnItsStageAndTheNextStageCompiles) {
    auto before = compileHlslInWorker(pixelShader(100));
    ASSERT_TRUE(before) << before.error();
    pid_t crashedWorker = hlslWorkerPid();
    auto crashed = compileHlslInWorker(crashingShader);
    ASSERT_FALSE(crashed);
    EXPECT_EQ(crashed.error(), "glslang crashed (signal 11, Segmentation fault)");
    EXPECT_EQ(hlslWorkerPid(), -1);
    EXPECT_NE(::kill(crashedWorker, 0), 0) << "the crashed worker was not reaped";
    auto after = compileHlslInWorker(pixelShader(101));
    ASSERT_TRUE(after) << after.error();
    ASSERT_EQ(after->kind, GlslangHlslOutcome::Compiled) << after->log;
    EXPECT_EQ(after->spirv[0], kSpirvMagic);
    EXPECT_GT(hlslWorkerPid(), 0);
    EXPECT_NE(hlslWorkerPid(), crashedWorker);
}

TEST(HlslWorker, StagesFromTwoThreadsEachGetTheirOwnOutcome) {
    std::vector<std::string> failures[2];
    std::vector<std::thread> threads;
    for (int t = 0; t < 2; ++t) {
        threads.emplace_back([&failures, t] {
            for (int i = 0; i < 20; ++i) {
                std::string identifier = "missing_t" + std::to_string(t) + "_i" + std::to_string(i);
                auto failed = compileHlslInWorker(failingShader(identifier));
                if (!failed || failed->kind != GlslangHlslOutcome::Failed || failed->log.find(identifier) == std::string::npos) {
                    failures[t].push_back(identifier + ": " + (failed ? failed->log : failed.error()));
                }
                auto compiled = compileHlslInWorker(pixelShader(1000 * t + i));
                if (!compiled || compiled->kind != GlslangHlslOutcome::Compiled) {
                    failures[t].push_back("shader " + std::to_string(i) + ": " + (compiled ? compiled->log : compiled.error()));
                }
            }
        });
    }
    for (std::thread& thread : threads) thread.join();
    EXPECT_TRUE(failures[0].empty()) << failures[0].front();
    EXPECT_TRUE(failures[1].empty()) << failures[1].front();
}

}  // namespace
}  // namespace rmfx
