// PanelCache: the docked side panel's pixels kept from the last frame that drew them. A frame whose panel draws
// exactly what the last one drew (the same Dear ImGui vertices, indices, commands and clip rectangles, all on the
// font atlas) copies the kept pixels back instead of drawing its widgets and glyphs again: on llvmpipe the panel is
// about 5 ms of a 1280x720 frame, and while the camera orbits or a light is dragged in the image nothing in it
// changes. The panel's pixels depend on nothing else: it is drawn over its own cleared background, and the other
// draw lists (captions, markers, the probe window over the image) must not touch it, or the frame is drawn whole.
// $SHADELAB_PANEL_CACHE: "off" draws every frame whole; "verify" also draws the panel on every frame the cache
// serves and compares the two (the counts go to --stats); "verify-stale" serves the kept pixels even when the panel
// changed, so that the comparison can be seen to fail (a negative control for the tests).
#pragma once

#include "gl/gl_api.h"
#include "gl/objects.h"

#include <cstddef>
#include <cstdint>
#include <vector>

struct ImDrawData;

namespace shadelab::app {

class PanelCache {
public:
    enum class Mode { On, Off, Verify, VerifyStale };
    // The mode $SHADELAB_PANEL_CACHE names (On when unset; an unknown value is On).
    static Mode modeFromEnvironment();

    explicit PanelCache(Mode mode) : mode_(mode) {}

    // Renders `data` into the bound default framebuffer: the lists inside the panel, framebuffer columns
    // [0, panelPixels) of a fbWidth x fbHeight framebuffer, from the kept pixels when they are what it holds (else
    // drawn and kept), then the rest. panelPixels 0 (no docked panel): everything drawn.
    void render(ImDrawData* data, int panelPixels, int fbWidth, int fbHeight);

    struct Counts {
        size_t hits = 0, misses = 0, whole = 0;  // served, drawn and kept, drawn with the rest (not cacheable)
        size_t verified = 0, differing = 0;      // Verify: frames compared, and those whose pixels differed
    };
    const Counts& counts() const { return counts_; }
    Mode mode() const { return mode_; }

private:
    void keep(int width, int height);
    void restore(int width, int height) const;
    std::vector<uint8_t> readPanel(int width, int height) const;

    Mode mode_;
    Counts counts_;
    std::vector<uint8_t> signature_, next_;  // what the kept pixels were drawn from; this frame's
    bool valid_ = false;
    int width_ = 0, height_ = 0;
    gl::Texture texture_;
    gl::Framebuffer fbo_;
};

}  // namespace shadelab::app
