#include "util/warning_capture.h"

#include "util/error_line.h"
#include "util/messages.h"

namespace shadelab {
namespace {

thread_local WarningCapture* g_active = nullptr;

}  // namespace

WarningCapture::WarningCapture() : outer_(g_active) { g_active = this; }

WarningCapture::~WarningCapture() { g_active = outer_; }

void WarningCapture::warn(const std::string& text) {
    printWarning(text);
    if (g_active) g_active->lines_.push_back(errorLine(text));  // the panel's line is the terminal's
}

}  // namespace shadelab
