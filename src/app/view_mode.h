// ViewMode: what the viewer's image shows, and its one name table: the words of a viewer script's "mode".
// The View panel's capitalised labels are display text, not names.
#pragma once

#include "util/name_table.h"

namespace shadelab::app {

enum class ViewMode { Raster, Traced, Split, Difference };

inline constexpr EnumName<ViewMode> kViewModeNames[] = {
    {ViewMode::Raster, "raster"},
    {ViewMode::Traced, "traced"},
    {ViewMode::Split, "split"},
    {ViewMode::Difference, "difference"},
};

inline const char* toString(ViewMode m) { return nameOf(kViewModeNames, m); }
inline std::optional<ViewMode> parseViewMode(std::string_view name) { return lookupName(kViewModeNames, name); }

}  // namespace shadelab::app
