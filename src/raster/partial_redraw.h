// PartialRedraw: the viewer's partial redraw (docs/viewer.md, "Partial redraw"). After a draw whose inputs
// differed from the last one only in some objects' materials (redraw_plan.h), the renderer draws just those
// objects again, in the full draw's order, over a copy of the image's depth, so at every pixel one of them owns
// (coverage) the fragment that wins is the one that won in the full draw (LEQUAL keeps the last of equal
// depths, and no later object came nearer); merge() then copies those pixels into the image. The image is bit
// for bit what a full draw gives. This class holds the key of the image it may start from and the GL side of
// the redraw; RasterRenderer runs the passes in between.
#pragma once

#include "gl/objects.h"
#include "gl/program.h"
#include "raster/draw_range.h"
#include "raster/redraw_plan.h"
#include "raster/render_target.h"
#include "scene/scene.h"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <optional>
#include <vector>

namespace shadelab::raster {

class PartialRedraw {
public:
    explicit PartialRedraw(const gl::ShaderLibrary& shaders) : shaders_(shaders) {}

    // Off by default; turning it off forgets the last image.
    void setEnabled(bool on);
    bool enabled() const { return enabled_; }
    // What the image holds, when a partial redraw may start from it; null after forget().
    const DrawKey* last() const { return last_ ? &*last_ : nullptr; }
    void remember(DrawKey key) { last_ = std::move(key); }
    void forget() { last_.reset(); }

    // The pixels the listed objects' bounds can cover in a width x height image (any plane: all of them).
    static PixelRect objectsRect(const Scene& scene, const std::vector<DrawRange>& ranges, const glm::mat4& viewProj,
                                 const std::vector<uint32_t>& ids, int width, int height);
    // Binds a colour target of `image`'s size that holds a copy of its depth inside `rect`, scissored to it.
    void begin(const RenderTarget& image, const PixelRect& rect);
    // Copies the redrawn pixels that `image`'s coverage gives to the listed objects into its colour, inside
    // `rect`; leaves `image` bound, the scissor off, depth test and writes on.
    void merge(const RenderTarget& image, const std::vector<uint32_t>& ids);

private:
    const gl::ShaderLibrary& shaders_;
    bool enabled_ = false;
    std::optional<DrawKey> last_;
    RenderTarget redrawn_;      // the redrawn objects, over a copy of the image's depth
    gl::Program merge_;         // copies their pixels into the image (partial_merge.frag)
    gl::Framebuffer mergeFbo_;  // the image's colour alone
    gl::VertexArray emptyVao_;
};

}  // namespace shadelab::raster
