// ViewMode: what the viewer's image shows, and its one name table: the words of a viewer script's "mode".
// The View panel's capitalised labels are display text, not names.
#pragma once

#include "util/name_table.h"

namespace shadelab::app {

// Raster, the Whitted reference (Traced), the two side by side (Split) or their difference; the path
// tracer's global illumination (Global), or local (raster) | global side by side (LocalGlobal).
enum class ViewMode { Raster, Traced, Split, Difference, Global, LocalGlobal };

inline constexpr EnumName<ViewMode> kViewModeNames[] = {
    {ViewMode::Raster, "raster"},         {ViewMode::Traced, "traced"}, {ViewMode::Split, "split"},
    {ViewMode::Difference, "difference"}, {ViewMode::Global, "global"}, {ViewMode::LocalGlobal, "local-global"},
};

inline bool isGlobal(ViewMode m) { return m == ViewMode::Global || m == ViewMode::LocalGlobal; }
// The two modes with a wipe between two images, each with a position of its own (viewer_state.h).
inline bool hasWipe(ViewMode m) { return m == ViewMode::Split || m == ViewMode::LocalGlobal; }

inline const char* toString(ViewMode m) { return nameOf(kViewModeNames, m); }
inline std::optional<ViewMode> parseViewMode(std::string_view name) { return lookupName(kViewModeNames, name); }

}  // namespace shadelab::app
