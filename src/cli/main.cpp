// shadelab: the command-line entry point. Dispatches subcommands and turns exceptions into one line on
// stderr and an exit code: 1 for bad input or a failed render, 2 for usage errors.
#include "cli/compare_command.h"
#include "cli/render_command.h"
#include "cli/view_command.h"
#include "util/input_error.h"
#include "util/messages.h"

#include <cstdio>
#include <exception>
#include <string>

namespace {

const char* const kHelp =
    "usage: shadelab <command> [options]\n"
    "\n"
    "A lab for the Phong and Blinn-Phong lighting models.\n"
    "\n"
    "commands:\n"
    "  render    render a scene (.json, .gltf, .glb) to PNG, headless\n"
    "  compare   compare two PNG images under the raster-vs-reference gates\n"
    "  view      open a scene in the interactive viewer (needs a display)\n"
    "\n"
    "Run 'shadelab <command> --help' for a command's options. Docs: docs/cli.md\n";

}  // namespace

int main(int argc, char** argv) {
    using namespace shadelab;
    const std::string command = argc > 1 ? argv[1] : "";
    try {
        if (command == "render") return cli::renderCommand(argc, argv);
        if (command == "compare") return cli::compareCommand(argc, argv);
        if (command == "view") return cli::viewCommand(argc, argv);
        if (command == "-h" || command == "--help" || command == "help") {
            std::fputs(kHelp, stdout);
            return 0;
        }
        if (command == "--version") {
            std::puts("shadelab " SHADELAB_VERSION);
            return 0;
        }
        throw UsageError(command.empty() ? "no command given" : "unknown command '" + command + "'");
    } catch (const UsageError& e) {
        printUsageError(e.what());
        if (command != "render" && command != "compare" && command != "view") std::fputs(kHelp, stderr);
        return 2;
    } catch (const std::exception& e) {
        printError(e.what());
        return 1;
    }
}
