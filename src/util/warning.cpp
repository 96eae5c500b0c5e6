// printWarning (warning.h).
#include "util/warning.h"

#include <cstdio>

namespace shadelab {

void printWarning(const std::string& line) { std::fprintf(stderr, "shadelab: warning: %s\n", line.c_str()); }

}  // namespace shadelab
