// `shadelab compare`: two PNG files under the gates of design.md §4, with a heatmap and a JSON report.
#pragma once

namespace shadelab::cli {

int compareCommand(int argc, char** argv);  // argv[1] == "compare"; exit 0 within gates, 1 not, 2 error

}  // namespace shadelab::cli
