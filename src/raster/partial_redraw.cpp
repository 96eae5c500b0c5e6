// PartialRedraw: the bounds, the depth copy and the merge of a partial redraw.
#include "raster/partial_redraw.h"

#include "raster/raster_limits.h"
#include "scene/coverage.h"
#include "util/check.h"

#include <algorithm>
#include <string>

namespace shadelab::raster {

void PartialRedraw::setEnabled(bool on) {
    enabled_ = on;
    if (!on) last_.reset();
}

PixelRect PartialRedraw::objectsRect(const Scene& scene, const std::vector<DrawRange>& ranges,
                                     const glm::mat4& viewProj, const std::vector<uint32_t>& ids, int w, int h) {
    const auto listed = [&ids](uint32_t id) { return std::find(ids.begin(), ids.end(), id) != ids.end(); };
    PixelRect rect;
    for (const DrawRange& r : ranges)
        if (r.mesh < scene.meshes.size() && listed(meshCoverageId(scene, r.mesh)))
            rect = unite(rect, boxPixelRect(viewProj, r.lo, r.hi, w, h));
    for (size_t i = 0; i < scene.spheres.size(); ++i)
        if (listed(sphereCoverageId(scene, i))) {
            const Sphere& sp = scene.spheres[i];
            rect = unite(
                rect, boxPixelRect(viewProj, sp.center - glm::vec3(sp.radius), sp.center + glm::vec3(sp.radius), w, h));
        }
    for (size_t i = 0; i < scene.planes.size(); ++i)
        if (listed(planeCoverageId(scene, i))) rect = PixelRect{0, 0, w, h};
    return rect;
}

void PartialRedraw::begin(const RenderTarget& image, const PixelRect& rect) {
    redrawn_.resize(image.width(), image.height(), false);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, image.framebuffer());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, redrawn_.framebuffer());
    glBlitFramebuffer(rect.x0, rect.y0, rect.x1, rect.y1, rect.x0, rect.y0, rect.x1, rect.y1, GL_DEPTH_BUFFER_BIT,
                      GL_NEAREST);
    redrawn_.bind();
    glEnable(GL_SCISSOR_TEST);
    glScissor(rect.x0, rect.y0, rect.x1 - rect.x0, rect.y1 - rect.y0);
}

void PartialRedraw::merge(const RenderTarget& image, const std::vector<uint32_t>& ids) {
    SHADELAB_CHECK_LE(ids.size(), kMaxPartialIds);  // partial_merge.frag's u_ids holds no more
    SHADELAB_CHECK(image.hasCoverage());            // the merge picks the objects' pixels by it
    if (!merge_) {
        merge_ = gl::Program::build(shaders_, "fullscreen.vert", "partial_merge.frag");
        mergeFbo_ = gl::Framebuffer::create();
        emptyVao_ = gl::VertexArray::create();
    }
    glBindFramebuffer(GL_FRAMEBUFFER, mergeFbo_.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, image.colorTexture(), 0);
    glViewport(0, 0, image.width(), image.height());
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glUseProgram(merge_.id());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, redrawn_.colorTexture());
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, image.coverageTexture());
    merge_.setSampler("t_partial", 0, gl::Program::Uniform::Required);
    merge_.setSampler("t_coverage", 1, gl::Program::Uniform::Required);
    for (size_t i = 0; i < ids.size(); ++i)
        merge_.set(("u_ids[" + std::to_string(i) + "]").c_str(), ids[i], gl::Program::Uniform::Required);
    merge_.set("u_idCount", int(ids.size()), gl::Program::Uniform::Required);
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glUseProgram(0);
    glDisable(GL_SCISSOR_TEST);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    image.bind();
}

}  // namespace shadelab::raster
