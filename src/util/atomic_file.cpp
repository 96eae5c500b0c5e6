// Atomic whole-file writes (O_TMPFILE + linkat, else a short-named temporary; fsync; rename; fsync of the
// folder). POSIX/Linux. Every failure becomes an InputError naming the path; nothing is left half-written.
#include "util/atomic_file.h"

#include "util/input_error.h"
#include "util/input_files.h"
#include "util/signal_cleanup.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <utility>

namespace shadelab {

namespace {

std::string errnoText(int err) { return std::strerror(err); }

[[noreturn]] void failWrite(const std::string& path, int err) {
    throw InputError(path, "cannot write: " + errnoText(err));
}

constexpr size_t kChunkBytes = size_t(1) << 20;  // write() size; also the afterChunk granularity

// A descriptor closed on every path; close() reports the error a careful writer must check.
class FileDescriptor {
public:
    explicit FileDescriptor(int fd) : fd_(fd) {}
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    ~FileDescriptor() {
        if (fd_ >= 0) ::close(fd_);
    }
    int get() const { return fd_; }
    // Returns 0 or the errno of a failed close.
    int close() {
        int rc = ::close(fd_);
        fd_ = -1;
        // Linux releases the descriptor even when close fails; EINTR is not a write failure.
        return (rc == 0 || errno == EINTR) ? 0 : errno;
    }

private:
    int fd_;
};

// A temporary name in the target's folder, unlinked on every error path unless released.
class TempName {
public:
    TempName(int dirFd, std::string name) : dirFd_(dirFd), name_(std::move(name)) {}
    TempName(const TempName&) = delete;
    TempName& operator=(const TempName&) = delete;
    ~TempName() {
        if (!released_) ::unlinkat(dirFd_, name_.c_str(), 0);
    }
    void release() { released_ = true; }

private:
    int dirFd_;
    std::string name_;
    bool released_ = false;
};

// Short whatever the target's name, so a 255-byte name still has room: ".shadelab.<pid>.<n>.tmp".
std::string tempName() {
    static std::atomic<unsigned> counter{0};
    return ".shadelab." + std::to_string(::getpid()) + "." + std::to_string(counter++) + ".tmp";
}

const char* fileTypeName(mode_t mode) {
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISSOCK(mode)) return "a socket";
    return "a file that is not a regular file";
}

// The regular file to create or replace: its folder and its name there.
struct Target {
    std::string dir;
    std::string name;
};

// Applies the type rules of atomic_file.h. A symlink to a regular file resolves to the file it names, so
// the rename replaces that file and the link stays a link (as `>` and cp do, not as `sed -i` does).
Target resolveTarget(const std::string& path) {
    std::string real = path;
    struct stat st;
    if (::lstat(path.c_str(), &st) == 0) {
        const bool link = S_ISLNK(st.st_mode);
        if (link && ::stat(path.c_str(), &st) != 0) {
            if (errno == ENOENT) throw InputError(path, "cannot write: a symlink to a missing file (not followed)");
            failWrite(path, errno);
        }
        if (S_ISDIR(st.st_mode)) throw InputError(path, "cannot write: is a directory");
        if (!S_ISREG(st.st_mode))
            throw InputError(path, std::string("refusing to replace ") + fileTypeName(st.st_mode) +
                                       (link ? " (through a symlink)" : "") + "; only regular files are written");
        if (link) {
            char* resolved = ::realpath(path.c_str(), nullptr);
            if (!resolved) failWrite(path, errno);
            real = resolved;
            std::free(resolved);
        }
    } else if (errno != ENOENT) {
        failWrite(path, errno);  // ENOTDIR, EACCES, ENAMETOOLONG, ELOOP
    }
    const size_t slash = real.find_last_of('/');
    Target t;
    t.dir = slash == std::string::npos ? "." : slash == 0 ? "/" : real.substr(0, slash);
    t.name = slash == std::string::npos ? real : real.substr(slash + 1);
    if (t.name.empty() || t.name == "." || t.name == "..") throw InputError(path, "cannot write: is a directory");
    return t;
}

int openDir(const std::string& path, const std::string& dir) {
    int fd;
    do {
        fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    } while (fd < 0 && errno == EINTR);
    if (fd < 0) failWrite(path, errno);
    return fd;
}

void writeAll(const std::string& path, int fd, const void* data, size_t size, const AtomicWriteOptions& options) {
    const char* p = static_cast<const char*>(data);
    size_t done = 0;
    while (done < size) {
        ssize_t n = ::write(fd, p + done, std::min(size - done, kChunkBytes));
        if (n < 0) {
            if (errno == EINTR) continue;
            failWrite(path, errno);
        }
        if (n == 0) failWrite(path, EIO);
        done += size_t(n);
        if (options.afterChunk) options.afterChunk(done);
    }
}

// Without fsync a crash after the rename can leave an empty file under the final name; without the
// folder's fsync, the rename itself may not survive a crash.
void syncFd(const std::string& path, int fd) {
    while (::fsync(fd) != 0) {
        if (errno == EINTR) continue;
        // Some file systems cannot fsync; that is not a write failure.
        if (errno == EINVAL || errno == EROFS) break;
        failWrite(path, errno);
    }
}

void renameOver(const std::string& path, int dirFd, const std::string& from, const std::string& to) {
    if (::renameat(dirFd, from.c_str(), dirFd, to.c_str()) != 0) failWrite(path, errno);
}

// O_TMPFILE: the data goes into an inode with no name, so a signal or crash during the long write leaves
// nothing behind. Only the link-then-rename at the end has a name, for two system calls. Returns false,
// before anything is named, when the file system or kernel cannot do it.
bool writeAnonymous(const std::string& path, int dirFd, const std::string& name, const void* data, size_t size,
                    const AtomicWriteOptions& options) {
    int fd;
    do {
        fd = ::openat(dirFd, ".", O_TMPFILE | O_WRONLY | O_CLOEXEC, 0644);
    } while (fd < 0 && errno == EINTR);
    if (fd < 0) {
        if (errno == EOPNOTSUPP || errno == EISDIR || errno == EINVAL) return false;
        failWrite(path, errno);
    }
    FileDescriptor file(fd);
    writeAll(path, file.get(), data, size, options);
    syncFd(path, file.get());

    // linkat cannot replace a file, so link under a unique name and rename that over the target.
    for (int attempt = 0; attempt < 100; ++attempt) {
        const std::string temp = tempName();
        SignalCleanup cleanup(dirFd, temp);
        // AT_EMPTY_PATH needs CAP_DAC_READ_SEARCH on most kernels; /proc/self/fd works without it.
        int rc = ::linkat(file.get(), "", dirFd, temp.c_str(), AT_EMPTY_PATH);
        if (rc != 0 && errno != EEXIST) {
            char proc[64];
            std::snprintf(proc, sizeof proc, "/proc/self/fd/%d", file.get());
            rc = ::linkat(AT_FDCWD, proc, dirFd, temp.c_str(), AT_SYMLINK_FOLLOW);
        }
        if (rc != 0) {
            if (errno == EEXIST) continue;
            if (errno == ENOENT && ::access("/proc/self/fd", X_OK) != 0) return false;  // no /proc
            failWrite(path, errno);
        }
        TempName named(dirFd, temp);
        if (int err = file.close()) failWrite(path, err);
        renameOver(path, dirFd, temp, name);
        named.release();
        return true;
    }
    failWrite(path, EEXIST);
}

// The fallback: a named temporary beside the target, removed on error and on SIGINT, SIGTERM and SIGHUP.
void writeNamed(const std::string& path, int dirFd, const std::string& name, const void* data, size_t size,
                const AtomicWriteOptions& options) {
    for (int attempt = 0; attempt < 100; ++attempt) {
        const std::string temp = tempName();
        SignalCleanup cleanup(dirFd, temp);  // armed before the name exists: no window without it
        int fd = ::openat(dirFd, temp.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, 0644);
        if (fd < 0) {
            if (errno == EINTR || errno == EEXIST) continue;
            failWrite(path, errno);
        }
        FileDescriptor file(fd);
        TempName named(dirFd, temp);
        writeAll(path, file.get(), data, size, options);
        syncFd(path, file.get());
        if (int err = file.close()) failWrite(path, err);
        renameOver(path, dirFd, temp, name);
        named.release();
        return;
    }
    failWrite(path, EEXIST);
}

}  // namespace

void checkWritableTarget(const std::string& path) {
    refuseOpenInput(path);
    const Target t = resolveTarget(path);
    FileDescriptor dir(openDir(path, t.dir));
    if (::faccessat(dir.get(), ".", W_OK, AT_EACCESS) != 0) failWrite(path, errno);
}

void writeFileAtomic(const std::string& path, const void* data, size_t size, const AtomicWriteOptions& options) {
    refuseOpenInput(path);
    const Target t = resolveTarget(path);
    FileDescriptor dir(openDir(path, t.dir));
    if (!options.allowTmpFile || !writeAnonymous(path, dir.get(), t.name, data, size, options))
        writeNamed(path, dir.get(), t.name, data, size, options);
    syncFd(path, dir.get());
}

}  // namespace shadelab
