// ViewerState actions: each edits the plain state and marks what the renderers must redo.
#include "app/viewer_state.h"

#include "app/specular_lobe.h"
#include "scene/coverage.h"
#include "scene/scene_load.h"
#include "scene/stage.h"
#include "scene/white_furnace.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace shadelab::app {
namespace {

Material* sphereOrPlaneMaterial(Scene& scene, const ObjectRef& r) {
    if (r.kind == ObjectKind::Sphere) return &scene.spheres[r.index].material;
    if (r.kind == ObjectKind::Plane) return &scene.planes[r.index].material;
    return nullptr;
}

// Writes the fields of `m` that differ from `before` into the mesh's override and applies it to every part.
void setMeshMaterial(Mesh& mesh, const Material& before, const Material& m) {
    MaterialOverride& o = mesh.material;
    if (m.ma != before.ma) o.ma = m.ma;
    if (m.md != before.md) o.md = m.md;
    if (m.ms != before.ms) o.ms = m.ms;
    if (m.s != before.s) o.s = m.s;
    if (m.kr != before.kr) o.kr = m.kr;
    if (m.kt != before.kt) o.kt = m.kt;
    if (m.ior != before.ior) o.ior = m.ior;
    if (m.baseColor != before.baseColor) o.baseColor = m.baseColor;
    if (m.metallic != before.metallic) o.metallic = m.metallic;
    if (m.roughness != before.roughness) o.roughness = m.roughness;
    if (m.emission != before.emission) o.emission = m.emission;
    if (m.model != before.model) o.model = m.model;  // back to the scene's model too
    for (int i = 0; i < kDisneyFieldCount; ++i) {
        const float DisneyParams::*field = kDisneyFields[i].member;
        if (m.disney.*field != before.disney.*field) o.disney.value[i] = m.disney.*field;
    }
    if (m.specular.factor != before.specular.factor) o.specular.factor = m.specular.factor;
    if (m.specular.color != before.specular.color) o.specular.color = m.specular.color;
    if (m.sheen.color != before.sheen.color) o.sheen.color = m.sheen.color;
    if (m.sheen.roughness != before.sheen.roughness) o.sheen.roughness = m.sheen.roughness;
    if (m.anisotropy.strength != before.anisotropy.strength) o.anisotropy.strength = m.anisotropy.strength;
    if (m.anisotropy.rotation != before.anisotropy.rotation) o.anisotropy.rotation = m.anisotropy.rotation;
    if (m.transmission.factor != before.transmission.factor) o.transmission.factor = m.transmission.factor;
    if (m.volume.thickness != before.volume.thickness) o.volume.thickness = m.volume.thickness;
    if (m.volume.attenuationDistance != before.volume.attenuationDistance)
        o.volume.attenuationDistance = m.volume.attenuationDistance;
    if (m.volume.attenuationColor != before.volume.attenuationColor)
        o.volume.attenuationColor = m.volume.attenuationColor;
    for (int i = 0; i < ClearcoatOverride::kCount; ++i) {
        const float Clearcoat::*field = kClearcoatFields[i].member;
        if (m.clearcoat.*field != before.clearcoat.*field) o.clearcoat.value[i] = m.clearcoat.*field;
    }
    for (MeshPart& p : mesh.parts) {
        o.applyTo(p.material);
        p.material.model = o.model;
    }
}

}  // namespace

ViewerState makeViewerState(Scene scene, std::string path) {
    ViewerState s;
    openScene(s, std::move(scene), std::move(path));
    return s;
}

void openScene(ViewerState& state, Scene scene, std::string path) {
    // A bare model opens on the stage (scene/stage.h): a floor, a soft background and shadows.
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".gltf" || ext == ".glb") setStage(scene, true);
    state.scene = std::move(scene);
    state.scenePath = std::move(path);
    // R returns to the file's camera: a scene file's own, or a bare model's first glTF camera.
    state.fileCamera = state.scene.modelCameras.empty() ? state.scene.camera : state.scene.modelCameras.front();
    state.orbit = orbitFromCamera(state.scene.camera);
    state.selected = 0;
    state.probe = ProbeState{};
    state.beforeFurnace.reset();
    ++state.geometryRevision;
    markChanged(state);
}

void markChanged(ViewerState& state) {
    ++state.revision;
    ++state.referenceRevision;
    ++state.editRevision;
}

void markRasterChanged(ViewerState& state) {
    ++state.revision;
    ++state.editRevision;
}

void markCameraChanged(ViewerState& state) {
    ++state.revision;
    ++state.referenceRevision;
}

Material objectMaterial(const Scene& scene, uint32_t id) {
    const ObjectRef r = objectRef(scene, id);
    if (r.kind == ObjectKind::Sphere) return scene.spheres[r.index].material;
    if (r.kind == ObjectKind::Plane) return scene.planes[r.index].material;
    if (r.kind == ObjectKind::Mesh) {
        const Mesh& mesh = scene.meshes[r.index];
        if (!mesh.parts.empty()) return mesh.parts.front().material;
        Material m;
        m.derived = kPhongFields | kPbrFields;  // as a glTF part's: the override gives, the rest derives
        mesh.material.applyTo(m);
        return m;
    }
    return Material{};
}

