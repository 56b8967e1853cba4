#include "io/file/AtomicFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>

namespace rmfx {
namespace fs = std::filesystem;
namespace {

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

Error failure(const fs::path& path, const std::string& step, int error) {
    return Error{"cannot save " + quoted(path) + ": " + step + ": " + std::strerror(error)};
}

// ".NAME.PID.N.tmp" beside the file: hidden, and unique within this process.
fs::path temporaryName(const fs::path& file) {
    static std::atomic<unsigned> counter{0};
    return file.parent_path() / ("." + file.filename().string() + "." + std::to_string(::getpid()) + "." +
                                 std::to_string(counter++) + ".tmp");
}

// A file beside the one being saved that is removed again unless a rename put it in place.
class TemporaryFile {
public:
    explicit TemporaryFile(fs::path beside) : beside_(std::move(beside)) {}
    ~TemporaryFile() {
        if (fd_ >= 0) ::close(fd_);
        if (!path_.empty()) ::unlink(path_.c_str());
    }
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;

    // A new file holding `contents`, on disk (fsync), with the permissions and owner of `like`
    // (else the default ones for a new file).
    bool write(std::string_view contents, const struct stat* like) {
        for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
            fs::path name = temporaryName(beside_);
            fd_ = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, like ? 0600 : 0666);
            if (fd_ >= 0) path_ = name;
            else if (errno != EEXIST) break;
        }
        if (fd_ < 0) {
            int error = errno;
            return fail(error, "cannot create a temporary file in " + quoted(folder()));
        }
        for (std::string_view rest = contents; !rest.empty();) {
            ssize_t written = ::write(fd_, rest.data(), rest.size());
            if (written < 0 && errno == EINTR) continue;
            if (written < 0) {
                int error = errno;
                return fail(error, "cannot write " + quoted(path_));
            }
            rest.remove_prefix(static_cast<size_t>(written));
        }
        if (like) {
            // The owner first: fchown clears set-user-ID bits that fchmod then restores. Only
            // a privileged process may give a file away; anyone else keeps their own ownership.
            struct stat now {};
            if (::fstat(fd_, &now) == 0 && (now.st_uid != like->st_uid || now.st_gid != like->st_gid))
                (void)::fchown(fd_, like->st_uid, like->st_gid);
            if (::fchmod(fd_, like->st_mode & 07777) != 0) {
                int error = errno;
                return fail(error, "cannot set the permissions of " + quoted(path_));
            }
        }
        if (::fsync(fd_) != 0) {
            int error = errno;
            return fail(error, "cannot flush " + quoted(path_) + " to disk");
        }
        int fd = fd_;
        fd_ = -1;
        if (::close(fd) != 0) {
            int error = errno;
            return fail(error, "cannot close " + quoted(path_));
        }
        return true;
    }

    // A second name for `existing` (a hard link); false where the file system has none.
    bool link(const fs::path& existing) {
        for (int attempt = 0; attempt < 100; ++attempt) {
            fs::path name = temporaryName(beside_);
            if (::link(existing.c_str(), name.c_str()) == 0) {
                path_ = name;
                return true;
            }
            if (errno != EEXIST) break;
        }
        int error = errno;
        return fail(error, "cannot link " + quoted(existing));
    }

    // Moves the file to `destination`, replacing what is there; from then on it is no longer temporary.
    bool renameTo(const fs::path& destination) {
        if (::rename(path_.c_str(), destination.c_str()) != 0) {
            int error = errno;
            return fail(error, "cannot rename " + quoted(path_) + " to " + quoted(destination));
        }
        path_.clear();
        return true;
    }

    const std::string& step() const { return step_; }
    int error() const { return error_; }

private:
    fs::path folder() const { return beside_.parent_path().empty() ? fs::path(".") : beside_.parent_path(); }

    bool fail(int error, std::string step) {
        error_ = error;
        step_ = std::move(step);
        return false;
    }

    fs::path beside_;
    fs::path path_;  // empty: nothing to remove
    int fd_ = -1;
    std::string step_;
    int error_ = 0;
};

bool readWhole(const fs::path& path, std::string& out) {
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    char buffer[65536];
    while (true) {
        ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            int error = errno;
            ::close(fd);
            errno = error;
            return n == 0;
        }
        out.append(buffer, static_cast<size_t>(n));
    }
}

// Makes the renames durable. Some file systems cannot sync a folder (EINVAL): nothing to do there.
bool syncFolder(const fs::path& folder) {
    int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return false;
    bool ok = ::fsync(fd) == 0 || errno == EINVAL;
    int error = errno;
    ::close(fd);
    errno = error;
    return ok;
}

}  // namespace

Result<std::string> readWholeFile(const fs::path& path) {
    std::string text;
    if (!readWhole(path, text)) {
        int error = errno;
        return Error{"cannot read " + quoted(path) + ": " + std::strerror(error)};
    }
    return text;
}

Result<void> writeFileAtomically(const fs::path& requested, std::string_view contents, bool keepBackup) {
    fs::path path = requested;
    std::error_code ec;
    if (fs::is_symlink(path, ec)) {
        fs::path target = fs::canonical(path, ec);
        if (ec) return Error{"cannot save " + quoted(requested) + ": cannot follow the symbolic link: " + ec.message()};
        path = target;
    }
    if (!path.has_filename()) return Error{"cannot save " + quoted(requested) + ": it names a folder, not a file"};
    fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();

    struct stat original {};
    bool exists = ::stat(path.c_str(), &original) == 0;
    if (int error = errno; !exists && error != ENOENT) return failure(path, "cannot look at it", error);
    if (exists && !S_ISREG(original.st_mode))
        return Error{"cannot save " + quoted(path) + ": it is not a regular file"};

    TemporaryFile next(path);
    if (!next.write(contents, exists ? &original : nullptr)) return failure(path, next.step(), next.error());

    if (keepBackup && exists) {
        fs::path backup = path;
        backup += ".bak";
        TemporaryFile previous(path);
        if (!previous.link(path)) {
            std::string old;
            if (!readWhole(path, old)) {
                int error = errno;
                return failure(path, "cannot read it to keep a backup", error);
            }
            if (!previous.write(old, &original)) return failure(path, previous.step(), previous.error());
        }
        if (!previous.renameTo(backup)) return failure(path, previous.step(), previous.error());
    }
    if (!next.renameTo(path)) return failure(path, next.step(), next.error());
    if (!syncFolder(folder)) {
        int error = errno;
        return failure(path, "the new contents are in place, but syncing the folder " + quoted(folder) + " failed",
                       error);
    }
    return {};
}

}  // namespace rmfx
