// Helpers the viewer's state, probe and script tests share (app_state_test.cpp and its siblings).
#pragma once

#include "app/viewer_state.h"
#include "scene/scene_load.h"
#include "scene/view.h"
#include "test_output.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace shadelab::test {

inline app::ViewerState defaultState() {
    const std::string path = sourcePath("assets/scenes/default.json");
    return app::makeViewerState(loadScene(path), path);
}

inline uint32_t idOf(const app::ViewerState& s, const std::string& name) {
    auto id = app::findObject(s.scene, name);
    EXPECT_TRUE(id.has_value()) << name;
    return id.value_or(0);
}

// Projects a world point to the pixel that contains it in a width x height image.
inline glm::ivec2 pixelOf(const Scene& scene, int width, int height, const glm::vec3& p) {
    const ViewSetup v = makeViewSetup(scene, width, height);
    const glm::vec4 clip = v.viewProj * glm::vec4(p, 1.0f);
    const float x = (clip.x / clip.w * 0.5f + 0.5f) * float(width);
    const float y = (1.0f - (clip.y / clip.w * 0.5f + 0.5f)) * float(height);
    return {int(std::floor(x)), int(std::floor(y))};
}

}  // namespace shadelab::test
