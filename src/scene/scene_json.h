// Scene files: JSON load and save (docs/scene-format.md). Loading parses the description only;
// meshes' glTF geometry is imported by loadScene() in scene_load.h.
#pragma once

#include "scene/scene.h"

#include <string>

namespace shadelab {

class JsonNode;

// Parses scene JSON text. `file` names the source in errors. Throws InputError whose message names the
// file, the JSON path and the problem, e.g. "a.json: lights[2].color: expected 3 numbers, got 2".
// Unknown fields are reported through `warn` (one line each), never as errors.
Scene parseSceneJson(const std::string& text, const std::string& file, void (*warn)(const std::string& line) = nullptr);
// The same over an already parsed document (its root node): the Python package's Scene.from_dict builds the
// document from a dict, so its errors and warnings read exactly as a file's.
Scene parseSceneDocument(const JsonNode& root);

// The scene file's readers of a material's and a light's fields, shared with the viewer's scripts so that
// both accept the same values and word errors alike (the "raster" reader is raster_override.h's). Each reads
// whichever of its fields object `n` holds; other keys are the caller's to warn about or refuse.
MaterialOverride parseMaterialOverride(const JsonNode& n);  // ma md ms s kr kt ior baseColor metallic roughness
LightOverride parseLightOverride(const JsonNode& n);        // "position", "direction", "color", the cone, "range"

// Serialises every described field (not imported geometry). parse(save(s)) == s, field by field. A material's
// fields derived from the other model's (Material::derived) are left out, so that loading derives them again;
// `withDerived` writes them too, listed under the material's "derived" (Python's documents: every value readable,
// and an edit of a given field re-derives the rest).
std::string sceneToJson(const Scene& scene, bool withDerived = false);

// Writes atomically (util/atomic_file.h).
void saveSceneJson(const Scene& scene, const std::string& path);

}  // namespace shadelab
