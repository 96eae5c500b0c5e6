// The viewer in front of a class, without a window: undo and redo (every edit is one step,
// camera moves are not steps and stay where they are, undoing an Open brings the other file back), Save
// never writes scene JSON over a glTF model or another kind of file, and the captions on the image.
#include "app/captions.h"
#include "app/file_list.h"
#include "app/light_markers.h"
#include "app/probe_diagram.h"
#include "app/probe_window_place.h"
#include "app/save_policy.h"
#include "app/undo_history.h"
#include "app/viewer_state.h"
#include "scene/scene_json.h"
#include "scene/scene_load.h"
#include "scene/view.h"
#include "test_output.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

using namespace shadelab;
using namespace shadelab::app;

namespace {

ViewerState stateOf(const std::string& relative) {
    const std::string path = test::sourcePath(relative);
    return makeViewerState(loadScene(path), path);
}

// The scene as Save writes it: equal text is an equal scene, camera included.
std::string saved(const Scene& scene, const std::string& name) {
    const std::string path = test::outputPath(name);
    saveSceneJson(scene, path);
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

TEST(AppUndo, RemovedLightComesBackExactlyAndRedoRemovesItAgain) {
    ViewerState s = stateOf("assets/scenes/default.json");
    UndoHistory history;
    history.reset(s);
    const std::string before = saved(s.scene, "undo_light_before.json");
    const size_t lights = s.scene.lights.size();
    ASSERT_GE(lights, 2u);
    ASSERT_TRUE(removeLight(s, 0));
    EXPECT_TRUE(history.commit(s));
    const std::string removed = saved(s.scene, "undo_light_removed.json");
    EXPECT_NE(removed, before) << "negative control: the removal changed the scene";

    const uint64_t revision = s.revision;
    ASSERT_TRUE(history.undo(s));
    EXPECT_EQ(s.scene.lights.size(), lights);
    EXPECT_EQ(saved(s.scene, "undo_light_undone.json"), before);
    EXPECT_GT(s.revision, revision) << "the renderers must redraw after an undo";
    EXPECT_FALSE(history.undo(s)) << "nothing older than the baseline";

    ASSERT_TRUE(history.redo(s));
    EXPECT_EQ(saved(s.scene, "undo_light_redone.json"), removed);
    EXPECT_FALSE(history.redo(s));
}

TEST(AppUndo, ADragIsOneStepAndCameraMovesAreNotSteps) {
    ViewerState s = stateOf("assets/scenes/default.json");
    UndoHistory history;
    history.reset(s);
    const uint32_t id = *findObject(s.scene, "#1");
    const float s0 = objectMaterial(s.scene, id).s;
    // A slider drag: many changes, one commit when the widget is released.
    for (float v = 10.0f; v <= 200.0f; v += 10.0f) setShininess(s, id, v);
    EXPECT_TRUE(history.commit(s));
    EXPECT_EQ(history.undoSteps(), 1u);
    // An orbit is navigation: no step, and undo leaves the camera where it is.
    OrbitCamera o = s.orbit;
    orbitRotate(o, 0.5f, 0.1f);
    applyOrbit(s, o);
    EXPECT_FALSE(history.commit(s));
    const Camera moved = s.scene.camera;
    ASSERT_TRUE(history.undo(s));
    EXPECT_EQ(objectMaterial(s.scene, id).s, s0);
    EXPECT_EQ(s.scene.camera.position, moved.position);
    EXPECT_EQ(s.scene.camera.target, moved.target);
}

TEST(AppUndo, NewEditDropsRedoAndHistoryIsBounded) {
    ViewerState s = stateOf("assets/scenes/default.json");
    UndoHistory history(4);
    history.reset(s);
    for (int i = 0; i < 6; ++i) {
        setAmbient(s, glm::vec3(0.01f * float(i + 1)));
        history.commit(s);
    }
    EXPECT_EQ(history.undoSteps(), 4u);
    ASSERT_TRUE(history.undo(s));
    EXPECT_EQ(s.scene.ambient, glm::vec3(0.01f * 5.0f));
    EXPECT_EQ(history.redoSteps(), 1u);
    setAmbient(s, glm::vec3(0.5f));
    history.commit(s);
    EXPECT_EQ(history.redoSteps(), 0u) << "a new edit ends the redo list";
}

TEST(AppUndo, UndoingAnOpenBringsTheOtherFileBack) {
    ViewerState s = stateOf("assets/scenes/default.json");
    UndoHistory history;
    history.reset(s);
    const std::string before = saved(s.scene, "undo_open_before.json");
    const uint64_t geometry = s.geometryRevision;
    const std::string torus = test::sourcePath("assets/scenes/torus.json");
    openScene(s, loadScene(torus), torus);
    history.commit(s);
    ASSERT_FALSE(s.scene.meshes.empty());
    ASSERT_TRUE(history.undo(s));
    EXPECT_EQ(s.scenePath, test::sourcePath("assets/scenes/default.json"));
    EXPECT_EQ(saved(s.scene, "undo_open_after.json"), before) << "the file's own camera comes back with it";
    EXPECT_GT(s.geometryRevision, geometry + 1) << "a fresh geometry revision, never an old one";
    ASSERT_TRUE(history.redo(s));
    EXPECT_EQ(s.scenePath, torus);
    EXPECT_FALSE(s.scene.meshes.empty());
}

TEST(AppSave, NeverOverAModelOrAnotherKindOfFile) {
    EXPECT_EQ(saveRefusal("lesson-saved.json"), "");
    EXPECT_EQ(saveRefusal("dir/Scene.JSON"), "");
    for (const char* bad : {"ClearCoatTest.gltf", "engine.GLB", "shot.png", "notes", ""})
        EXPECT_NE(saveRefusal(bad), "") << bad;
    EXPECT_NE(saveRefusal("model.gltf").find("glTF"), std::string::npos);
    const std::string dir = test::outputPath("save_policy_dir.json");
    std::filesystem::create_directories(dir);
    EXPECT_EQ(saveRefusal(dir), "is a folder");
}

// Each wipe keeps its own position, and one never moved sits in the middle of the visible image (so a wipe
// never starts under the projector's panel).
TEST(AppWipes, EachModeHasItsOwnWipeStartingAtTheVisibleCentre) {
    ViewerState s = stateOf("assets/scenes/default.json");
    setMode(s, ViewMode::Split);
    EXPECT_FLOAT_EQ(wipePosition(s, 0.7f), 0.7f);
    setSplitPosition(s, 0.25f);
    EXPECT_FLOAT_EQ(wipePosition(s, 0.7f), 0.25f);
    setMode(s, ViewMode::LocalGlobal);
    EXPECT_FLOAT_EQ(wipePosition(s, 0.7f), 0.7f) << "Local | Global does not inherit Split's wipe";
    setSplitPosition(s, 2.0f);
    EXPECT_FLOAT_EQ(wipePosition(s, 0.7f), 1.0f);
    setMode(s, ViewMode::Split);
    EXPECT_FLOAT_EQ(wipePosition(s, 0.7f), 0.25f);
    EXPECT_TRUE(hasWipe(ViewMode::Split) && hasWipe(ViewMode::LocalGlobal));
    EXPECT_FALSE(hasWipe(ViewMode::Global) || hasWipe(ViewMode::Difference));
}

// Wherever the wipe is, its two labels never overlap and never leave the visible image; a label with no room
// on its side is not drawn. Negative control: the old rule (each label clamped into the visible image) printed
// "raster" over "reference" with the wipe near the panel's edge.
TEST(AppWipes, LabelsNeverCollideWhereverTheWipeIs) {
    EXPECT_STREQ(wipeCaptions(ViewMode::LocalGlobal).left, "local (raster)");
    EXPECT_STREQ(wipeCaptions(ViewMode::LocalGlobal).right, "global (path traced)");
    EXPECT_STREQ(wipeCaptions(ViewMode::Split).right, "reference (Whitted ray tracer)");
    const float visibleLeft = 600.0f, right = 1900.0f, gap = 12.0f, wl = 140.0f, wr = 520.0f;
    int both = 0, oldCollisions = 0;
    for (float wipe = 0.0f; wipe <= 1920.0f; wipe += 5.0f) {
        const WipeLabelPlacement p = placeWipeLabels(visibleLeft, right, wipe, gap, wl, wr);
        if (p.leftShown) {
            EXPECT_GE(p.leftX, visibleLeft) << wipe;
            EXPECT_LE(p.leftX + wl, wipe) << wipe;
        }
        if (p.rightShown) {
            EXPECT_GE(p.rightX, wipe) << wipe;
            EXPECT_LE(p.rightX + wr, right) << wipe;
        }
        if (p.leftShown && p.rightShown) {
            ++both;
            EXPECT_LE(p.leftX + wl, p.rightX) << wipe;
        }
        // The old rule: each label clamped into [visibleLeft, right - width] on its own.
        const float oldLeft = std::clamp(wipe - gap - wl, visibleLeft, right - wl);
        const float oldRight = std::clamp(wipe + gap, visibleLeft, right - wr);
        if (oldLeft + wl > oldRight && oldRight + wr > oldLeft) ++oldCollisions;
    }
    EXPECT_GT(both, 0) << "in the middle both labels show";
    EXPECT_GT(oldCollisions, 0) << "negative control: the old clamping collides";
}

// The probe window lies inside the visible image and clear of the probed point's square wherever the point is,
// when it fits at all; it is placed beside the point on the side with room. Negative control: the old rule
// (always at the top of the image, beside the point by the clearance) covered points near the top edge at a
// projector's size.
TEST(AppProbeWindow, InsideTheVisibleImageAndNeverOverThePoint) {
    ProbeWindowSpace space;
    space.visibleMin = {700.0f, 20.0f};  // the panel covers the left of a 1900x1060 image
    space.visibleMax = {1880.0f, 1040.0f};
    space.clearance = 120.0f;
    const glm::vec2 size(700.0f, 380.0f);  // a projector's probe window
    int placed = 0, oldCovers = 0;
    for (float y = space.visibleMin.y; y <= space.visibleMax.y; y += 20.0f)
        for (float x = space.visibleMin.x; x <= space.visibleMax.x; x += 20.0f) {
            space.point = {x, y};
            const ProbeWindowPlace p = placeProbeWindow(space, size);
            ASSERT_TRUE(p.fits) << x << ", " << y << ": an image this size has room on some side";
            ++placed;
            EXPECT_GE(p.topLeft.x, space.visibleMin.x);
            EXPECT_GE(p.topLeft.y, space.visibleMin.y);
            EXPECT_LE(p.topLeft.x + size.x, space.visibleMax.x);
            EXPECT_LE(p.topLeft.y + size.y, space.visibleMax.y);
            const bool apartX = p.topLeft.x >= x + space.clearance || p.topLeft.x + size.x <= x - space.clearance;
            const bool apartY = p.topLeft.y >= y + space.clearance || p.topLeft.y + size.y <= y - space.clearance;
            EXPECT_TRUE(apartX || apartY) << "the window covers the point at " << x << ", " << y;
            // The old rule: at the top, right of the point on the left half, left of it on the right half,
            // pushed inside.
            const bool onRight = x > 0.5f * (space.visibleMin.x + space.visibleMax.x);
            const float oldX = onRight ? std::max(space.visibleMin.x, x - space.clearance - size.x)
                                       : std::min(space.visibleMax.x - size.x, x + space.clearance);
            const bool oldApartX = oldX >= x + space.clearance || oldX + size.x <= x - space.clearance;
            const bool oldApartY =
                space.visibleMin.y >= y + space.clearance || space.visibleMin.y + size.y <= y - space.clearance;
            if (!oldApartX && !oldApartY) ++oldCovers;
        }
    EXPECT_GT(placed, 1000);
    EXPECT_GT(oldCovers, 0) << "negative control: the old rule covers some points";
    // Where the arrows' square leaves no side wide enough, the window keeps clear of the point alone.
    space.minClearance = 10.0f;
    space.clearance = 400.0f;
    space.point = {1290.0f, 530.0f};
    const ProbeWindowPlace near = placeProbeWindow(space, size);
    EXPECT_TRUE(near.fits);
    EXPECT_TRUE(near.topLeft.x >= 1300.0f || near.topLeft.x + size.x <= 1280.0f || near.topLeft.y >= 540.0f ||
                near.topLeft.y + size.y <= 520.0f);
    // A window larger than the image cannot fit: it says so, and still starts inside.
    space.point = {1200.0f, 500.0f};
    const ProbeWindowPlace huge = placeProbeWindow(space, {1500.0f, 1200.0f});
    EXPECT_FALSE(huge.fits);
    EXPECT_GE(huge.topLeft.x, space.visibleMin.x);
    EXPECT_GE(huge.topLeft.y, space.visibleMin.y);
}

TEST(AppCaptions, SayTheModelTheTermsAndTheMode) {
    ViewerState s = stateOf("assets/scenes/default.json");
    applyProgression(s, 3);
    setModel(s, ShadingModel::BlinnPhong);
    EXPECT_EQ(imageCaption(s), "Blinn-Phong  \xc2\xb7  step 3: ambient + diffuse + specular  \xc2\xb7  raster");
    setNormalized(s, true);
    setMode(s, ViewMode::Split);
    EXPECT_EQ(imageCaption(s),
              "normalised Blinn-Phong  \xc2\xb7  step 3: ambient + diffuse + specular  \xc2\xb7  raster | reference");
    applyProgression(s, 5);
    EXPECT_EQ(termsCaption(s.scene.terms), "step 5: ambient + diffuse + specular + shadows + reflections");
    // Global: the path tracer has no ambient term, whatever its switch says; Local | Global's left side does.
    setMode(s, ViewMode::Global);
    EXPECT_EQ(imageCaption(s),
              "normalised Blinn-Phong  \xc2\xb7  step 5: diffuse + specular + shadows + reflections  \xc2\xb7  "
              "global illumination (path traced)  \xc2\xb7  first sample");
    // The samples and the noise (none measured from one sample), and the denoised preview says so, in the
    // Global modes only (the raster modes have nothing to denoise).
    EXPECT_NE(imageCaption(s, GlobalCaption{1, 0.0, false}).find("\xc2\xb7  1 sample, noise -"), std::string::npos);
    EXPECT_EQ(imageCaption(s, GlobalCaption{16, 2.14, true}),
              "normalised Blinn-Phong  \xc2\xb7  step 5: diffuse + specular + shadows + reflections  \xc2\xb7  "
              "global illumination (path traced)  \xc2\xb7  16 samples, noise 2.1/255  \xc2\xb7  denoised");
    setGlobalPart(s, trace::PathPart::Indirect);
    EXPECT_NE(imageCaption(s).find("indirect light only"), std::string::npos);
    setMode(s, ViewMode::LocalGlobal);
    EXPECT_EQ(imageCaption(s),
              "normalised Blinn-Phong  \xc2\xb7  step 5: ambient + diffuse + specular + shadows + reflections  "
              "\xc2\xb7  local (raster) | global (path traced)  \xc2\xb7  first sample");
    EXPECT_NE(
        imageCaption(s, GlobalCaption{4, 3.0, true})
            .find("local (raster) | global (path traced)  \xc2\xb7  4 samples, noise 3.0/255  \xc2\xb7  denoised"),
        std::string::npos);
    for (Term t : {Term::Ambient, Term::Diffuse, Term::Specular, Term::Shadows, Term::Reflections})
        setTerm(s, t, false);
    EXPECT_EQ(termsCaption(s.scene.terms), "step 0: no illumination");
    setTerm(s, Term::Shadows, true);  // not a step, and still no light term on
    EXPECT_EQ(termsCaption(s.scene.terms), "no illumination, shadows");
    setTerm(s, Term::Shadows, false);
    setTerm(s, Term::Diffuse, true);  // not a step either
    EXPECT_EQ(termsCaption(s.scene.terms), "diffuse");
    setTerm(s, Term::Diffuse, false);
    setModel(s, ShadingModel::Pbr);
    EXPECT_EQ(modelCaption(s.scene), "PBR (GGX)");
    // An object under its own model is named too, or the caption would mislead (control: back to the scene's).
    Material own = objectMaterial(s.scene, 1);
    own.model = ShadingModel::Phong;
    setObjectMaterial(s, 1, own);
    EXPECT_EQ(modelCaption(s.scene), "PBR (GGX) and the objects' own models");
    own.model = ShadingModel::Pbr;
    setObjectMaterial(s, 1, own);
    EXPECT_EQ(modelCaption(s.scene), "PBR (GGX)");
    // A display that is not Standard is named at the end (not in Difference, which shows the raw values).
    setMode(s, ViewMode::Raster);
    EXPECT_EQ(imageCaption(s, GlobalCaption{4, 3.0, true}), imageCaption(s)) << "no samples or denoising in Raster";
    const std::string plain = imageCaption(s);
    EXPECT_EQ(plain.find("filmic"), std::string::npos);
    setDisplay(s, DisplaySettings{1.5, ViewTransform::Filmic});
    EXPECT_EQ(imageCaption(s), plain + "  \xc2\xb7  filmic, +1.5 stops");
    setMode(s, ViewMode::Difference);
    EXPECT_EQ(imageCaption(s).find("filmic"), std::string::npos);
    setMode(s, ViewMode::Raster);
    setDisplay(s, DisplaySettings{});
    EXPECT_EQ(imageCaption(s), plain);
}

TEST(AppLightMarkers, DraggedLightLandsUnderThePointer) {
    ViewerState s = stateOf("assets/scenes/default.json");
    const int w = 320, h = 180;
    s.scene.lights[0].position = glm::vec3(-2.0f, 2.5f, 2.0f);
    std::vector<LightMarker> markers = lightMarkers(s.scene, w, h);
    ASSERT_EQ(markers.size(), s.scene.lights.size());
    const LightMarker m = markers[0];
    EXPECT_TRUE(m.visible);
    EXPECT_FALSE(m.clamped);
    EXPECT_EQ(markerAt(markers, m.shown + glm::vec2(3.0f, -2.0f), 12.0f), 0);
    EXPECT_EQ(markerAt(markers, m.shown + glm::vec2(40.0f, 0.0f), 12.0f), -1) << "negative control: too far";
    // The default scene's fill light is above the frame: its marker waits at the image's edge.
    EXPECT_TRUE(markers[1].clamped);
    EXPECT_GE(markers[1].shown.y, kMarkerInset);

    const glm::vec2 target = m.pixel + glm::vec2(60.0f, 25.0f);
    const Light moved = draggedLight(s.scene, w, h, 0, target);
    ASSERT_TRUE(setLight(s, 0, moved));
    const LightMarker after = lightMarkers(s.scene, w, h)[0];
    EXPECT_NEAR(after.pixel.x, target.x, 1e-2f);
    EXPECT_NEAR(after.pixel.y, target.y, 1e-2f);
    const ViewSetup v = makeViewSetup(s.scene, w, h);
    EXPECT_NEAR(glm::dot(moved.position - v.eye, v.forward), glm::dot(glm::vec3(-2.0f, 2.5f, 2.0f) - v.eye, v.forward),
                1e-4f)
        << "it moves in the plane facing the camera";
}

TEST(AppLightMarkers, DirectionalLightPointsFromItsMarkerToTheSceneCentre) {
    ViewerState s = stateOf("assets/scenes/default.json");
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.2f, -0.1f, -1.0f));  // from in front: its marker is in the frame
    s.scene.lights = {sun};
    const int w = 320, h = 180;
    const LightMarker m = lightMarkers(s.scene, w, h)[0];
    ASSERT_FALSE(m.clamped) << m.pixel.x << ", " << m.pixel.y;
    const Light turned = draggedLight(s.scene, w, h, 0, m.pixel + glm::vec2(-50.0f, 0.0f));
    EXPECT_NEAR(glm::length(turned.direction), 1.0f, 1e-5f);
    EXPECT_GT(glm::length(turned.direction - sun.direction), 0.05f);
    s.scene.lights = {turned};
    const LightMarker after = lightMarkers(s.scene, w, h)[0];
    EXPECT_NEAR(after.pixel.x, m.pixel.x - 50.0f, 0.5f) << "the marker follows the pointer";
}

