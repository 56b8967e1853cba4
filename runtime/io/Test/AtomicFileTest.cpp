// Writing a file atomically: a reader finds the old or the new complete file, never a partial one;
// the old file becomes the backup; every failure leaves the original and no temporary file.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <regex>
#include <thread>

#include "io/file/AtomicFile.h"
#include "tests/support/FolderFiles.h"
#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

namespace fs = std::filesystem;
using test::filesIn;
using test::readText;
using test::statOf;

// `text` as a regular expression that matches it and nothing else.
std::string literal(const std::string& text) { return std::regex_replace(text, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)"); }

// The temporary file writeFileAtomically makes beside `file`, ".NAME.PID.N.tmp" (AtomicFile.cpp), as a
// regular expression: its process id and counter are not known here.
std::string temporaryOf(const fs::path& file) {
    return literal((file.parent_path() / ("." + file.filename().string())).string()) + R"(\.[0-9]+\.[0-9]+\.tmp)";
}

TEST(AtomicFile, WritesNewFilesAndOptionallyNoBackup) {
    test::ScratchDir dir;
    fs::path file = dir / "new.txt";
    ASSERT_TRUE(writeFileAtomically(file, "one\n").ok());
    EXPECT_EQ(readText(file), "one\n");
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"new.txt"}));  // nothing to back up
    ASSERT_TRUE(writeFileAtomically(file, "two\n", false).ok());
    EXPECT_EQ(readText(file), "two\n");
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"new.txt"}));
    ASSERT_EQ(::chmod(file.c_str(), 0604), 0);
    ASSERT_TRUE(writeFileAtomically(file, "three\n").ok());
    EXPECT_EQ(statOf(file).st_mode & 07777, 0604u);
    EXPECT_EQ(statOf(dir / "new.txt.bak").st_mode & 07777, 0604u);
    EXPECT_EQ(readText(dir / "new.txt.bak"), "two\n");
}

TEST(AtomicFile, AReaderAlwaysFindsTheOldOrTheNewCompleteFile) {
    // While one thread saves again and again, another keeps reading the file: every read must
    // find the file and see one of the two complete versions, never a missing or partial one.
    test::ScratchDir dir;
    const std::string a(200000, 'a'), b(300000, 'b');
    fs::path file = dir.write("look.xml", a);
    std::atomic<bool> done{false};
    std::atomic<int> reads{0}, missing{0}, partial{0};
    std::thread reader([&] {
        while (!done) {
            std::string seen;
            int fd = ::open(file.c_str(), O_RDONLY);
            if (fd < 0) {
                ++missing;
                continue;
            }
            char buffer[65536];
            for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) seen.append(buffer, static_cast<size_t>(n));
            ::close(fd);
            if (seen != a && seen != b) ++partial;
            ++reads;
        }
    });
    for (int i = 0; i < 100; ++i) ASSERT_TRUE(writeFileAtomically(file, i % 2 ? a : b).ok());
    done = true;
    reader.join();
    EXPECT_GT(reads.load(), 0);
    EXPECT_EQ(missing.load(), 0);
    EXPECT_EQ(partial.load(), 0);
    EXPECT_EQ(readText(file), a);
    EXPECT_EQ(readText(dir / "look.xml.bak"), b);
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"look.xml", "look.xml.bak"}));
}

TEST(AtomicFile, MissingFolderIsAnErrorNamingThePath) {
    test::ScratchDir dir;
    fs::path file = dir / "missing" / "look.xml";
    auto written = writeFileAtomically(file, "x");
    ASSERT_FALSE(written.ok());
    EXPECT_EQ(written.error(), "cannot save '" + file.string() + "': cannot create a temporary file in '" +
                                   (dir / "missing").string() + "': No such file or directory");
    EXPECT_TRUE(filesIn(dir.path()).empty());
}

TEST(AtomicFile, AFolderInThePlaceOfTheFileIsAnError) {
    test::ScratchDir dir;
    fs::create_directory(dir / "look.xml");
    auto written = writeFileAtomically(dir / "look.xml", "x");
    ASSERT_FALSE(written.ok());
    EXPECT_EQ(written.error(), "cannot save '" + (dir / "look.xml").string() + "': it is not a regular file");
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"look.xml"}));
}

TEST(AtomicFile, ABackupThatCannotBeReplacedLeavesEverythingAsItWas) {
    test::ScratchDir dir;
    fs::path file = dir.write("look.xml", "old");
    fs::create_directory(dir / "look.xml.bak");
    fs::path bak = dir / "look.xml.bak";
    dir.write("look.xml.bak/keep", "k");
    auto written = writeFileAtomically(file, "new");
    ASSERT_FALSE(written.ok());
    EXPECT_TRUE(
        std::regex_match(written.error(), std::regex(literal("cannot save '" + file.string() + "': cannot rename '") +
                                                     temporaryOf(file) + literal("' to '" + bak.string() + "': Is a directory"))))
        << written.error();
    EXPECT_EQ(readText(file), "old");
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"look.xml", "look.xml.bak"}));
}

TEST(AtomicFile, AFailedWriteLeavesTheOriginalAndNoTemporaryFile) {
    // A file size limit makes write() fail half way (EFBIG), as a full disk would; this works
    // for root too, whom a read-only folder does not stop.
    test::ScratchDir dir;
    fs::path file = dir.write("look.xml", "old contents");
    struct rlimit saved {};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
    auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
    struct rlimit small = saved;
    small.rlim_cur = 4096;
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    auto written = writeFileAtomically(file, std::string(100000, 'x'));
    ::setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, previousHandler);
    ASSERT_FALSE(written.ok());
    EXPECT_TRUE(std::regex_match(written.error(), std::regex(literal("cannot save '" + file.string() + "': cannot write '") +
                                                             temporaryOf(file) + literal("': File too large"))))
        << written.error();
    EXPECT_EQ(readText(file), "old contents");
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"look.xml"}));
}

TEST(AtomicFile, AReadOnlyFolderIsAnError) {
    if (::geteuid() == 0) GTEST_SKIP() << "root writes into read-only folders";
    test::ScratchDir dir;
    fs::path file = dir.write("look.xml", "old");
    ASSERT_EQ(::chmod(dir.path().c_str(), 0555), 0);
    auto written = writeFileAtomically(file, "new");
    ::chmod(dir.path().c_str(), 0755);
    ASSERT_FALSE(written.ok());
    EXPECT_EQ(written.error(), "cannot save '" + file.string() + "': cannot create a temporary file in '" +
                                   dir.path().string() + "': Permission denied");
    EXPECT_EQ(readText(file), "old");
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"look.xml"}));
}

}  // namespace
}  // namespace rmfx
