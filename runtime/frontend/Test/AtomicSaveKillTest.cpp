// Saves lose nothing even when the writer dies: a child process saves a workspace again and again
// (alternating two versions, through the editor's save path) and is killed with SIGKILL at a random
// moment; after each kill the workspace file and its backup are each one complete version, and
// the temporary files the writer leaves behind never replace it.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "core/Value.h"
#include "frontend/workspace/VariableValueWriter.h"
#include "frontend/workspace/WorkspaceParser.h"
#include "io/file/AtomicFile.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

namespace fs = std::filesystem;

// A workspace large enough (about 1 MiB of comment) that a write takes a while to land.
std::string workspaceText(double gain) {
    std::string text = "<?xml version=\"1.0\"?>\n<workspace version=\"1\">\n";
    text += "  <float name=\"Gain\" value=\"" + std::to_string(gain) + "\"/>\n  <!-- ";
    text += std::string(1 << 20, 'x');
    text += " -->\n  <pass name=\"p\"/>\n</workspace>\n";
    return text;
}

// Parses `file` and returns its Gain, or nothing when it is not one complete workspace.
std::optional<double> gainOf(const fs::path& file) {
    auto text = readWholeFile(file);
    if (!text) return std::nullopt;
    Result<Workspace> parsed = parseWorkspaceText(*text, file, "fx");
    if (!parsed.ok() || parsed->variables.size() != 1) return std::nullopt;
    const std::string tail = " -->\n  <pass name=\"p\"/>\n</workspace>\n";
    if (text->find(std::string(1 << 20, 'x') + tail) == std::string::npos) return std::nullopt;
    return parsed->variables[0].value.asFloat();
}

TEST(AtomicSaveKill, KillingTheWriterAtRandomMomentsLeavesACompleteFile) {
    ScratchDir dir;
    const fs::path file = dir / "fx.xml";
    ASSERT_TRUE(writeFileAtomically(file, workspaceText(1.0), false));
    std::mt19937 random(20261121);
    int killedMidway = 0, sawNewVersion = 0;
    for (int round = 0; round < 40; ++round) {
        pid_t child = fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            // The editor's save: rewrite the value in place, write atomically, keep FILE.bak.
            for (int i = 0;; ++i) {
                std::map<std::string, Value> values{{"Gain", Value::ofFloat(i % 2 ? 2.0f : 1.0f)}};
                if (!saveVariableValues(file, values)) _exit(2);
            }
        }
        std::this_thread::sleep_for(std::chrono::microseconds(std::uniform_int_distribution<int>(0, 100000)(random)));
        kill(child, SIGKILL);
        int status = 0;
        waitpid(child, &status, 0);
        ASSERT_TRUE(WIFSIGNALED(status)) << "the writer stopped by itself, status " << status;
        SCOPED_TRACE("round " + std::to_string(round));
        auto gain = gainOf(file);
        ASSERT_TRUE(gain) << "the workspace is not one complete version";
        EXPECT_TRUE(*gain == 1.0 || *gain == 2.0) << *gain;
        sawNewVersion += *gain == 2.0;
        if (fs::exists(dir / "fx.xml.bak")) {
            auto backup = gainOf(dir / "fx.xml.bak");
            ASSERT_TRUE(backup) << "the backup is not one complete version";
        }
        // A temporary file left by the killed writer is the only other thing in the folder.
        for (const auto& entry : fs::directory_iterator(dir.path())) {
            std::string name = entry.path().filename().string();
            if (name == "fx.xml" || name == "fx.xml.bak") continue;
            ++killedMidway;
            fs::remove(entry.path());
        }
    }
    // Evidence that kills landed inside writes, and that writes completed between kills.
    std::printf("kills that left a temporary file behind: %d of 40; rounds ending on the second version: %d\n",
                killedMidway, sawNewVersion);
    EXPECT_GT(killedMidway, 0);
    EXPECT_GT(sawNewVersion, 0);
}

}  // namespace
}  // namespace rmfx::test