// A spot light added in the viewer aims at the scene's centre; its marker sits at its position with an arrow
// along its axis; dragging the disc moves the position under the pointer and keeps the aim, dragging the arrow's
// tip aims it.
TEST(AppLightMarkers, SpotLightMarkerDragsItsPositionAndKeepsItsAim) {
    ViewerState s = stateOf("assets/scenes/default.json");
    s.scene.lights.clear();
    const int i = addLight(s, LightType::Spot);
    ASSERT_EQ(i, 0);
    Light spot = s.scene.lights[0];
    EXPECT_EQ(spot.type, LightType::Spot);
    const Bounds b = sceneBounds(s.scene);
    EXPECT_GT(glm::dot(spot.direction, glm::normalize(0.5f * (b.lo + b.hi) - spot.position)), 0.999f);
    spot.position = glm::vec3(-2.0f, 2.5f, 2.0f);  // in the frame
    ASSERT_TRUE(setLight(s, 0, spot));
    const int w = 320, h = 180;
    const LightMarker m = lightMarkers(s.scene, w, h)[0];
    ASSERT_FALSE(m.clamped);
    EXPECT_GT(glm::length(m.arrowTip - m.pixel), 1.0f) << "a spot's marker shows its axis";
    const glm::vec2 target = m.pixel + glm::vec2(40.0f, 10.0f);
    const Light moved = draggedLight(s.scene, w, h, 0, target);
    EXPECT_EQ(moved.direction, spot.direction);
    EXPECT_GT(glm::length(moved.position - spot.position), 0.1f);
    ASSERT_TRUE(setLight(s, 0, moved));
    const LightMarker after = lightMarkers(s.scene, w, h)[0];
    EXPECT_NEAR(after.pixel.x, target.x, 1e-2f);
    EXPECT_NEAR(after.pixel.y, target.y, 1e-2f);

    // The arrow's tip is the aiming handle: dragged, the spot turns toward the pointer and stays where it is.
    const std::vector<LightMarker> markers = lightMarkers(s.scene, w, h);
    EXPECT_EQ(aimHandleAt(s.scene, markers, after.arrowTip + glm::vec2(1.0f, -1.0f), 8.0f), 0);
    EXPECT_EQ(aimHandleAt(s.scene, markers, after.arrowTip + glm::vec2(30.0f, 0.0f), 8.0f), -1) << "too far";
    const glm::vec2 aimAt = after.arrowTip + glm::vec2(-30.0f, 20.0f);
    const Light aimed = aimedSpot(s.scene, w, h, 0, aimAt);
    EXPECT_EQ(aimed.position, moved.position);
    EXPECT_NEAR(glm::length(aimed.direction), 1.0f, 1e-5f);
    EXPECT_GT(glm::length(aimed.direction - moved.direction), 0.05f);
    ASSERT_TRUE(setLight(s, 0, aimed));
    const LightMarker turned = lightMarkers(s.scene, w, h)[0];
    // The arrow keeps its length in the world, so on screen it points from the disc toward the pointer.
    const glm::vec2 arrow = glm::normalize(turned.arrowTip - turned.pixel);
    EXPECT_GT(glm::dot(arrow, glm::normalize(aimAt - turned.pixel)), 0.9999f) << "the arrow points at the pointer";
    // Negative control: a point light has no aiming handle.
    s.scene.lights[0].type = LightType::Point;
    EXPECT_EQ(aimHandleAt(s.scene, lightMarkers(s.scene, w, h), turned.arrowTip, 8.0f), -1);
}

