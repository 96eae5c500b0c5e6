// ViewerState: everything the viewer's panels edit, as plain data, and the actions that change
// it. The GUI, the --script automation and the unit tests all call these same functions; drawing reads
// the state and never writes it. Actions that change what a renderer sees bump `revision` (and, unless only
// the rasterizer sees it, `referenceRevision`).
#pragma once

#include "app/material_presets.h"
#include "app/orbit_camera.h"
#include "app/view_mode.h"
#include "image/encode.h"
#include "probe/probe.h"
#include "scene/object_ref.h"
#include "scene/scene.h"
#include "trace/path/path_settings.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

namespace shadelab::app {

struct ProbeState {
    bool active = false;
    int x = 0, y = 0;      // pixel of the rendered image, row 0 at the top: where it was set, then where the
                           // anchored point projects
    ProbeAnchor anchor;    // set from the first probe at the pixel; the probe then follows the point
    bool rayTree = false;  // draw the Whitted ray tree of the probed pixel in the view (key T)
};

struct ViewerState {
    Scene scene;                            // what both renderers draw and what Save writes
    std::string scenePath;                  // the file it was opened from; empty for none
    std::vector<std::string> loadWarnings;  // what loading it warned about (ignored features), for the panel
    Camera fileCamera;                      // the scene file's camera, restored by resetCamera (key R)
    OrbitCamera orbit;                      // scene.camera as orbit parameters; written back on every move
    ViewMode mode = ViewMode::Raster;
    trace::PathPart globalPart = trace::PathPart::All;  // what Global mode shows: all, direct or indirect light
    bool globalDenoise = true;  // the Global modes show the denoised preview (key D: the raw estimate)
    Encoding encoding = Encoding::Srgb;
    uint32_t selected = 0;  // coverage id of the selected object (scene/coverage.h), 0 = none
    ProbeState probe;
    // The wipes of Split and of Local | Global, fractions of the image width from the left; unset until first
    // moved, when a wipe sits in the middle of what the panel leaves visible (wipePosition).
    std::optional<float> splitPosition, globalSplitPosition;
    int heatGain = 16;                   // Difference mode amplification (compare_report.h)
    uint64_t revision = 1;               // bumped by every change a renderer can see
    uint64_t referenceRevision = 1;      // bumped by every change the tracer can see (not scene.raster)
    uint64_t geometryRevision = 1;       // bumped when the meshes change (a new scene)
    uint64_t editRevision = 1;           // bumped by every change but the camera's: what undo steps over
    std::optional<Scene> beforeFurnace;  // the scene before the white furnace, while it is on
};

ViewerState makeViewerState(Scene scene, std::string path);
// Replaces the scene (drag and drop, Open): camera, selection and probe are reset; the view mode is kept.
void openScene(ViewerState& state, Scene scene, std::string path);
void markChanged(ViewerState& state);
// A change only the rasterizer sees (scene.raster): the reference keeps running.
void markRasterChanged(ViewerState& state);
// A camera move (orbit, pan, zoom, F, R): both renderers redraw, but it is navigation, not an edit, so
// undo does not step over it (undo_history.h).
void markCameraChanged(ViewerState& state);

// --- objects, by coverage id (scene/object_ref.h) ---
// A mesh's material is its first part's; setting it writes the changed fields into the mesh's override
// (so a save keeps them) and applies them to every part.
Material objectMaterial(const Scene& scene, uint32_t id);
bool setObjectMaterial(ViewerState& state, uint32_t id, const Material& m);

void select(ViewerState& state, uint32_t id);
bool setShininess(ViewerState& state, uint32_t id, float s);  // clamped to [0, kMaxShininess]
bool applyPreset(ViewerState& state, uint32_t id, const MaterialPreset& preset);

// --- lighting model and terms (Term, termEnabled and the names: scene/terms.h) ---
void setTerm(ViewerState& state, Term t, bool on);
void toggleTerm(ViewerState& state, Term t);
// The lecture's progression: step 0 no illumination (every term off: each object's unlit colour, docs/lighting.md),
// 1 ambient, 2 +diffuse, 3 +specular, 4 +shadows, 5 +reflections.
inline constexpr int kProgressionSteps = 5;  // the last step; the first is 0
Terms progressionTerms(int step);            // step clamped to [0, 5]
void applyProgression(ViewerState& state, int step);
int progressionStep(const Terms& terms);  // 0..5 when the terms are exactly a step, else -1
void setModel(ViewerState& state, ShadingModel model);
// Energy-normalised Phong / Blinn-Phong lobes (design.md §7).
void setNormalized(ViewerState& state, bool normalized);
// Switches the model and converts shininess so highlights keep their size (specular_lobe.h rule):
// to Blinn-Phong s -> equivalentBlinnExponent(s), to Phong the inverse. Only the selected object, or every
// object when `allObjects` or nothing is selected. No-op on s when the model already is `model`.
void switchModelKeepingHighlights(ViewerState& state, ShadingModel model, bool allObjects);

// The white furnace (scene/white_furnace.h): on saves the scene and replaces it with its furnace version; off
// restores it (keeping the camera, model and `normalized` changed meanwhile). Edits made in the furnace are
// dropped when it is turned off. Opening a scene leaves it.
void setWhiteFurnace(ViewerState& state, bool on);
// pbr's image-based lighting (scene/environment.h; nullopt: none) and multiple-scattering compensation.
void setEnvironment(ViewerState& state, std::optional<Environment> environment);
void setEnergyCompensation(ViewerState& state, bool on);
inline bool whiteFurnaceOn(const ViewerState& state) { return state.beforeFurnace.has_value(); }

// --- rasterizer settings (scene.raster; the tracer ignores them) ---
// Sets all of them, each brought into the scene file's range (raster_settings.h): a shadow-map size <= 0 is
// auto, others are clamped to [kMinShadowMapSize, kMaxShadowMapSize]; biases to [0, kMaxShadowBias] (NaN: 0);
// the cube size to [kMinReflectionCubeSize, kMaxReflectionCubeSize].
void setRasterSettings(ViewerState& state, const RasterSettings& raster);

// --- lights ---
void setAmbient(ViewerState& state, const glm::vec3& Ia);
// Adds a light above and in front of the scene (white, intensity 1); -1 when kMaxLights are in use.
int addLight(ViewerState& state, LightType type);
bool removeLight(ViewerState& state, int index);
bool setLight(ViewerState& state, int index, const Light& light);
// Il as a colour whose largest component is 1 times a scalar intensity, as the Lights panel shows it.
struct ColorIntensity {
    glm::vec3 color{1.0f};
    float intensity = 0.0f;
};
ColorIntensity splitIntensity(const glm::vec3& Il);
inline glm::vec3 joinIntensity(const ColorIntensity& c) { return c.color * c.intensity; }

// --- camera ---
void applyOrbit(ViewerState& state, const OrbitCamera& orbit);  // writes scene.camera
void frameAll(ViewerState& state);                              // key F
void resetCamera(ViewerState& state);                           // key R: the scene file's camera
void useCamera(ViewerState& state, const Camera& camera);
// The stage under a model (scene/stage.h); a bare .gltf/.glb opens with it on.
void setStageOn(ViewerState& state, bool on);  // e.g. one of a model's glTF cameras

// --- view ---
void setMode(ViewerState& state, ViewMode mode);
void setGlobalPart(ViewerState& state, trace::PathPart part);
// Whether the Global modes show the path tracer's denoised preview or its raw estimate. A view choice: the path
// tracer keeps running, and the probe and the statistics always read the raw estimate.
void setGlobalDenoise(ViewerState& state, bool on);
void setEncoding(ViewerState& state, Encoding encoding);
// The scene's display (exposure and view transform, image/view_transform.h): the window, screenshots and
// renders show it, and a save keeps it. The exposure is brought into [kMinExposure, kMaxExposure] (NaN: 0).
// An edit undo steps over; no renderer redraws for it.
void setDisplay(ViewerState& state, const DisplaySettings& display);
// The wipe of the current mode (Local | Global's in that mode, else Split's), clamped to [0, 1].
void setSplitPosition(ViewerState& state, float position);
// The current mode's wipe: as set, else `visibleCentre` (the middle of the visible image, same units).
float wipePosition(const ViewerState& state, float visibleCentre);
void setHeatGain(ViewerState& state, int gain);  // clamped to [1, 255]
void setProbe(ViewerState& state, int x, int y);
void clearProbe(ViewerState& state);
void setRayTree(ViewerState& state, bool on);  // the probe's ray tree drawn in the view, or not

}  // namespace shadelab::app
