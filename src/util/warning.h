// printWarning: the one way shadelab reports a non-fatal problem (an unknown JSON field, a glTF feature it
// skips) as one line on stderr. Matches JsonNode's WarnFn, so loaders take it as their `warn` callback.
#pragma once

#include <string>

namespace shadelab {

// Writes "shadelab: warning: <line>" and a newline to stderr.
void printWarning(const std::string& line);

}  // namespace shadelab
