// Scene files: JSON text ↔ Scene (docs/scene-format.md). Loading validates every field and names its JSON
// path in errors; saving writes every field, so a saved file documents itself and loads back exactly.
// Mesh geometry is not touched here: loadScene() (scene_load.h) imports it.
//
// Sections: 1. loading camera, lights (materials, read and written: material_json.cpp)   2. loading objects
//           3. the light reader scripts share; parseSceneJson
//           4. saving (the layout; exact floats: json_write.h)      5. sceneToJson, saveSceneJson
#include "scene/scene_json.h"

#include "scene/json_reader.h"
#include "scene/json_write.h"
#include "scene/material_json.h"
#include "scene/raster_override.h"
#include "scene/scene_limits.h"
#include "util/atomic_file.h"
#include "util/input_error.h"

#include <algorithm>
#include <charconv>
#include <climits>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <iterator>
#include <map>
#include <stdexcept>

namespace shadelab {

namespace {

constexpr int kFormatVersion = 1;
constexpr int kMaxDepthLimit = 64;

// ---- 1. Loading the camera and lights (materials: material_json.cpp) ---------------------------------

Camera parseCamera(const JsonNode& n) {
    n.requireObject().warnUnknownKeys({"position", "target", "up", "fovY"});
    Camera c;
    if (auto f = n.find("position")) c.position = f->vec3Within(kMaxCoordinate);
    if (auto f = n.find("target")) c.target = f->vec3Within(kMaxCoordinate);
    if (auto f = n.find("up")) c.up = f->nonZeroVec3();
    if (auto f = n.find("fovY")) c.fovY = f->inRange(0.0f, 180.0f, true, true);
    glm::vec3 view = c.target - c.position;
    if (view == glm::vec3(0.0f)) n.failAt("target", "must differ from camera.position");
    if (glm::length(glm::cross(glm::normalize(view), glm::normalize(c.up))) < 1e-6f)
        n.failAt("up", "must not be parallel to the view direction (target - position)");
    return c;
}

Light parseLight(const JsonNode& n) {
    n.requireObject().warnUnknownKeys(
        {"type", "name", "position", "direction", "color", "attenuation", "innerConeAngle", "outerConeAngle", "range"});
    Light l;
    l.type = n.child("type").oneOf(kLightTypeNames, "light type");
    if (auto f = n.find("name")) l.name = f->string();
    // Each type requires its own fields (child() fails "missing required field"); the other types' are optional
    // and unused, but kept so that a saved scene loads back exactly.
    if (l.positional()) n.child("position");
    if (l.type != LightType::Point) n.child("direction");
    parseLightOverride(n).applyTo(l);
    if (l.innerConeAngle > l.outerConeAngle)
        n.failAt("innerConeAngle", "must not exceed outerConeAngle (" + std::to_string(l.outerConeAngle) + ")");
    if (auto f = n.find("attenuation")) {
        f->vec3();  // shape and finiteness
        l.attenuation = {(*f)[0].nonNegative(), (*f)[1].nonNegative(), (*f)[2].nonNegative()};
        if (l.attenuation == glm::vec3(0.0f)) f->fail("must not be all zero: 1/(kc + kl*d + kq*d^2) would divide by 0");
    }
    return l;
}

// ---- 2. Loading objects --------------------------------------------------------------------------------

float nonZero(const JsonNode& n) {
    float f = n.finite();
    if (f == 0.0f) n.fail("must be non-zero");
    return f;
}

// {"translate", "rotate" (Euler degrees, applied X then Y then Z), "scale"}: M = T · Rz · Ry · Rx · S.
glm::mat4 parseTransform(const JsonNode& n) {
    n.requireObject().warnUnknownKeys({"translate", "rotate", "scale"});
    glm::mat4 m(1.0f);
    if (auto f = n.find("translate")) m = glm::translate(m, f->vec3());
    if (auto f = n.find("rotate")) {
        glm::vec3 r = f->vec3();
        m = glm::rotate(m, glm::radians(r.z), glm::vec3(0, 0, 1));
        m = glm::rotate(m, glm::radians(r.y), glm::vec3(0, 1, 0));
        m = glm::rotate(m, glm::radians(r.x), glm::vec3(1, 0, 0));
    }
    if (auto f = n.find("scale")) {
        glm::vec3 s = f->json().is_number() ? glm::vec3(nonZero(*f)) : f->vec3();
        if (!f->json().is_number())
            for (size_t i = 0; i < 3; ++i) nonZero((*f)[i]);  // vec3() has checked there are 3
        m = glm::scale(m, s);
    }
    // Scales that are each non-zero can still make a singular matrix in floats (1e-38 cubed is 0): refused as a
    // matrix is, so that the scene saves (as a matrix) into a file that loads.
    if (glm::determinant(glm::mat3(m)) == 0.0f) n.fail("must be invertible (its 3x3 part has determinant 0)");
    return m;
}

// 16 numbers, column-major (OpenGL and glTF order): an affine, invertible transform.
glm::mat4 parseMatrix(const JsonNode& n) {
    if (n.arraySize() != 16) n.fail("expected 16 numbers (column-major), got " + std::to_string(n.arraySize()));
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = n[static_cast<size_t>(i)].finite();
    if (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f)
        n.fail("must be affine: elements 3, 7, 11, 15 (the last row) must be 0, 0, 0, 1");
    if (glm::determinant(glm::mat3(m)) == 0.0f) n.fail("must be invertible (its 3x3 part has determinant 0)");
    return m;
}

void parseObject(const JsonNode& n, const NamedMaterials& named, Scene& scene) {
    n.requireObject();
    JsonNode type = n.child("type");
    std::string t = type.string();
    std::string name = n.has("name") ? n.child("name").string() : std::string();
    if (t == "sphere") {
        n.warnUnknownKeys({"type", "name", "center", "radius", "material"});
        Sphere s;
        s.name = name;
        s.center = n.child("center").vec3Within(kMaxCoordinate);
        const JsonNode radius = n.child("radius");
        s.radius = radius.within(radius.positive(), kMaxCoordinate, "the largest coordinate");
        s.material = parseMaterial(n, named);
        scene.spheres.push_back(s);
    } else if (t == "plane") {
        n.warnUnknownKeys({"type", "name", "normal", "offset", "point", "material", "checker"});
        Plane p;
        p.name = name;
        if (auto f = n.find("normal")) p.normal = f->unitVec3();
        if (n.has("offset") && n.has("point")) n.failAt("point", "give either \"offset\" or \"point\", not both");
        if (auto f = n.find("offset")) p.offset = f->within(f->finite(), kMaxCoordinate, "the largest coordinate");
        if (auto f = n.find("point")) {
            glm::dvec3 q(f->vec3Within(kMaxCoordinate)), normal(p.normal);
            p.offset = static_cast<float>(glm::dot(normal, q));
        }
        p.material = parseMaterial(n, named);
        if (auto f = n.find("checker")) {
            f->requireObject().warnUnknownKeys({"md2", "size"});
            Checker c;
            if (auto g = f->find("md2")) c.md2 = g->rgb();
            if (auto g = f->find("size")) c.size = g->positive();
            p.checker = c;
        }
        scene.planes.push_back(p);
    } else if (t == "mesh") {
        n.warnUnknownKeys({"type", "name", "source", "transform", "matrix", "material"});
        Mesh m;
        m.name = name;
        m.source = n.child("source").string();
        if (m.source.empty()) n.failAt("source", "must not be empty");
        if (n.has("transform") && n.has("matrix"))
            n.failAt("matrix", "give either \"transform\" or \"matrix\", not both");
        if (auto f = n.find("transform")) m.transform = parseTransform(*f);
        if (auto f = n.find("matrix")) m.transform = parseMatrix(*f);
        if (auto f = n.find("material")) m.material = parseMaterialRef(*f, named);
        scene.meshes.push_back(std::move(m));
    } else {
        type.fail("unknown object type '" + t + "'; expected sphere, plane or mesh");
    }
}

}  // namespace

// ---- 3. The light reader scripts share; parseSceneJson --------------------------------------------------

LightOverride parseLightOverride(const JsonNode& n) {
    n.requireObject();
    LightOverride l;
    if (auto f = n.find("position")) l.position = f->vec3Within(kMaxCoordinate);
    if (auto f = n.find("direction")) l.direction = f->unitVec3();
    if (auto f = n.find("color")) l.color = f->rgbUpTo(kMaxRadiance);
    if (auto f = n.find("innerConeAngle")) l.innerConeAngle = f->inRange(0.0f, kMaxConeAngle, false, false);
    if (auto f = n.find("outerConeAngle")) l.outerConeAngle = f->inRange(0.0f, kMaxConeAngle, false, false);
    if (auto f = n.find("range")) l.range = f->positive();
    return l;
}

// "environment": {"hdr": path, "intensity": x, "rotation": degrees}; {} is the uniform `background`.
static Environment parseEnvironment(const JsonNode& n) {
    n.requireObject().warnUnknownKeys({"hdr", "intensity", "rotation"});
    Environment e;
    if (auto f = n.find("hdr")) {
        e.hdr = f->string();
        if (e.hdr.empty()) f->fail("must name a .hdr file; omit \"hdr\" for a uniform environment");
        if (e.hdr.find('\0') != std::string::npos) f->fail("contains a NUL character");
    }
    if (auto f = n.find("intensity"))
        e.intensity = f->within(f->nonNegative(), kMaxEnvironmentIntensity, "the largest environment intensity");
    if (auto f = n.find("rotation")) e.rotation = f->inRange(-360.0f, 360.0f, false, false);
    return e;
}

Scene parseSceneJson(const std::string& text, const std::string& file, void (*warn)(const std::string& line)) {
    nlohmann::json doc = parseJsonText(text, file);
    return parseSceneDocument(JsonNode(doc, "", file, warn));
}

Scene parseSceneDocument(const JsonNode& root) {
    root.requireObject().warnUnknownKeys({"shadelab", "title", "notes", "camera", "model", "normalized", "terms",
                                          "ambient", "background", "environment", "energyCompensation", "maxDepth",
                                          "raster", "display", "lights", "objects", "materials"});
    Scene scene;
    if (auto f = root.find("shadelab")) {
        int version = f->integerIn(1, INT_MAX);
        if (version > kFormatVersion)
            f->fail("this file is format version " + std::to_string(version) + "; this build reads version " +
                    std::to_string(kFormatVersion) + " or older");
    }
    if (auto f = root.find("title")) scene.title = f->string();
    if (auto f = root.find("notes")) scene.notes = f->string();
    if (auto f = root.find("camera")) scene.camera = parseCamera(*f);
    if (auto f = root.find("model")) scene.model = f->oneOf(kShadingModelNames, "shading model");
    if (auto f = root.find("normalized")) scene.normalized = f->boolean();
    if (auto f = root.find("terms")) {
        f->requireObject().warnUnknownKeys(canonicalNames(kTermNames));
        for (const EnumName<Term>& term : kTermNames)
            if (auto g = f->find(term.name)) termFlag(scene.terms, term.value) = g->boolean();
    }
    if (auto f = root.find("ambient")) scene.ambient = f->rgbUpTo(kMaxRadiance);
    if (auto f = root.find("background")) scene.background = f->rgbUpTo(kMaxRadiance);
    if (auto f = root.find("environment"); f && !f->json().is_null()) scene.environment = parseEnvironment(*f);
    if (auto f = root.find("energyCompensation")) scene.energyCompensation = f->boolean();
    if (auto f = root.find("maxDepth")) scene.maxDepth = f->integerIn(0, kMaxDepthLimit);
    if (auto f = root.find("raster")) {
        f->requireObject().warnUnknownKeys(
            {"shadowMapSize", "depthBias", "normalBias", "pcf", "reflectionCubeSize", "movingPreview"});
        parseRasterOverride(*f).applyTo(scene.raster);
    }
    // How the scene's images are shown and encoded (image/view_transform.h); never what is rendered.
    if (auto f = root.find("display")) {
        f->requireObject().warnUnknownKeys({"exposure", "viewTransform"});
        if (auto g = f->find("exposure")) {
            const double stops = g->number();
            if (std::optional<std::string> why = exposureProblem(stops)) g->fail(*why);
            scene.display.exposure = stops;
        }
        if (auto g = f->find("viewTransform"))
            scene.display.transform = g->oneOf(kViewTransformNames, "view transform");
    }

    if (auto f = root.find("lights")) {
        size_t n = f->arraySize();
        if (n > static_cast<size_t>(kMaxLights))
            f->fail("too many lights: " + std::to_string(n) + "; at most " + std::to_string(kMaxLights));
        for (size_t i = 0; i < n; ++i) scene.lights.push_back(parseLight((*f)[i]));
    }
    NamedMaterials named;
    if (auto f = root.find("materials")) {
        f->requireObject();
        for (auto it = f->json().begin(); it != f->json().end(); ++it)
            named[it.key()] = parseMaterialFields(f->child(it.key()));
    }
    if (auto f = root.find("objects")) {
        size_t n = f->arraySize();
        for (size_t i = 0; i < n; ++i) parseObject((*f)[i], named, scene);
    }
    return scene;
}

// ---- 4. Saving: exact floats and a readable layout -----------------------------------------------------

namespace {

using OJson = nlohmann::ordered_json;
using json_write::exact;
using json_write::vec;

bool isScalar(const OJson& j) { return (!j.is_object() && !j.is_array()) || j.empty(); }

std::string scalar(const OJson& j) { return j.dump(-1, ' ', false, OJson::error_handler_t::replace); }

// One line: {"a": 1, "b": [1, 2, 3]}.
std::string inlineForm(const OJson& j) {
    if (isScalar(j)) return scalar(j);
    std::string s = j.is_array() ? "[" : "{";
    for (auto it = j.begin(); it != j.end(); ++it) {
        if (it != j.begin()) s += ", ";
        if (j.is_object()) s += scalar(it.key()) + ": ";
        s += inlineForm(*it);
    }
    return s + (j.is_array() ? "]" : "}");
}

// Vectors and small flat objects stay on one line; everything else gets one member per line.
void writePretty(const OJson& j, int indent, std::string& out) {
    bool flat = std::all_of(j.begin(), j.end(), [](const OJson& e) {
        return isScalar(e) || (e.is_array() && std::all_of(e.begin(), e.end(), isScalar));
    });
    std::string one = inlineForm(j);
    if (isScalar(j) || (j.is_array() && flat && one.size() <= 120) || (flat && indent + one.size() <= 100)) {
        out += one;
        return;
    }
    std::string pad(static_cast<size_t>(indent + 2), ' ');
    out += j.is_array() ? "[\n" : "{\n";
    for (auto it = j.begin(); it != j.end(); ++it) {
        out += pad;
        if (j.is_object()) out += scalar(it.key()) + ": ";
        writePretty(*it, indent + 2, out);
        out += std::next(it) == j.end() ? "\n" : ",\n";
    }
    out += std::string(static_cast<size_t>(indent), ' ') + (j.is_array() ? "]" : "}");
}

}  // namespace

// ---- 5. sceneToJson, saveSceneJson ---------------------------------------------------------------------

std::string sceneToJson(const Scene& scene, bool withDerived) {
    OJson doc;
    doc["shadelab"] = kFormatVersion;
    doc["title"] = scene.title;
    doc["notes"] = scene.notes;
    const Camera& c = scene.camera;
    doc["camera"] = {
        {"position", vec(c.position)}, {"target", vec(c.target)}, {"up", vec(c.up)}, {"fovY", exact(c.fovY)}};
    doc["model"] = toString(scene.model);
    doc["normalized"] = scene.normalized;
    const Terms& t = scene.terms;
    doc["terms"] = OJson::object();
    for (const EnumName<Term>& term : kTermNames) doc["terms"][term.name] = termEnabled(t, term.value);
    doc["ambient"] = vec(scene.ambient);
    doc["background"] = vec(scene.background);
    if (scene.environment) {
        const Environment& e = *scene.environment;
        doc["environment"] = OJson::object();
        if (!e.hdr.empty()) doc["environment"]["hdr"] = e.hdr;
        doc["environment"]["intensity"] = exact(e.intensity);
        doc["environment"]["rotation"] = exact(e.rotation);
    }
    doc["energyCompensation"] = scene.energyCompensation;
    doc["maxDepth"] = scene.maxDepth;
    const RasterSettings& r = scene.raster;
    doc["raster"] = {{"shadowMapSize", r.shadowMapSize == 0 ? OJson("auto") : OJson(r.shadowMapSize)},
                     {"depthBias", exact(r.depthBias)},
                     {"normalBias", exact(r.normalBias)},
                     {"pcf", r.pcf},
                     {"reflectionCubeSize", r.reflectionCubeSize},
                     {"movingPreview", r.movingPreview}};
    // Written only when it is not Standard, so that saving a scene that never had one adds nothing.
    if (!scene.display.isStandard())
        doc["display"] = {{"exposure", scene.display.exposure}, {"viewTransform", toString(scene.display.transform)}};

    OJson lights = OJson::array();
    for (const Light& l : scene.lights) {
        lights.push_back({{"type", toString(l.type)},
                          {"name", l.name},
                          {"position", vec(l.position)},
                          {"direction", vec(l.direction)},
                          {"color", vec(l.color)},
                          {"attenuation", vec(l.attenuation)}});
        // The cone is written for a spot light, or where another type keeps one it was given; absent range: none.
        OJson& saved = lights.back();
        if (l.type == LightType::Spot || l.innerConeAngle != kDefaultInnerConeAngle ||
            l.outerConeAngle != kDefaultOuterConeAngle) {
            saved["innerConeAngle"] = exact(l.innerConeAngle);
            saved["outerConeAngle"] = exact(l.outerConeAngle);
        }
        if (l.range > 0.0f) saved["range"] = exact(l.range);
    }
    doc["lights"] = lights;

    OJson objects = OJson::array();
    for (const Sphere& s : scene.spheres) {
        objects.push_back({{"type", "sphere"},
                           {"name", s.name},
                           {"center", vec(s.center)},
                           {"radius", exact(s.radius)},
                           {"material", materialJson(s.material, withDerived)}});
    }
    for (const Plane& p : scene.planes) {
        OJson j = {{"type", "plane"},
                   {"name", p.name},
                   {"normal", vec(p.normal)},
                   {"offset", exact(p.offset)},
                   {"material", materialJson(p.material, withDerived)}};
        if (p.checker) j["checker"] = {{"md2", vec(p.checker->md2)}, {"size", exact(p.checker->size)}};
        objects.push_back(j);
    }
    for (const Mesh& m : scene.meshes) {
        OJson j = {{"type", "mesh"}, {"name", m.name}, {"source", m.source}};
        if (m.transform != glm::mat4(1.0f)) {
            OJson matrix = OJson::array();
            for (int i = 0; i < 16; ++i) matrix.push_back(exact(m.transform[i / 4][i % 4]));
            j["matrix"] = matrix;
        }
        j["material"] = overrideJson(m.material);
        objects.push_back(j);
    }
    doc["objects"] = objects;

    std::string out;
    writePretty(doc, 0, out);
    return out + "\n";
}

void saveSceneJson(const Scene& scene, const std::string& path) { writeFileAtomic(path, sceneToJson(scene)); }

}  // namespace shadelab
