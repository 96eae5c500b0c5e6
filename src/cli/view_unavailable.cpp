// `shadelab view` in a build configured with SHADELAB_BUILD_VIEWER=OFF (no GLFW, no Dear ImGui): one line
// on stderr and exit code 1, as for a machine without a display.
#include "cli/view_command.h"

#include <stdexcept>

namespace shadelab::cli {

int viewCommand(int, char**) {
    throw std::runtime_error(
        "this build has no viewer (configured with SHADELAB_BUILD_VIEWER=OFF); "
        "use 'shadelab render <scene> -o out.png' for images");
}

}  // namespace shadelab::cli