TEST(AppProbeDiagram, EveryVectorIsDrawnFullLengthAtItsAngleFromN) {
    ProbeResult p;
    p.hit = true;
    p.N = glm::vec3(0, 1, 0);
    p.V = glm::vec3(0, 1, 0);  // looking straight down the normal: V is a dot in the 3D overlay
    ProbeLight l;
    l.L = glm::normalize(glm::vec3(-1, 1, 0));
    l.R = glm::normalize(glm::vec3(1, 1, 0));
    l.H = glm::normalize(l.L + p.V);
    l.NoL = glm::dot(p.N, l.L);
    p.lights = {l};
    const ProbeDiagram d = probeDiagram(p, 0);
    ASSERT_EQ(d.arrows.size(), 5u);
    const float px = 62.0f;  // the probe window's radius at UI scale 1
    for (const DiagramArrow& a : d.arrows) {
        EXPECT_NEAR(glm::length(a.dir), 1.0f, 1e-5f) << a.name;
        EXPECT_GE(glm::length(a.dir) * px, 20.0f) << a.name << " must not collapse to a dot";
    }
    EXPECT_EQ(d.arrows[0].name, "N");
    EXPECT_NEAR(d.arrows[1].angleDeg, 45.0f, 1e-3f);  // L
    EXPECT_LT(d.arrows[1].dir.x, 0.0f) << "L on the left";
    EXPECT_GT(d.arrows[2].dir.x, 0.0f) << "R on the right";
    EXPECT_NEAR(d.arrows[4].angleDeg, 0.0f, 1e-3f);  // V along N
    EXPECT_TRUE(d.lit);
    // V out of the plane of incidence is reported, not lost.
    p.V = glm::normalize(glm::vec3(0, 1, 1));
    EXPECT_NEAR(probeDiagram(p, 0).vOutOfPlaneDeg, 45.0f, 1e-3f);
    // Negative control: no hit, no figure.
    p.hit = false;
    EXPECT_TRUE(probeDiagram(p, 0).arrows.empty());
}

