// Every input a fuzz target ever failed on (tests/fuzz-regressions/<target>/, saved by
// scripts/fuzz.sh's instructions) runs through the target's entry on every build: a crash here
// is the finding come back; a FuzzPropertyViolation is a broken promise of the code under test.

#include <gtest/gtest.h>

#include <set>

#include "fuzz/FuzzEntries.h"
#include "fuzz/FuzzInputFiles.h"
#include "tests/support/TestSupport.h"

namespace rmfx::fuzz {
namespace {

namespace fs = std::filesystem;

fs::path regressions() { return test::sourceDir() / "tests" / "fuzz-regressions"; }

void runFile(const FuzzEntry& entry, const fs::path& file) {
    std::string bytes = test::readText(file);
    try {
        entry.run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    } catch (const FuzzPropertyViolation& e) {
        ADD_FAILURE() << entry.name << " on " << file << ": " << e.what();
    }
}

TEST(FuzzRegressionTest, EveryFindingRunsCleanThroughItsTarget) {
    int ran = 0;
    for (const FuzzEntry& entry : fuzzEntries()) {
        fs::path folder = regressions() / entry.name;
        if (!fs::is_directory(folder)) continue;
        for (const auto& file : fs::directory_iterator(folder)) {
            if (!file.is_regular_file() || file.path().filename() == "README.md") continue;
            SCOPED_TRACE(file.path().string());
            runFile(entry, file.path());
            ++ran;
        }
    }
    EXPECT_GT(ran, 0) << "no regression inputs under " << regressions();
}

// A folder whose name is no target would be skipped without a word.
TEST(FuzzRegressionTest, EveryRegressionFolderNamesATarget) {
    std::set<std::string> names;
    for (const FuzzEntry& entry : fuzzEntries()) names.insert(entry.name);
    for (const auto& folder : fs::directory_iterator(regressions())) {
        if (folder.is_directory()) {
            EXPECT_TRUE(names.count(folder.path().filename().string())) << folder.path();
        }
    }
}

TEST(FuzzInputFilesTest, SplitsAtMarkerLinesAndWritesOnlyPlainRelativeNames) {
    FuzzInput input = splitFuzzInput("main 1\nmain 2\n//@@ a/b.glsl\nb\n//@@ ../up\nx\n//@@ snippet:s\r\ns\n");
    EXPECT_EQ(input.main, "main 1\nmain 2\n");
    ASSERT_EQ(input.parts.size(), 3u);
    EXPECT_EQ(input.parts[0].name, "a/b.glsl");
    EXPECT_EQ(input.parts[0].text, "b\n");
    EXPECT_EQ(input.parts[1].name, "../up");
    EXPECT_EQ(input.parts[2].name, "snippet:s");

    fs::path folder = freshScratchFolder() / "w";
    writeParts({{"a/b.glsl", "b"}, {"../up", "u"}, {"../../out", "x"}, {"/abs", "x"}, {"a//c", "x"}, {"a/./d", "x"}},
               folder);
    EXPECT_EQ(test::readText(folder / "a" / "b.glsl"), "b");
    EXPECT_EQ(test::readText(folder.parent_path() / "up"), "u");  // still inside the scratch folder
    EXPECT_FALSE(fs::exists(folder.parent_path().parent_path() / "out"));
    EXPECT_FALSE(fs::exists(folder / "a" / "c"));
    EXPECT_FALSE(fs::exists(folder / "a" / "d"));
}

}  // namespace
}  // namespace rmfx::fuzz
