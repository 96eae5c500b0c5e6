// readFile: path checks, a non-blocking open, fstat checks, and a read bounded by the limit.
#include "util/read_file.h"

#include "util/error_line.h"
#include "util/input_error.h"
#include "util/input_files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>

namespace shadelab {
namespace {

const char* fileKind(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

std::string notRegular(mode_t mode) {
    return std::string("cannot read: is ") + fileKind(mode) + ", not a regular file";
}

std::string overLimit(uint64_t size, uint64_t maxBytes) {
    return "file of " + std::to_string(size) + " bytes exceeds the limit of " + std::to_string(maxBytes) + " bytes";
}

}  // namespace

bool isRegularFile(const std::string& path) {
    struct stat st;
    return path.find('\0') == std::string::npos && ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

std::string readFile(const std::string& path, uint64_t maxBytes) {
    if (path.empty()) throw InputError("\"\"", "empty file name");
    if (path.find('\0') != std::string::npos) throw InputError(errorLine(path), "file name contains a NUL character");
    struct stat st;
    if (::stat(path.c_str(), &st) != 0) {
        const int err = errno;
        throw InputError(path, "cannot read: " + std::string(std::strerror(err)));
    }
    if (!S_ISREG(st.st_mode)) throw InputError(path, notRegular(st.st_mode));
    if (uint64_t(st.st_size) > maxBytes) throw InputError(path, overLimit(uint64_t(st.st_size), maxBytes));

    int fd;
    do {
        fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    } while (fd < 0 && errno == EINTR);
    if (fd < 0) throw InputError(path, "cannot read: " + std::string(std::strerror(errno)));
    struct FdGuard {
        int fd;
        ~FdGuard() { ::close(fd); }
    } guard{fd};
    // The path may have been swapped between stat and open: check what was opened.
    if (::fstat(fd, &st) != 0) throw InputError(path, "cannot read: " + std::string(std::strerror(errno)));
    if (!S_ISREG(st.st_mode)) throw InputError(path, notRegular(st.st_mode));
    if (uint64_t(st.st_size) > maxBytes) throw InputError(path, overLimit(uint64_t(st.st_size), maxBytes));

    std::string out;
    out.reserve(size_t(st.st_size));
    char buf[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0) {
            if (errno == EINTR || errno == EAGAIN) continue;
            throw InputError(path, "cannot read: " + std::string(std::strerror(errno)));
        }
        if (n == 0) break;
        if (uint64_t(out.size()) + uint64_t(n) > maxBytes)
            throw InputError(path,
                             "file grew past the limit of " + std::to_string(maxBytes) + " bytes while being read");
        out.append(buf, size_t(n));
    }
    noteInputRead(path);
    return out;
}

}  // namespace shadelab
