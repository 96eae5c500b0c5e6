// RasterRenderer: Scene → linear float image through OpenGL (design.md §1, §2). Meshes are rasterized;
// spheres and planes are ray-cast impostors using the tracer's own intersection code, so silhouettes
// and normals are exact. Shadows (shadow maps) and planar mirrors follow the scene's term switches.
#pragma once

#include "gl/program.h"
#include "image/image.h"
#include "raster/band.h"
#include "raster/color_programs.h"
#include "raster/environment_cubes.h"
#include "raster/geometry_buffers.h"
#include "raster/ibl_textures.h"
#include "raster/mesh_textures.h"
#include "raster/partial_redraw.h"
#include "raster/raster_limits.h"
#include "raster/redraw_plan.h"
#include "raster/render_target.h"
#include "raster/shader_variant.h"
#include "raster/shadow_maps.h"
#include "raster/triangle_batches.h"
#include "scene/scene.h"

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

namespace shadelab::raster {

struct FrameBlock;

// When a renderer compiles its colour programs. AtStart: two variants that between them hold every line of the
// shaders (no shadows; every optional block), so a shader error surfaces in the constructor, before anything is
// drawn; what the viewer wants when it starts or reloads its shaders (it keeps the running programs on an
// error). OnFirstUse: only the programs a draw needs, when it needs them; what a one-shot render wants: the
// headless 2CylinderEngine render skips 12 programs it never draws with (about 100 ms and 8 MiB on llvmpipe),
// and a shader error surfaces at the first draw instead, with the same message.
enum class ProgramCheck { AtStart, OnFirstUse };

class RasterRenderer {
public:
    // Needs a current GL 3.3 core or OpenGL ES 3.0 context, whose dialect (gl::currentContextDialect) the
    // programs are compiled in, whatever `shaders` says. Throws InputError on shader errors (AtStart: here).
    explicit RasterRenderer(const gl::ShaderLibrary& shaders = gl::ShaderLibrary(),
                            ProgramCheck check = ProgramCheck::AtStart);
    RasterRenderer(const RasterRenderer&) = delete;  // its program sets point at shaders_
    RasterRenderer& operator=(const RasterRenderer&) = delete;

    // Uploads every mesh part and the textures its material has (a texture a later material edit binds is
    // uploaded at its first draw). Call again when geometry changes; materials are read at draw time.
    void uploadMeshes(const Scene& scene);

    // Draws the scene (or one band of it) into the internal target, with coverage ids when asked. The
    // target is width x band rows. uploadMeshes must have seen the scene's current geometry. With
    // scene.terms.shadows, shadow maps are re-rendered only when lights, casters or scene.raster change; with
    // scene.terms.reflections, each mirror plane (kr > 0) gets a mirrored pass of the same band.
    // `jitter` moves every sample off its pixel centre by that many pixels (x right, y down), for the viewer's
    // accumulated supersampling (sample a of a k-grid sits at (a + 0.5)/k - 0.5); {0, 0} is the centre.
    void draw(const Scene& scene, int width, int height, bool withCoverage = false, Band band = {},
              glm::vec2 jitter = glm::vec2(0.0f));

    const RenderTarget& target() const { return target_; }
    // The pixels of target() (GL row order) where object `id`'s coverage can lie: its bounds projected with the
    // camera of the last draw into target() (PartialRedraw::objectsRect), empty when it is off screen, all of them
    // for a plane or after a draw of a band. The display pass outlines a selected object only there.
    PixelRect objectRect(const Scene& scene, uint32_t id) const;

    // The viewer's partial redraw (docs/viewer.md, "Partial redraw"), off by default. When on, a draw of the whole
    // image at the pixel centres with coverage, after one whose inputs differed only in some objects' materials,
    // redraws only the pixels of those objects (and of objects whose environment cube changed with them); the image is
    // bit for bit what a full draw gives (redraw_plan.h). A draw with nothing changed then draws nothing.
    void setPartialRedraw(bool on) { partial_.setEnabled(on); }
    // Whether target() keeps an alpha channel (the default): renders that read only the colour drop it and
    // draw into RGB32F where the GL allows (RenderTarget::resize), 8 MiB less at 1920x1080.
    void setTargetAlpha(bool on) { targetAlpha_ = on; }
    // Whether the mesh passes draw in flushed batches where that pays (TriangleBatches::sizeForCurrentContext):
    // one-shot renders (the CLI, Python) turn it on; a window's frames leave it off, since llvmpipe's raster
    // threads woken hundreds of times a frame beside the X server made the viewer's 2CylinderEngine frame
    // 144 → 199 ms, while a one-shot render of it got faster and 22 MiB smaller.
    void setTriangleBatches(bool on) { batchTriangles_ = on ? TriangleBatches::sizeForCurrentContext() : 0; }
    bool targetAlpha() const { return targetAlpha_; }
    // The next draw is a full one (a benchmark's forced redraw).
    void invalidate() { partial_.forget(); }
    // One jittered sample of the whole image (see draw), into a colour-only target of its own, which it
    // returns: target() keeps the centre sample and its coverage.
    const RenderTarget& drawSample(const Scene& scene, int width, int height, glm::vec2 jitter);