TEST(AppFileList, ListsFoldersThenScenesAndRemembersRecentFiles) {
    const std::string dir = test::outputPath("file_list");
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir + "/sub");
    std::filesystem::create_directories(dir + "/.hidden");
    for (const char* f : {"b.json", "a.GLB", "model.gltf", "notes.txt", "shot.png"})
        std::ofstream(dir + "/" + f) << "x";
    const FileList list = listSceneFolder(dir);
    EXPECT_TRUE(list.error.empty()) << list.error;
    std::vector<std::string> names;
    for (const FileEntry& e : list.entries) names.push_back(e.name);
    EXPECT_EQ(names, (std::vector<std::string>{"../", "sub/", "a.GLB", "b.json", "model.gltf"}));
    EXPECT_FALSE(listSceneFolder(dir + "/missing").error.empty()) << "negative control: an unreadable folder says why";

    std::vector<std::string> recent;
    for (const char* p : {"a", "b", "a", "c"}) rememberRecent(recent, p, 2);
    EXPECT_EQ(recent, (std::vector<std::string>{"c", "a"}));
}

// A spot's marker outlines its outer cone: a closed rim around the arrow's end, wider for a wider cone;
// a point light, and a spot whose marker waits at the image's edge, have none.
TEST(AppLightMarkers, SpotMarkerOutlinesItsCone) {
    ViewerState s = stateOf("assets/scenes/default.json");
    s.scene.lights.clear();
    addLight(s, LightType::Spot);
    addLight(s, LightType::Point);
    Light spot = s.scene.lights[0];
    spot.position = glm::vec3(0.5f, 2.3f, 1.5f);
    spot.direction = glm::normalize(glm::vec3(-0.2f, -1.0f, -0.6f));
    spot.innerConeAngle = 0.2f;
    spot.outerConeAngle = 0.3f;
    ASSERT_TRUE(setLight(s, 0, spot));
    const int w = 320, h = 180;
    auto spread = [](const LightMarker& m) {
        float r = 0.0f;
        for (const glm::vec2& p : m.coneRim) r = std::max(r, glm::length(p - m.arrowTip));
        return r;
    };
    const std::vector<LightMarker> markers = lightMarkers(s.scene, w, h);
    ASSERT_EQ(markers[0].coneRim.size(), 32u);
    EXPECT_TRUE(markers[1].coneRim.empty()) << "a point light has no cone";
    const float narrow = spread(markers[0]);
    EXPECT_GT(narrow, 2.0f);
    spot.outerConeAngle = 0.6f;
    ASSERT_TRUE(setLight(s, 0, spot));
    EXPECT_GT(spread(lightMarkers(s.scene, w, h)[0]), 1.5f * narrow) << "control: a wider cone, a wider rim";
    spot.position = glm::vec3(0.0f, 40.0f, 0.0f);  // far above the frame: the marker is clamped to the edge
    ASSERT_TRUE(setLight(s, 0, spot));
    const LightMarker off = lightMarkers(s.scene, w, h)[0];
    EXPECT_TRUE(off.clamped);
    EXPECT_TRUE(off.coneRim.empty());
}
