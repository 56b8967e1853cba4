#pragma once
// Tells which of a set of files changed on disk, without blocking: inotify on the FOLDERS that
// hold them, filtered by file name, because editors save by writing a temporary file and renaming
// it over the original (a new inode, which a watch on the file itself would miss).
//
// A change is a finished write (IN_CLOSE_WRITE), a file renamed or created into place
// (IN_MOVED_TO, IN_CREATE), or a removal (IN_DELETE, IN_MOVED_FROM). Attribute changes are not.
// The events of one save are reported as one change. A removal is reported only when the file
// is still missing a moment later (`settle`), since some editors delete or rename the original
// before writing the new one; a created file is reported when its writer closes it (or after
// `settle` when nobody writes it, as with a hard link).
//
// When inotify cannot be used (its instance or watch limits, a folder that does not exist yet)
// the problem is reported by errors() and the files concerned are checked by time stamp and size
// on every poll instead, so changes are still seen.

#include <chrono>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace rmfx {

class FileWatcher {
public:
    using Clock = std::chrono::steady_clock;

    enum class Method {
        Inotify,     // time stamps only for folders inotify cannot watch
        TimeStamps,  // time stamps for every folder (what happens when inotify is unavailable)
    };

    explicit FileWatcher(Clock::duration settle = std::chrono::milliseconds(50), Method method = Method::Inotify);
    ~FileWatcher();
    FileWatcher(const FileWatcher&) = delete;
    FileWatcher& operator=(const FileWatcher&) = delete;

    // Replaces the set of watched files (they need not exist). Paths are reported by poll()
    // exactly as given here.
    void watch(const std::vector<std::filesystem::path>& files);
    std::vector<std::filesystem::path> files() const;

    // The watched files that changed since the last call, each once, sorted. Never blocks.
    std::vector<std::filesystem::path> poll();
    // When the earliest change the last poll() returned happened: the file's status-change time
    // (st_ctime, set by the write or the rename) where it can be trusted, else when the event was
    // read. Clock::time_point{} when the last poll returned nothing.
    Clock::time_point lastChangeTime() const { return lastChangeTime_; }
    // Whether the last poll() saw a file appear in a watched folder that is NOT watched itself
    // (a shader's new #include that did not exist yet, say).
    bool sawOtherFileAppear() const { return sawOtherFileAppear_; }

    // Problems met so far (inotify unavailable, a watch limit reached, the event queue
    // overflowing), one sentence each; the watcher falls back to checking time stamps.
    const std::vector<std::string>& errors() const { return errors_; }
    // Whether every watched folder is watched through inotify (no time-stamp fallback).
    bool allFoldersNotified() const;

private:
    struct FileState {
        bool exists = false;
        long long size = 0, inode = 0;
        long long mtimeNs = 0, ctimeNs = 0;  // ctime: a rename onto the file changes it, size and mtime may not
        bool operator==(const FileState&) const = default;
    };
    struct Folder {
        std::filesystem::path path;  // canonical
        int descriptor = -1;         // inotify watch; -1: checked by time stamp
        std::map<std::string, std::vector<std::filesystem::path>> names;  // file name → paths as given
        std::map<std::string, FileState> states;  // for time-stamp checks
    };
    enum class Pending { Created, Removed };

    static FileState stateOf(const std::filesystem::path& path);
    void addWatch(Folder& folder);
    void readEvents(Clock::time_point now);
    void checkTimeStamps(Folder& folder, Clock::time_point now);
    void markChanged(const Folder& folder, const std::string& name, Clock::time_point seen);
    void markAllChanged(const Folder& folder, Clock::time_point seen);
    void report(const std::string& message);
    Folder* folderOf(int descriptor);

    int fd_ = -1;
    Clock::duration settle_;
    std::map<std::filesystem::path, Folder> folders_;  // by canonical path
    std::map<std::filesystem::path, Clock::time_point> changed_;  // path as given → when seen
    std::map<std::filesystem::path, std::pair<Pending, Clock::time_point>> pending_;
    std::vector<std::string> errors_;
    std::set<std::string> reported_;
    Clock::time_point lastPoll_{};
    Clock::time_point watchedSince_{};
    Clock::time_point lastChangeTime_{};
    bool sawOtherFileAppear_ = false;
    bool otherFileAppeared_ = false;
};

}  // namespace rmfx
