// ArrowOverlay: the probe's N, V and per-light L, R, H drawn as labelled 3D arrows over the image
// (shaders/view_arrows.*, depth testing off). Returns where the labels go; the UI draws the text.
#pragma once

#include "app/image_view.h"
#include "gl/program.h"
#include "probe/probe.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace shadelab::app {

struct ArrowLabel {
    std::string text;
    glm::vec2 position;  // framebuffer pixels, y down from the top of the window
    glm::vec3 color;
};

struct Arrow {
    std::string label;
    glm::vec3 direction;  // unit
    glm::vec3 color;      // display colour (sRGB-ish, for the overlay only)
};

// The arrows of a probe: N, V, then L, R, H for each light (labelled L1, R1, H1, ... with two or more lights).
std::vector<Arrow> probeArrows(const ProbeResult& probe);

// One arrow from `base` to `tip` in world units, its label placed at `labelAt` (0 the base, 1 the tip).
struct ArrowSegment {
    glm::vec3 base, tip, color;
    std::string label;
    float labelAt = 1.0f;
    float width = 1.0f;  // times the probe arrows' shaft width
};

class ArrowOverlay {
public:
    explicit ArrowOverlay(const gl::ShaderLibrary& shaders);
    // Draws into `rect` of the window (framebuffer pixels), for an image rendered at renderWidth x
    // renderHeight of `scene`; arrows start at probe.P. `windowHeight` converts label positions to y-down.
    std::vector<ArrowLabel> draw(const Scene& scene, const ProbeResult& probe, int renderWidth, int renderHeight,
                                 const ImageRect& rect, int windowHeight, float pixelScale);
    // Any arrows, seen by the scene's camera. The part of a segment behind the camera is cut away, so a ray
    // from an eye elsewhere draws from where it enters the view.
    std::vector<ArrowLabel> draw(const Scene& scene, const std::vector<ArrowSegment>& segments, int renderWidth,
                                 int renderHeight, const ImageRect& rect, int windowHeight, float pixelScale);

private:
    gl::Program program_;
    gl::VertexArray vao_;
    gl::Buffer vbo_;
};

}  // namespace shadelab::app
