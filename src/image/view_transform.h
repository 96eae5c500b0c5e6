// DisplaySettings: how a linear image is shown and encoded, as plain data every front end edits (the
// command line's --exposure and --view-transform, a scene file's "display", Python's render(exposure=,
// view_transform=), the viewer's View panel and scripts). An exposure in stops multiplies linear values by
// 2^stops, then a view transform maps them into [0, 1]; the encoding (encoding.h) comes after, as before.
// Display only: renderers, comparisons, the difference view and the probe read the linear data untouched.
// The curves themselves are shaders/view_transform.glsl (the viewer's shader and image/encode.cpp share it).
#pragma once

#include "util/name_table.h"

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace shadelab {

// Standard: clamp to [0, 1], today's look and bytes (the default). Filmic: Krzysztof Narkowicz's fit of the
// ACES RRT + ODT, "ACES Filmic Tone Mapping Curve" (2016), applied per channel as published (no 0.6
// pre-scale): highlights roll off towards 1 instead of clipping, and a value of 1 shows as about 0.8.
enum class ViewTransform { Standard, Filmic };

// The words of --view-transform, of a scene's display.viewTransform, of Python and of viewer scripts.
inline constexpr EnumName<ViewTransform> kViewTransformNames[] = {
    {ViewTransform::Standard, "standard"},
    {ViewTransform::Filmic, "filmic"},
};

inline const char* toString(ViewTransform t) { return nameOf(kViewTransformNames, t); }
inline std::optional<ViewTransform> parseViewTransform(std::string_view name) {
    return lookupName(kViewTransformNames, name);
}

// Exposure bounds, stops: 2^±16 spans any scene shadelab lights (radiance is capped at 1e6) without taking a
// float near overflow or underflow.
inline constexpr double kMinExposure = -16.0, kMaxExposure = 16.0;

struct DisplaySettings {
    double exposure = 0.0;  // stops, kMinExposure..kMaxExposure: linear values times 2^exposure
    ViewTransform transform = ViewTransform::Standard;

    // Today's conversion exactly: no exposure, the Standard clamp.
    bool isStandard() const { return exposure == 0.0 && transform == ViewTransform::Standard; }
    // The factor the linear values are multiplied by, in float as both the C++ and the GLSL use it.
    float scale() const { return float(std::exp2(exposure)); }
    bool operator==(const DisplaySettings& o) const { return exposure == o.exposure && transform == o.transform; }
    bool operator!=(const DisplaySettings& o) const { return !(*this == o); }
};

// Why an exposure cannot be used ("must be in [-16, 16] stops, got 40"), or none; NaN and infinities are
// refused. Every front end words it with its field: `--exposure: ...`, `display.exposure: ...`, `exposure: ...`.
inline std::optional<std::string> exposureProblem(double stops) {
    static_assert(kMinExposure == -16.0 && kMaxExposure == 16.0, "the message below names both");
    if (stops >= kMinExposure && stops <= kMaxExposure) return std::nullopt;
    char got[32];
    std::snprintf(got, sizeof got, "%g", stops);
    return "must be in [-16, 16] stops, got " + std::string(got);
}

// "filmic, +1.5 stops", "standard, -2 stops", "filmic": how captions and status lines name a display that is
// not Standard; empty for Standard.
inline std::string describe(const DisplaySettings& d) {
    if (d.isStandard()) return "";
    std::string text = toString(d.transform);
    if (d.exposure != 0.0) {
        char stops[32];
        std::snprintf(stops, sizeof stops, ", %+.3g stops", d.exposure);
        text += stops;
    }
    return text;
}

}  // namespace shadelab
