// printWarning / printError / printUsageError over errorLine.
#include "util/messages.h"

#include "util/error_line.h"

#include <cstdio>

namespace shadelab {
namespace {

void print(const char* kind, const std::string& text) {
    std::fprintf(stderr, "shadelab: %s: %s\n", kind, errorLine(text).c_str());
}

}  // namespace

void printWarning(const std::string& text) { print("warning", text); }
void printError(const std::string& text) { print("error", text); }
void printUsageError(const std::string& text) { print("usage error", text); }

}  // namespace shadelab