    // What the last draw did, for benches and tests.
    struct DrawReport {
        bool partial = false;  // only some objects were redrawn (partialIds of them, 0: nothing changed)
        int partialIds = 0;
        bool shadowMaps = false;    // the shadow maps were re-rendered
        bool environments = false;  // the environment cubes were re-rendered
    };
    const DrawReport& lastDraw() const { return report_; }

    // Shadow-map layers rendered for the last shadowed draw (0: none needed), for reports and benches.
    int shadowLayers() const { return shadows_.layers(); }

private:
    // What one run of the colour passes leaves out or changes: the mirror pass skips its plane and reverses
    // winding; an environment face skips its own object and adds no environment reflections (one bounce).
    struct PassOptions {
        int skipPlane = -1, skipSphere = -1, skipRange = -1;
        bool mirrored = false;
        bool reflections = true;  // planar mirrors and environment cubes looked up (the primary pass only)
        const std::vector<uint32_t>* only = nullptr;  // a partial redraw: only objects with these coverage ids
    };
    // model: shading::SL_MODEL_*; normalized: Scene::normalized.
    void setMaterial(const gl::Program& p, const Material& m, uint32_t objectId, int model, bool normalized) const;
    // plain, environment: ColorPrograms::Kind values.
    const gl::Program& objectProgram(const ColorPrograms& programs, int plain, int environment, int sphere, int range,
                                     const PassOptions& options) const;
    void uploadFrame(const FrameBlock& frame) const;
    void drawPasses(const Scene& scene, const FrameBlock& frame, const PassOptions& options) const;
    // One mesh part (ranges_[k]) with its material, through drawPasses' state, in the pass's batches.
    void drawRange(const Scene& scene, const PassOptions& options, size_t k, TriangleBatches& batches) const;
    void prepareShadows(const Scene& scene, int width, int height);
    void prepareEnvironments(const Scene& scene, const FrameBlock& frame);
    void drawBackdrop(const FrameBlock& frame) const;
    void render(RenderTarget& target, const Scene& scene, int width, int height, bool withCoverage, Band band,
                glm::vec2 jitter, bool reusable);
    void redrawPart(const Scene& scene, const FrameBlock& frame, const std::vector<uint32_t>& ids);

    const gl::ShaderLibrary shaders_;
    ColorProgramCache programs_;  // after shaders_, which it compiles from
    ShadowMaps shadows_;
    std::vector<float> shadowKey_;  // what the current shadow maps were rendered from
    EnvironmentCubes environments_;
    std::vector<EnvironmentProbe> probes_;   // this draw's reflective spheres and mesh parts, cube i for probe i
    std::optional<DrawKey> environmentKey_;  // what the cubes were rendered from
    std::vector<RenderTarget> mirrorTargets_;
    std::vector<int> mirrorOfPlane_;  // per plane: index into mirrorTargets_ for this band, or -1
    mutable MeshTextures textures_;   // base-colour textures, uploaded on a part's first draw
    IblTextures ibl_;                 // the environment's prefiltered atlas and the DFG table
    gl::Program backdrop_;            // an environment map behind everything (environment_backdrop.frag)
    gl::Buffer frameUbo_;
    GeometryBuffers geometry_;
    RenderTarget target_;
    RenderTarget sampleTarget_;                // drawSample's
    PartialRedraw partial_;                    // what target_ holds, when a partial redraw may start from it
    std::optional<glm::mat4> targetViewProj_;  // the camera of target_'s last whole draw (objectRect)
    size_t batchTriangles_ = 0;                // the mesh passes' batches (setTriangleBatches)
    bool targetAlpha_ = true;
    bool environmentsRendered_ = false;
    DrawReport report_;
};

// Number of bands that keeps the RGBA32F target near `maxTargetBytes` (1 for small images).
int bandCount(int width, int height, size_t maxTargetBytes = size_t(32) << 20);

// Convenience for one-shot renders: draw, then read colour (and coverage when asked).
struct RasterOutput {
    ImageF color;
    std::vector<uint32_t> coverage;  // empty unless requested
};
RasterOutput renderRaster(RasterRenderer& r, const Scene& scene, int width, int height, bool withCoverage);

}  // namespace shadelab::raster
