// `shadelab render`: one scene (JSON or glTF) to one PNG, headless.
#pragma once

namespace shadelab::cli {

int renderCommand(int argc, char** argv);  // argv[1] == "render"

}  // namespace shadelab::cli
