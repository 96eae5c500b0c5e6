// `shadelab view`: the viewer's command line, parsed here with cli::Args; app/app.h runs the window. A build
// without the viewer (SHADELAB_BUILD_VIEWER=OFF) links view_unavailable.cpp instead, which only says so.
#pragma once

namespace shadelab::cli {

// argv[1] is "view". Throws UsageError (exit 2), and InputError or std::runtime_error (exit 1).
int viewCommand(int argc, char** argv);

}  // namespace shadelab::cli
