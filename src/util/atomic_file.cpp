// Atomic whole-file writes (temp file in the same folder, fsync, rename).
// POSIX only. Every failure becomes an InputError naming the path; nothing is left half-written.
#include "util/atomic_file.h"

#include "util/input_error.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace shadelab {

namespace {

std::string errnoText(int err) { return std::strerror(err); }

// Closes the descriptor and unlinks the temp file unless released; used on every error path.
class TempFile {
public:
    TempFile(std::string path, int fd) : path_(std::move(path)), fd_(fd) {}
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;
    ~TempFile() {
        if (fd_ >= 0) ::close(fd_);
        if (!released_) ::unlink(path_.c_str());
    }
    int fd() const { return fd_; }
    // Returns 0 or the errno of a failed close.
    int close() {
        int rc = ::close(fd_);
        fd_ = -1;
        // Linux releases the descriptor even when close fails; EINTR is not a write failure.
        return (rc == 0 || errno == EINTR) ? 0 : errno;
    }
    void release() { released_ = true; }
    const std::string& path() const { return path_; }

private:
    std::string path_;
    int fd_;
    bool released_ = false;
};

int openTemp(const std::string& path, std::string& tmpPath, int& err) {
    static std::atomic<unsigned> counter{0};
    for (int attempt = 0; attempt < 100; ++attempt) {
        tmpPath = path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
        int fd = ::open(tmpPath.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, 0644);
        if (fd >= 0) return fd;
        if (errno == EINTR || errno == EEXIST) continue;
        err = errno;
        return -1;
    }
    err = EEXIST;
    return -1;
}

}  // namespace

void writeFileAtomic(const std::string& path, const void* data, size_t size) {
    // Refuse a directory up front: rename() would give a less helpful "Is a directory" only sometimes.
    struct stat st;
    if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
        throw InputError(path, "cannot write: is a directory");

    std::string tmpPath;
    int err = 0;
    int fd = openTemp(path, tmpPath, err);
    if (fd < 0) throw InputError(path, "cannot write: " + errnoText(err));
    TempFile tmp(tmpPath, fd);

    const char* p = static_cast<const char*>(data);
    size_t left = size;
    while (left > 0) {
        ssize_t n = ::write(tmp.fd(), p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw InputError(path, "cannot write: " + errnoText(errno));
        }
        if (n == 0) throw InputError(path, "cannot write: " + errnoText(EIO));
        p += n;
        left -= size_t(n);
    }
    // Without fsync a crash after the rename can leave an empty file under the final name.
    while (::fsync(tmp.fd()) != 0) {
        if (errno == EINTR) continue;
        // Some file systems (and pipes) cannot fsync; that is not a write failure.
        if (errno == EINVAL || errno == EROFS) break;
        throw InputError(path, "cannot write: " + errnoText(errno));
    }
    if (int closeErr = tmp.close()) throw InputError(path, "cannot write: " + errnoText(closeErr));
    if (::rename(tmpPath.c_str(), path.c_str()) != 0)
        throw InputError(path, "cannot write: " + errnoText(errno));
    tmp.release();
}

}  // namespace shadelab
