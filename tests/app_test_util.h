// Helpers the viewer's state, probe and script tests share (app_state_test.cpp and its siblings).
#pragma once

#include "app/viewer_state.h"
#include "pixel_of.h"
#include "scene/scene_load.h"
#include "test_output.h"

#include <gtest/gtest.h>

#include <string>

namespace shadelab::test {

inline app::ViewerState defaultState() {
    const std::string path = sourcePath("assets/scenes/default.json");
    return app::makeViewerState(loadScene(path), path);
}

inline uint32_t idOf(const app::ViewerState& s, const std::string& name) {
    auto id = findObject(s.scene, name);
    EXPECT_TRUE(id.has_value()) << name;
    return id.value_or(0);
}

}  // namespace shadelab::test
