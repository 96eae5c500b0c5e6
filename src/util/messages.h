// The one way shadelab prints a message on stderr: "shadelab: <kind>: <text>", always one line (the text
// goes through errorLine: control characters escaped, capped at 300 bytes). printWarning matches
// JsonNode's WarnFn, so loaders take it as their `warn` callback.
#pragma once

#include <string>

namespace shadelab {

void printWarning(const std::string& text);     // a non-fatal problem: an unknown field, a skipped feature
void printError(const std::string& text);       // bad input or a failed command (exit 1)
void printUsageError(const std::string& text);  // a bad flag or argument (exit 2)

}  // namespace shadelab
