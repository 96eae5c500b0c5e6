// `shadelab view`: the viewer's command line, parsed here with cli::Args; app/app.h runs the window.
#pragma once

namespace shadelab::cli {

// argv[1] is "view". Throws UsageError (exit 2), and InputError or std::runtime_error (exit 1).
int viewCommand(int argc, char** argv);

}  // namespace shadelab::cli