bool setObjectMaterial(ViewerState& state, uint32_t id, const Material& m) {
    const ObjectRef r = objectRef(state.scene, id);
    if (r.kind == ObjectKind::None) return false;
    if (Material* dst = sphereOrPlaneMaterial(state.scene, r)) {
        // The edited fields count as given; what was derived from them follows (deriveFields).
        const Material before = *dst;
        *dst = m;
        deriveFields(*dst, editedFields(before, m));
    } else
        setMeshMaterial(state.scene.meshes[r.index], objectMaterial(state.scene, id), m);
    markChanged(state);
    return true;
}

void select(ViewerState& state, uint32_t id) {
    state.selected = objectRef(state.scene, id).kind == ObjectKind::None ? 0 : id;
}

bool setShininess(ViewerState& state, uint32_t id, float s) {
    Material m = objectMaterial(state.scene, id);
    m.s = std::clamp(s, 0.0f, kMaxShininess);
    return setObjectMaterial(state, id, m);
}

bool applyPreset(ViewerState& state, uint32_t id, const MaterialPreset& preset) {
    return setObjectMaterial(state, id, withPreset(objectMaterial(state.scene, id), preset));
}

void setTerm(ViewerState& state, Term t, bool on) {
    termFlag(state.scene.terms, t) = on;
    markChanged(state);
}

void toggleTerm(ViewerState& state, Term t) { setTerm(state, t, !termEnabled(state.scene.terms, t)); }

Terms progressionTerms(int step) {
    step = std::clamp(step, 0, kProgressionSteps);
    return Terms{step >= 1, step >= 2, step >= 3, step >= 4, step >= 5};
}

void applyProgression(ViewerState& state, int step) {
    state.scene.terms = progressionTerms(step);
    markChanged(state);
}

int progressionStep(const Terms& terms) {
    for (int step = 0; step <= kProgressionSteps; ++step) {
        const Terms p = progressionTerms(step);
        if (p.ambient == terms.ambient && p.diffuse == terms.diffuse && p.specular == terms.specular &&
            p.shadows == terms.shadows && p.reflections == terms.reflections)
            return step;
    }
    return -1;
}

void setModel(ViewerState& state, ShadingModel model) {
    state.scene.model = model;
    markChanged(state);
}

void setNormalized(ViewerState& state, bool normalized) {
    state.scene.normalized = normalized;
    markChanged(state);
}

void switchModelKeepingHighlights(ViewerState& state, ShadingModel model, bool allObjects) {
    // Only Phong ↔ Blinn-Phong have equivalent exponents; pbr and disney read roughness, not s.
    const bool lecture = !isPhysicallyBased(model) && !isPhysicallyBased(state.scene.model);
    if (lecture && state.scene.model != model) {
        const bool all = allObjects || state.selected == 0;
        for (uint32_t id = 1; id <= objectCount(state.scene); ++id) {
            if (!all && id != state.selected) continue;
            const float s = objectMaterial(state.scene, id).s;
            setShininess(state, id,
                         model == ShadingModel::BlinnPhong ? equivalentBlinnExponent(s) : equivalentPhongExponent(s));
        }
    }
    setModel(state, model);
}

void setWhiteFurnace(ViewerState& state, bool on) {
    if (on == whiteFurnaceOn(state)) return;
    if (on) {
        state.beforeFurnace = state.scene;
        state.scene = whiteFurnaceScene(state.scene);
    } else {
        state.scene = leaveWhiteFurnace(*state.beforeFurnace, state.scene);
        state.beforeFurnace.reset();
    }
    markChanged(state);
}

void setRasterSettings(ViewerState& state, const RasterSettings& raster) {
    auto bias = [](float b) { return b >= 0.0f ? std::min(b, kMaxShadowBias) : 0.0f; };
    RasterSettings& r = state.scene.raster;
    r.shadowMapSize =
        raster.shadowMapSize <= 0 ? 0 : std::clamp(raster.shadowMapSize, kMinShadowMapSize, kMaxShadowMapSize);
    r.depthBias = bias(raster.depthBias);
    r.normalBias = bias(raster.normalBias);
    r.pcf = raster.pcf;
    r.reflectionCubeSize = std::clamp(raster.reflectionCubeSize, kMinReflectionCubeSize, kMaxReflectionCubeSize);
    r.movingPreview = raster.movingPreview;
    markRasterChanged(state);  // the tracer has no shadow maps or cubes: the reference keeps running
}

void setAmbient(ViewerState& state, const glm::vec3& Ia) {
    state.scene.ambient = glm::max(Ia, glm::vec3(0.0f));
    markChanged(state);
}

