// WarningCapture: keeps the warnings a load prints, so the viewer can show them in its panel as well as on
// the terminal (ignored textures were once mentioned only on the terminal). While one is alive on a
// thread, WarningCapture::warn prints each line with printWarning and records it there as printed (errorLine:
// escaped, capped); loaders take
// WarningCapture::warn as their `warn` callback like printWarning itself.
#pragma once

#include <string>
#include <vector>

namespace shadelab {

class WarningCapture {
public:
    WarningCapture();
    ~WarningCapture();
    WarningCapture(const WarningCapture&) = delete;
    WarningCapture& operator=(const WarningCapture&) = delete;

    static void warn(const std::string& text);
    const std::vector<std::string>& lines() const { return lines_; }

private:
    std::vector<std::string> lines_;
    WarningCapture* outer_;
};

}  // namespace shadelab
