// Output paths of the commands: `-` is stdout, anything else a file written atomically (util/atomic_file.h).
// Also the refusals made before any work: an output that is one of the inputs, or that cannot be written.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace shadelab {

// "-", or "/dev/stdout" spelt out: the output goes to this process's stdout, whatever that is (pipe,
// terminal, file). Other links to a descriptor (/proc/self/fd/1) follow the file rules of atomic_file.h.
bool isStdout(const std::string& path);

// Throws InputError naming `path` when the output is the same existing file (device and inode, through
// symlinks) as one of `inputs`: "<path>: refusing to overwrite an input with the output (<flag>)". Inputs
// that do not exist are skipped; their own read reports them.
void refuseInputAsOutput(const std::string& path, const std::string& flag, const std::vector<std::string>& inputs);

// Creates the folder of the output `path` with its parents when missing (so that `render -o out/x.png` and
// Python's `image.save("out/x.png")` work in a fresh clone). Throws InputError naming `path` when it cannot
// ("cannot create its folder out: Permission denied"). Nothing for stdout or a bare file name.
void createOutputFolder(const std::string& path);

// refuseInputAsOutput; then the output's folder is created with its parents when missing (so that
// `render -o out/x.png` works in a fresh clone); then checkWritableTarget (an existing non-regular file, a
// read-only folder), so a command fails before it renders. A path through an existing file is refused
// ("cannot write: Not a directory"). Nothing to check for stdout.
void checkOutput(const std::string& path, const std::string& flag, const std::vector<std::string>& inputs);

// The name of an output derived from another (`<stem>_heat.png`, `<stem>_report.json`): stem + suffix, after
// the checks the stem itself would get. Throws InputError naming the stem when it is stdout or names something
// other than a regular file (a device, a FIFO, a folder): "/dev/null" must not turn into a new
// "/dev/null_heat.png". The derived file is then written like any output (writeFileAtomic's checks, input
// files included).
std::string derivedOutput(const std::string& stem, const std::string& suffix);

// Writes `data` to stdout when isStdout (errors name "stdout"), else writeFileAtomic.
void writeOutput(const std::string& path, const void* data, size_t size);

}  // namespace shadelab
