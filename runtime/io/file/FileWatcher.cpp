#include "io/file/FileWatcher.h"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <sys/inotify.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rmfx {
namespace {

constexpr uint32_t folderMask = IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE | IN_DELETE | IN_MOVED_FROM |
                                IN_DELETE_SELF | IN_MOVE_SELF | IN_ONLYDIR;

long long nanoseconds(const timespec& t) { return static_cast<long long>(t.tv_sec) * 1000000000LL + t.tv_nsec; }

}  // namespace

FileWatcher::FileWatcher(Clock::duration settle, Method method) : settle_(settle) {
    if (method == Method::TimeStamps) return;
    fd_ = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (fd_ < 0)
        report(std::string("cannot use inotify (") + std::strerror(errno) +
               "; fs.inotify.max_user_instances may be reached): watched files are checked by time stamp instead");
}

FileWatcher::~FileWatcher() {
    if (fd_ >= 0) ::close(fd_);
}

FileWatcher::FileState FileWatcher::stateOf(const std::filesystem::path& path) {
    FileState state;
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return state;
    state.exists = true;
    state.size = static_cast<long long>(st.st_size);
    state.inode = static_cast<long long>(st.st_ino);
    state.mtimeNs = nanoseconds(st.st_mtim);
    state.ctimeNs = nanoseconds(st.st_ctim);
    return state;
}

void FileWatcher::report(const std::string& message) {
    if (reported_.insert(message).second) errors_.push_back(message);
}

FileWatcher::Folder* FileWatcher::folderOf(int descriptor) {
    for (auto& [path, folder] : folders_)
        if (folder.descriptor == descriptor) return &folder;
    return nullptr;
}

void FileWatcher::addWatch(Folder& folder) {
    folder.descriptor = -1;
    if (fd_ < 0) return;
    int wd = inotify_add_watch(fd_, folder.path.c_str(), folderMask);
    if (wd < 0) {
        int e = errno;
        if (e == ENOENT || e == ENOTDIR) return;  // not there yet: checked by time stamp until it is
        std::string why = e == ENOSPC ? "the inotify watch limit is reached (fs.inotify.max_user_watches)"
                                      : std::strerror(e);
        report("cannot watch folder " + folder.path.string() + " (" + why +
               "): its files are checked by time stamp instead");
        return;
    }
    // Two paths to one folder (a bind mount) share a watch descriptor; the second is polled.
    if (Folder* other = folderOf(wd); other && other != &folder) return;
    folder.descriptor = wd;
}

void FileWatcher::watch(const std::vector<std::filesystem::path>& files) {
    std::map<std::filesystem::path, Folder> next;
    for (const auto& file : files) {
        std::filesystem::path absolute = std::filesystem::absolute(file).lexically_normal();
        std::error_code ignored;
        std::filesystem::path folder = std::filesystem::weakly_canonical(absolute.parent_path(), ignored);
        if (folder.empty()) folder = absolute.parent_path();
        Folder& f = next[folder];
        f.path = folder;
        auto& paths = f.names[absolute.filename().string()];
        if (std::find(paths.begin(), paths.end(), file) == paths.end()) paths.push_back(file);
    }
    for (auto& [path, old] : folders_) {
        auto it = next.find(path);
        if (it != next.end()) {
            it->second.descriptor = old.descriptor;
            it->second.states = std::move(old.states);
        } else if (old.descriptor >= 0) {
            inotify_rm_watch(fd_, old.descriptor);
        }
    }
    folders_ = std::move(next);
    for (auto& [path, folder] : folders_) {
        if (folder.descriptor < 0) addWatch(folder);
        if (folder.descriptor >= 0) continue;
        for (const auto& [name, paths] : folder.names)
            if (!folder.states.count(name)) folder.states[name] = stateOf(folder.path / name);
    }
    watchedSince_ = Clock::now();
    std::set<std::filesystem::path> kept(files.begin(), files.end());
    std::erase_if(changed_, [&](const auto& entry) { return !kept.count(entry.first); });
    std::erase_if(pending_, [&](const auto& entry) { return !kept.count(entry.first); });
}

std::vector<std::filesystem::path> FileWatcher::files() const {
    std::vector<std::filesystem::path> out;
    for (const auto& [path, folder] : folders_)
        for (const auto& [name, paths] : folder.names) out.insert(out.end(), paths.begin(), paths.end());
    std::sort(out.begin(), out.end());
    return out;
}

bool FileWatcher::allFoldersNotified() const {
    return std::all_of(folders_.begin(), folders_.end(), [](const auto& f) { return f.second.descriptor >= 0; });
}

void FileWatcher::markChanged(const Folder& folder, const std::string& name, Clock::time_point seen) {
    auto it = folder.names.find(name);
    if (it == folder.names.end()) return;
    for (const auto& path : it->second) {
        changed_.emplace(path, seen);
        pending_.erase(path);
    }
}

