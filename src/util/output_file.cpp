// Output paths: stdout for `-`, the same-file refusal (st_dev/st_ino) and the up-front checks; the atomic
// write itself is util/atomic_file.cpp.
#include "util/output_file.h"

#include "util/atomic_file.h"
#include "util/input_error.h"

#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace shadelab {

// Replacing /dev/stdout's link by a file (as root) or renaming over whatever file stdout is open on would
// both surprise; writing to the descriptor is what the name asks for.
bool isStdout(const std::string& path) { return path == "-" || path == "/dev/stdout"; }

void refuseInputAsOutput(const std::string& path, const std::string& flag, const std::vector<std::string>& inputs) {
    if (isStdout(path)) return;
    struct stat out;
    if (::stat(path.c_str(), &out) != 0) return;  // a new file cannot be an input
    for (const std::string& input : inputs) {
        struct stat in;
        if (::stat(input.c_str(), &in) != 0 || in.st_dev != out.st_dev || in.st_ino != out.st_ino) continue;
        throw InputError(path, "refusing to overwrite an input with the output (" + flag + ")" +
                                   (input == path ? "" : ": it is " + input));
    }
}

void createOutputFolder(const std::string& path) {
    if (isStdout(path)) return;
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    std::error_code ec;
    if (!folder.empty() && !std::filesystem::exists(folder, ec)) {
        std::filesystem::create_directories(folder, ec);
        if (ec) throw InputError(path, "cannot create its folder " + folder.string() + ": " + ec.message());
    }
}

void checkOutput(const std::string& path, const std::string& flag, const std::vector<std::string>& inputs) {
    if (isStdout(path)) return;
    refuseInputAsOutput(path, flag, inputs);
    createOutputFolder(path);
    checkWritableTarget(path);
}

std::string derivedOutput(const std::string& stem, const std::string& suffix) {
    if (isStdout(stem)) throw InputError(stem, "stdout cannot name derived outputs (" + suffix + "); give a file stem");
    struct stat st;
    if (::stat(stem.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        throw InputError(stem, "names a " + std::string(S_ISDIR(st.st_mode) ? "folder" : "device or special file") +
                                   ", not a file stem for derived outputs (" + suffix + ")");
    return stem + suffix;
}

void writeOutput(const std::string& path, const void* data, size_t size) {
    if (!isStdout(path)) {
        writeFileAtomic(path, data, size);
        return;
    }
    // Whatever stdio holds goes first; then the bytes straight to the descriptor, errors checked.
    if (std::fflush(stdout) != 0) throw InputError("stdout", std::string("cannot write: ") + std::strerror(errno));
    const char* p = static_cast<const char*>(data);
    size_t left = size;
    while (left > 0) {
        ssize_t n = ::write(STDOUT_FILENO, p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw InputError("stdout", std::string("cannot write: ") + std::strerror(errno));
        }
        p += n;
        left -= size_t(n);
    }
}

}  // namespace shadelab
