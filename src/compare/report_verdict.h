// What every comparison report opens or ends with, 8-bit (compare_report.cpp) and linear-light
// (linear_compare.cpp) alike: the verdict and its reasons as the summary's last lines, and the JSON report's
// first keys (verdict, pass, reasons, the images, the size). Internal to src/compare/.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace shadelab::compare_detail {

using Json = nlohmann::ordered_json;  // keys in the order written: verdict first, for people reading it

inline std::string verdictLines(bool pass, const std::vector<std::string>& reasons) {
    std::string s = pass ? "verdict: PASS\n" : "verdict: FAIL\n";
    for (const std::string& reason : reasons) s += "  - " + reason + "\n";
    return s;
}

inline Json verdictJson(bool pass, const std::vector<std::string>& reasons, const std::string& imageA,
                        const std::string& imageB, int width, int height) {
    Json j;
    j["verdict"] = pass ? "pass" : "fail";
    j["pass"] = pass;
    j["reasons"] = reasons;
    if (!imageA.empty()) j["image_a"] = imageA;
    if (!imageB.empty()) j["image_b"] = imageB;
    j["width"] = width;
    j["height"] = height;
    return j;
}

}  // namespace shadelab::compare_detail