void FileWatcher::markAllChanged(const Folder& folder, Clock::time_point seen) {
    for (const auto& [name, paths] : folder.names)
        for (const auto& path : paths) pending_[path] = {Pending::Removed, seen};
}

void FileWatcher::readEvents(Clock::time_point now) {
    if (fd_ < 0) return;
    alignas(inotify_event) char buffer[16384];
    for (;;) {
        ssize_t length = ::read(fd_, buffer, sizeof buffer);
        if (length <= 0) {
            if (length < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
                report(std::string("reading inotify events failed: ") + std::strerror(errno));
            if (length < 0 && errno == EINTR) continue;
            return;
        }
        for (char* p = buffer; p < buffer + length;) {
            const auto* event = reinterpret_cast<const inotify_event*>(p);
            p += sizeof(inotify_event) + event->len;
            if (event->mask & IN_Q_OVERFLOW) {
                report("the inotify event queue overflowed: every watched file is read again");
                for (auto& [path, folder] : folders_)
                    for (const auto& [name, paths] : folder.names) markChanged(folder, name, now);
                continue;
            }
            Folder* folder = folderOf(event->wd);
            if (!folder) continue;
            if (event->mask & (IN_DELETE_SELF | IN_MOVE_SELF | IN_IGNORED)) {
                // The folder went away (or moved): its files are gone from their paths. It is
                // checked by time stamp, and watched again once it is back.
                if (event->mask & IN_MOVE_SELF) inotify_rm_watch(fd_, folder->descriptor);
                folder->descriptor = -1;
                folder->states.clear();
                for (const auto& [name, paths] : folder->names) folder->states[name] = FileState{};
                markAllChanged(*folder, now);
                continue;
            }
            if (event->len == 0) continue;
            std::string name = event->name;
            auto it = folder->names.find(name);
            if (it == folder->names.end()) {
                if (event->mask & (IN_CREATE | IN_MOVED_TO)) otherFileAppeared_ = true;
                continue;
            }
            for (const auto& path : it->second) {
                if (event->mask & (IN_CLOSE_WRITE | IN_MOVED_TO)) {
                    changed_.emplace(path, now);
                    pending_.erase(path);
                } else if (event->mask & IN_CREATE) {
                    pending_[path] = {Pending::Created, now};
                } else if (event->mask & (IN_DELETE | IN_MOVED_FROM)) {
                    changed_.erase(path);
                    pending_[path] = {Pending::Removed, now};
                }
            }
        }
    }
}

void FileWatcher::checkTimeStamps(Folder& folder, Clock::time_point now) {
    for (const auto& [name, paths] : folder.names) {
        FileState& state = folder.states[name];
        FileState current = stateOf(folder.path / name);
        bool same = state == current;
        state = current;
        if (same) continue;
        for (const auto& path : paths) {
            if (current.exists) {
                changed_.emplace(path, now);
                pending_.erase(path);
            } else if (!pending_.count(path)) {
                pending_[path] = {Pending::Removed, now};
            }
        }
    }
}

std::vector<std::filesystem::path> FileWatcher::poll() {
    Clock::time_point now = Clock::now();
    otherFileAppeared_ = false;
    readEvents(now);
    for (auto& [path, folder] : folders_) {
        if (folder.descriptor >= 0) continue;
        std::error_code ignored;
        if (fd_ >= 0 && std::filesystem::is_directory(folder.path, ignored)) addWatch(folder);
        checkTimeStamps(folder, now);
    }
    Clock::time_point after = Clock::now();
    for (auto it = pending_.begin(); it != pending_.end();) {
        if (after - it->second.second < settle_) {
            ++it;
            continue;
        }
        changed_.emplace(it->first, it->second.second);
        it = pending_.erase(it);
    }

    std::vector<std::filesystem::path> out;
    lastChangeTime_ = {};
    // The status-change time the write or rename gave the file, on the steady clock; kept
    // within the span in which the event can have happened.
    auto realNow = std::chrono::system_clock::now();
    for (const auto& [path, seen] : changed_) {
        out.push_back(path);
        Clock::time_point when = seen;
        FileState state = stateOf(path);
        if (state.exists) {
            auto ctime = std::chrono::system_clock::time_point(
                std::chrono::duration_cast<std::chrono::system_clock::duration>(std::chrono::nanoseconds(state.ctimeNs)));
            Clock::time_point changedAt = after - std::chrono::duration_cast<Clock::duration>(realNow - ctime);
            Clock::time_point earliest = std::min(std::max(lastPoll_, watchedSince_), seen);
            when = std::clamp(changedAt, earliest, seen);
        }
        if (lastChangeTime_ == Clock::time_point{} || when < lastChangeTime_) lastChangeTime_ = when;
    }
    changed_.clear();
    sawOtherFileAppear_ = otherFileAppeared_;
    lastPoll_ = after;
    return out;
}

}  // namespace rmfx
