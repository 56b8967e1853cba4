// FileWatcher: which saves are seen (in-place writes, temp file + rename, creation, removal), that
// attribute changes and other files are not, that the events of one save come out as one change,
// and the time-stamp fallback used when inotify cannot watch a folder.
//
// Nothing here is timed: a test that waits for a change polls until it comes (at most 5 s), and
// a test that expects NO change writes a watched "sentinel" file afterwards and polls until the
// sentinel is reported; inotify keeps events in order, so anything the earlier operation caused
// has been read by then.

#include <chrono>
#include <fstream>
#include <thread>

#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "io/file/FileWatcher.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

namespace fs = std::filesystem;
using Paths = std::vector<fs::path>;

// Polls until something is reported (or 5 s pass); returns everything reported until then.
Paths pollUntilChange(FileWatcher& watcher) {
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (std::chrono::steady_clock::now() < deadline) {
        Paths changed = watcher.poll();
        if (!changed.empty()) return changed;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return {};
}

// Polls until `sentinel` is reported; returns every OTHER path reported on the way.
Paths pollUntilSentinel(FileWatcher& watcher, const fs::path& sentinel) {
    Paths others;
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (std::chrono::steady_clock::now() < deadline) {
        bool found = false;
        for (const fs::path& p : watcher.poll()) {
            if (p == sentinel)
                found = true;
            else
                others.push_back(p);
        }
        if (found) return others;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ADD_FAILURE() << "the sentinel " << sentinel << " was never reported";
    return others;
}

// The way editors save: write a temporary file beside the original, then rename it over.
void saveAtomically(const fs::path& file, const std::string& text) {
    fs::path temporary = file.parent_path() / (file.filename().string() + ".tmp~");
    std::ofstream(temporary, std::ios::binary) << text;
    fs::rename(temporary, file);
}

TEST(FileWatcherTest, InPlaceWriteIsOneChange) {
    ScratchDir dir;
    fs::path shader = dir.write("a.frag", "one");
    fs::path other = dir.write("other.txt", "x");
    FileWatcher watcher;
    watcher.watch({shader});
    EXPECT_TRUE(watcher.errors().empty());
    EXPECT_TRUE(watcher.allFoldersNotified());
    EXPECT_TRUE(watcher.poll().empty());

    // Three writes (each a truncate, a write and a close) and a write to a file nobody watches.
    for (const char* text : {"two", "three", "four"}) std::ofstream(shader, std::ios::binary) << text;
    std::ofstream(other, std::ios::binary) << "y";
    EXPECT_EQ(pollUntilChange(watcher), Paths{shader});
    EXPECT_TRUE(watcher.poll().empty());
}

TEST(FileWatcherTest, AtomicSaveByRenameIsSeenAndTheTemporaryFileIsNot) {
    ScratchDir dir;
    fs::path shader = dir.write("a.frag", "one");
    FileWatcher watcher;
    watcher.watch({shader});
    struct stat before {};
    ASSERT_EQ(::stat(shader.c_str(), &before), 0);
    saveAtomically(shader, "two");
    struct stat after {};
    ASSERT_EQ(::stat(shader.c_str(), &after), 0);
    ASSERT_NE(before.st_ino, after.st_ino);  // a new inode: a watch on the file itself would miss it
    EXPECT_EQ(pollUntilChange(watcher), Paths{shader});
    // The rename is seen again (the watch is on the folder, not on the replaced inode).
    saveAtomically(shader, "three");
    EXPECT_EQ(pollUntilChange(watcher), Paths{shader});
}

TEST(FileWatcherTest, AttributeChangesAreNotChanges) {
    ScratchDir dir;
    fs::path shader = dir.write("a.frag", "one");
    fs::path sentinel = dir.write("sentinel", "");
    FileWatcher watcher;
    watcher.watch({shader, sentinel});
    ASSERT_EQ(::chmod(shader.c_str(), 0600), 0);
    fs::last_write_time(shader, fs::last_write_time(shader) - std::chrono::hours(1));  // utimes: IN_ATTRIB too
    std::ofstream(sentinel) << "x";
    EXPECT_EQ(pollUntilSentinel(watcher, sentinel), Paths{});
}

TEST(FileWatcherTest, OtherFilesInTheFolderAreNotReportedButTheirAppearanceIsNoted) {
    ScratchDir dir;
    fs::path shader = dir.write("a.frag", "one");
    fs::path sentinel = dir.write("sentinel", "");
    FileWatcher watcher;
    watcher.watch({shader, sentinel});
    dir.write("new.glsl", "float f;");
    std::ofstream(sentinel) << "x";
    Paths others;
    bool appeared = false, found = false;
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (!found && std::chrono::steady_clock::now() < deadline) {
        for (const fs::path& p : watcher.poll()) {
            if (p == sentinel)
                found = true;
            else
                others.push_back(p);
        }
        appeared = appeared || watcher.sawOtherFileAppear();
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    EXPECT_TRUE(found);
    EXPECT_EQ(others, Paths{});
    EXPECT_TRUE(appeared);
}

TEST(FileWatcherTest, RemovalIsReportedAndSoIsTheReturn) {
    ScratchDir dir;
    fs::path texture = dir.write("t.png", "png");
    FileWatcher watcher;
    watcher.watch({texture});
    fs::remove(texture);
    EXPECT_EQ(pollUntilChange(watcher), Paths{texture});
    EXPECT_FALSE(fs::exists(texture));
    dir.write("t.png", "png again");
    EXPECT_EQ(pollUntilChange(watcher), Paths{texture});
}

TEST(FileWatcherTest, RemovingAndWritingAgainBeforeAPollIsOneChange) {
    ScratchDir dir;
    fs::path shader = dir.write("a.frag", "one");
    FileWatcher watcher;
    watcher.watch({shader});
    // As an editor that moves the original to a backup and writes a new file.
    fs::rename(shader, dir / "a.frag~");
    dir.write("a.frag", "two");
    EXPECT_EQ(pollUntilChange(watcher), Paths{shader});
    // Nothing else follows once the removal had time to settle.
    std::this_thread::sleep_for(std::chrono::milliseconds(120));
    EXPECT_TRUE(watcher.poll().empty());
}

TEST(FileWatcherTest, FilesInSeveralFoldersAndAFolderThatAppearsLater) {
    ScratchDir dir;
    fs::create_directories(dir / "glsl");
    fs::path shader = dir.write("glsl/a.frag", "one");
    fs::path workspace = dir.write("ws.xml", "<workspace/>");
    fs::path later = dir / "media" / "t.png";  // its folder does not exist yet
    FileWatcher watcher;
    watcher.watch({workspace, shader, later});
    EXPECT_TRUE(watcher.errors().empty());  // a missing folder is not a watcher error
    EXPECT_EQ(watcher.files(), (Paths{shader, later, workspace}));

    std::ofstream(shader) << "two";
    EXPECT_EQ(pollUntilChange(watcher), Paths{shader});
    fs::create_directories(dir / "media");
    dir.write("media/t.png", "png");
    EXPECT_EQ(pollUntilChange(watcher), Paths{later});
    EXPECT_TRUE(watcher.allFoldersNotified());  // watched through inotify once it exists
    saveAtomically(later, "png 2");
    EXPECT_EQ(pollUntilChange(watcher), Paths{later});
}

TEST(FileWatcherTest, ReplacingTheWatchedSetStopsReportingOldFiles) {
    ScratchDir dir;
    fs::path a = dir.write("a.frag", "a");
    fs::path b = dir.write("b.frag", "b");
    FileWatcher watcher;
    watcher.watch({a});
    watcher.watch({b});
    EXPECT_EQ(watcher.files(), Paths{b});
    std::ofstream(a) << "a2";
    std::ofstream(b) << "b2";
    EXPECT_EQ(pollUntilSentinel(watcher, b), Paths{});
}

TEST(FileWatcherTest, FolderRemovedAndCreatedAgain) {
    ScratchDir dir;
    fs::create_directories(dir / "glsl");
    fs::path shader = dir.write("glsl/a.frag", "one");
    FileWatcher watcher;
    watcher.watch({shader});
    fs::remove_all(dir / "glsl");
    EXPECT_EQ(pollUntilChange(watcher), Paths{shader});
    fs::create_directories(dir / "glsl");
    dir.write("glsl/a.frag", "two");
    EXPECT_EQ(pollUntilChange(watcher), Paths{shader});
    std::ofstream(shader) << "three";
    EXPECT_EQ(pollUntilChange(watcher), Paths{shader});
}

TEST(FileWatcherTest, WithoutInotifyChangesAreFoundByTimeStamp) {
    ScratchDir dir;
    fs::path shader = dir.write("a.frag", "one");
    FileWatcher watcher(std::chrono::milliseconds(50), FileWatcher::Method::TimeStamps);
    watcher.watch({shader});
    EXPECT_FALSE(watcher.allFoldersNotified());
    EXPECT_TRUE(watcher.poll().empty());
    saveAtomically(shader, "two");  // a new inode even if size and time stamp were equal
    EXPECT_EQ(pollUntilChange(watcher), Paths{shader});
    fs::remove(shader);
    EXPECT_EQ(pollUntilChange(watcher), Paths{shader});
    dir.write("a.frag", "three");
    EXPECT_EQ(pollUntilChange(watcher), Paths{shader});
}

TEST(FileWatcherTest, ChangeTimeLiesBetweenTheWriteAndThePoll) {
    ScratchDir dir;
    fs::path shader = dir.write("a.frag", "one");
    FileWatcher watcher;
    watcher.watch({shader});
    watcher.poll();
    auto before = FileWatcher::Clock::now();
    saveAtomically(shader, "two");
    Paths changed = pollUntilChange(watcher);
    auto after = FileWatcher::Clock::now();
    ASSERT_EQ(changed, Paths{shader});
    // File time stamps are coarser than the steady clock: allow a 20 ms tick before.
    EXPECT_GE(watcher.lastChangeTime(), before - std::chrono::milliseconds(20));
    EXPECT_LE(watcher.lastChangeTime(), after);
}

}  // namespace
}  // namespace rmfx::test
