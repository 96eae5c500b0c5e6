// The selected object's outline in the display pass (app/image_view.h): drawn only inside a scissor around the
// object's bounds (RasterRenderer::objectRect), the window's pixels must be exactly those of the outline drawn
// everywhere, for every object of the lecture scene (spheres, the floor) seen whole and half off the frame, in a
// window rectangle that scales the image by a non-integer factor. Negative control: bounds that miss the object
// lose the outline, and the comparison must see it.
#include "app/image_view.h"
#include "gl/objects.h"
#include "gl_fixture.h"
#include "image/png.h"
#include "raster/raster_renderer.h"
#include "scene/coverage.h"
#include "scene/scene_load.h"
#include "test_output.h"
#include "trace/trace_test_util.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

using namespace shadelab;

namespace {

constexpr int kImageW = 320, kImageH = 180;    // the raster image
constexpr int kWindowW = 440, kWindowH = 260;  // the "window" it is shown in
const app::ImageRect kRect{17, 9, 403, 227};   // where: about 1.26x the image, not a whole factor

class ImageViewOutline : public test::GlTest {};

// The window's RGBA bytes after the display pass of `r`'s image with `selected` outlined.
std::vector<uint8_t> show(const app::ImageView& view, const raster::RasterRenderer& r, uint32_t selected,
                          std::optional<app::ImageRect> bounds) {
    gl::Texture color = gl::Texture::create();
    glBindTexture(GL_TEXTURE_2D, color.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kWindowW, kWindowH, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glBindTexture(GL_TEXTURE_2D, 0);
    gl::Framebuffer fbo = gl::Framebuffer::create();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
    glClearColor(0.2f, 0.3f, 0.4f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    app::ImageViewInputs in;
    in.raster = r.target().colorTexture();
    in.imageWidth = r.target().width();
    in.imageHeight = r.target().height();
    in.coverage = r.target().coverageTexture();
    in.selected = selected;
    in.selectedBounds = bounds;
    view.draw(kRect, in);
    std::vector<uint8_t> out(size_t(kWindowW) * kWindowH * 4);
    glReadPixels(0, 0, kWindowW, kWindowH, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return out;
}

size_t differingPixels(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    size_t n = 0;
    for (size_t i = 0; i + 4 <= a.size(); i += 4) n += std::memcmp(&a[i], &b[i], 4) != 0;
    return n;
}

void writeEvidence(const std::string& name, const std::vector<uint8_t>& rgba) {
    Image8 img;
    img.width = kWindowW;
    img.height = kWindowH;
    img.channels = 3;
    img.data.resize(size_t(kWindowW) * kWindowH * 3);
    for (int y = 0; y < kWindowH; ++y)  // GL rows bottom first; the PNG's top first
        for (int x = 0; x < kWindowW; ++x)
            for (int c = 0; c < 3; ++c)
                img.data[(size_t(kWindowH - 1 - y) * kWindowW + x) * 3 + c] = rgba[(size_t(y) * kWindowW + x) * 4 + c];
    writePng(test::outputPath(name + ".png"), img);
}

app::ImageRect imageRect(const raster::PixelRect& r) { return app::ImageRect{r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0}; }

TEST_F(ImageViewOutline, TheScissoredOutlineIsTheWholeOutline) {
    for (int view = 0; view < 2; ++view) {
        Scene scene = loadScene(test::sourcePath("assets/scenes/default.json"));
        if (view == 1) {  // closer and turned: the red sphere cut by the frame's left edge
            scene.camera.position = glm::vec3(-1.5f, 1.3f, 5.5f);
            scene.camera.target = glm::vec3(-0.5f, 0.8f, 0.0f);
        }
        raster::RasterRenderer r;
        r.uploadMeshes(scene);
        r.draw(scene, kImageW, kImageH, true);
        std::vector<uint32_t> coverage;
        r.target().readCoverage(coverage);
        const auto visible = [&coverage](uint32_t id) {
            return std::find(coverage.begin(), coverage.end(), id) != coverage.end();
        };
        if (view == 1) {  // the view does what it is for: the red sphere reaches the left edge
            bool atEdge = false;
            for (int y = 0; y < kImageH; ++y)
                atEdge = atEdge || coverage[size_t(y) * kImageW] == sphereCoverageId(scene, 0);
            EXPECT_TRUE(atEdge) << "the second view no longer cuts the red sphere at the frame's edge";
        }
        app::ImageView imageView{gl::ShaderLibrary()};
        const std::vector<uint8_t> none = show(imageView, r, 0, std::nullopt);
        for (size_t i = 0; i < scene.spheres.size() + scene.planes.size(); ++i) {
            const uint32_t id = i < scene.spheres.size() ? sphereCoverageId(scene, i)
                                                         : planeCoverageId(scene, i - scene.spheres.size());
            const std::string name = "outline_view" + std::to_string(view) + "_object" + std::to_string(i);
            const std::vector<uint8_t> everywhere = show(imageView, r, id, std::nullopt);
            const std::vector<uint8_t> scissored = show(imageView, r, id, imageRect(r.objectRect(scene, id)));
            // The outline shows for every object in view (else the comparison below could not fail).
            if (visible(id)) {
                EXPECT_GT(differingPixels(everywhere, none), 0u) << name << ": no outline drawn";
            }
            const size_t diff = differingPixels(scissored, everywhere);
            EXPECT_EQ(diff, 0u) << name << ": the outline inside the object's bounds differs from the whole outline";
            if (diff != 0) {
                writeEvidence(name + "_everywhere", everywhere);
                writeEvidence(name + "_scissored", scissored);
            }
            if (i == 0) {
                // Negative control: bounds beside the object (moved right by their width plus the margin) lose the
                // outline, and the same comparison sees it.
                app::ImageRect beside = imageRect(r.objectRect(scene, id));
                beside.x += beside.width + 8;
                const std::vector<uint8_t> missed = show(imageView, r, id, beside);
                EXPECT_GT(differingPixels(missed, everywhere), 0u)
                    << name << ": bounds beside the object kept the outline";
            }
        }
    }
}

}  // namespace