int addLight(ViewerState& state, LightType type) {
    Scene& scene = state.scene;
    if (scene.lights.size() >= size_t(kMaxLights)) return -1;
    const Bounds b = sceneBounds(scene);
    const glm::vec3 centre = b.empty() ? scene.camera.target : 0.5f * (b.lo + b.hi);
    const float radius = b.empty() ? 1.0f : std::max(0.5f * glm::length(b.hi - b.lo), 1e-3f);
    glm::vec3 toEye = scene.camera.position - centre;
    toEye = glm::length(toEye) > 0.0f ? glm::normalize(toEye) : glm::vec3(0.0f, 0.0f, 1.0f);
    const glm::vec3 up = glm::normalize(scene.camera.up);
    Light l;
    l.type = type;
    l.name = "light " + std::to_string(scene.lights.size() + 1);
    l.position = centre + 2.0f * radius * glm::normalize(toEye + up);
    l.direction = glm::normalize(centre - l.position);
    l.color = glm::vec3(1.0f);
    scene.lights.push_back(l);
    markChanged(state);
    return int(scene.lights.size()) - 1;
}

bool removeLight(ViewerState& state, int index) {
    if (index < 0 || size_t(index) >= state.scene.lights.size()) return false;
    state.scene.lights.erase(state.scene.lights.begin() + index);
    markChanged(state);
    return true;
}

bool setLight(ViewerState& state, int index, const Light& light) {
    if (index < 0 || size_t(index) >= state.scene.lights.size()) return false;
    state.scene.lights[size_t(index)] = light;
    markChanged(state);
    return true;
}

ColorIntensity splitIntensity(const glm::vec3& Il) {
    const float m = std::max({Il.r, Il.g, Il.b});
    if (!(m > 0.0f)) return ColorIntensity{glm::vec3(1.0f), 0.0f};
    return ColorIntensity{Il / m, m};
}

void applyOrbit(ViewerState& state, const OrbitCamera& orbit) {
    state.orbit = orbit;
    state.scene.camera = cameraFromOrbit(orbit);
    markCameraChanged(state);
}

void setEnvironment(ViewerState& state, std::optional<Environment> environment) {
    state.scene.environment = std::move(environment);
    markChanged(state);
}

void setEnergyCompensation(ViewerState& state, bool on) {
    state.scene.energyCompensation = on;
    markChanged(state);
}

void setStageOn(ViewerState& state, bool on) {
    if (on == hasStage(state.scene)) return;
    setStage(state.scene, on);
    markChanged(state);
}

void useCamera(ViewerState& state, const Camera& camera) {
    state.scene.camera = camera;
    state.orbit = orbitFromCamera(camera);
    markCameraChanged(state);
}

void frameAll(ViewerState& state) {
    const Bounds b = sceneBounds(state.scene);
    if (b.empty()) return;  // planes only: nothing bounded to frame
    Camera c = frameBounds(b, state.scene.camera.fovY);
    state.scene.camera = c;
    state.orbit = orbitFromCamera(c);
    markCameraChanged(state);
}

void resetCamera(ViewerState& state) {
    state.scene.camera = state.fileCamera;
    state.orbit = orbitFromCamera(state.fileCamera);
    markCameraChanged(state);
}

void setMode(ViewerState& state, ViewMode mode) { state.mode = mode; }

void setGlobalPart(ViewerState& state, trace::PathPart part) { state.globalPart = part; }

void setGlobalDenoise(ViewerState& state, bool on) { state.globalDenoise = on; }

void setEncoding(ViewerState& state, Encoding encoding) { state.encoding = encoding; }

void setDisplay(ViewerState& state, const DisplaySettings& display) {
    DisplaySettings d = display;
    d.exposure = std::isnan(d.exposure) ? 0.0 : std::clamp(d.exposure, kMinExposure, kMaxExposure);
    if (d == state.scene.display) return;
    state.scene.display = d;
    ++state.editRevision;
}

void setSplitPosition(ViewerState& state, float position) {
    (state.mode == ViewMode::LocalGlobal ? state.globalSplitPosition : state.splitPosition) =
        std::clamp(std::isnan(position) ? 0.5f : position, 0.0f, 1.0f);
}

float wipePosition(const ViewerState& state, float visibleCentre) {
    const std::optional<float>& set =
        state.mode == ViewMode::LocalGlobal ? state.globalSplitPosition : state.splitPosition;
    return set.value_or(std::clamp(visibleCentre, 0.0f, 1.0f));
}

void setHeatGain(ViewerState& state, int gain) { state.heatGain = std::clamp(gain, 1, 255); }

void setProbe(ViewerState& state, int x, int y) {
    state.probe.active = true;
    state.probe.x = x;
    state.probe.y = y;
    state.probe.anchor = ProbeAnchor{};  // anchored again by the first probe at this pixel
}

void clearProbe(ViewerState& state) { state.probe.active = false; }

void setRayTree(ViewerState& state, bool on) { state.probe.rayTree = on; }

}  // namespace shadelab::app
