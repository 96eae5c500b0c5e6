// _Scene: the compiled side of shadelab.Scene (python/shadelab/scene.py). Documents go in as Python values and come
// back as scene-file text; every check, name table and message is the scene file's (scene/scene_json.h).
// max_memory (bytes, 0: none) holds an environment map's load to render(max_memory=...)'s limit.
#include "python/bindings.h"
#include "python/py_json.h"
#include "python/scene_handle.h"
#include "scene/scene_json.h"
#include "scene/scene_models.h"
#include "util/output_file.h"

#include <pybind11/stl.h>

#include <cstdint>
#include <optional>

namespace py = pybind11;

namespace shadelab::python {

void bindScene(py::module_& m) {
    py::class_<SceneHandle>(m, "_Scene")
        .def_static(
            "load",
            [](const std::string& path, bool allowExternalPaths, uint64_t maxMemory) {
                std::vector<std::string> warnings;
                std::optional<SceneHandle> h;
                {
                    py::gil_scoped_release released;  // a large glTF takes a while; the handle is no one else's
                    h = SceneHandle::load(path, allowExternalPaths, warnings, maxMemory);
                }
                return py::make_tuple(std::move(*h), warnings);
            },
            py::arg("path"), py::arg("allow_external_paths") = false, py::arg("max_memory") = 0)
        .def_static(
            "from_document",
            [](py::handle doc, const std::string& baseDir, bool allowExternalPaths, uint64_t maxMemory) {
                std::vector<std::string> warnings;
                const nlohmann::json document = toJson(doc);
                std::optional<SceneHandle> h;
                {
                    py::gil_scoped_release released;
                    h = SceneHandle::fromDocument(document, baseDir, allowExternalPaths, warnings, maxMemory);
                }
                return py::make_tuple(std::move(*h), warnings);
            },
            py::arg("document"), py::arg("base_dir"), py::arg("allow_external_paths") = false,
            py::arg("max_memory") = 0)
        .def(
            "replace",
            [](SceneHandle& h, py::handle doc, bool rejectUnknownFields) {
                std::vector<std::string> warnings;
                const bool replaced = h.replace(toJson(doc), warnings, rejectUnknownFields);
                return py::make_tuple(replaced, warnings);
            },
            py::arg("document"), py::arg("reject_unknown_fields") = false,
            "Parses `document` as a scene file: (replaced, warnings); the scene is unchanged when it raises")
        .def("to_json", [](const SceneHandle& h) { return sceneToJson(h.scene()); })
        .def("to_document", [](const SceneHandle& h) { return jsonTextToPython(sceneToJson(h.scene(), true)); })
        .def("save",
             [](const SceneHandle& h, const std::string& path) {
                 createOutputFolder(path);  // as `render -o out/x.png` does
                 saveSceneJson(h.scene(), path);
             })
        .def("copy", [](const SceneHandle& h) { return SceneHandle(h); })
        .def(
            "layers_not_shown", [](const SceneHandle& h) { return layersNotShown(h.scene()); },
            "glTF's layers that objects carry but their model does not shade (scene_models.h), \"\" for none")
        .def_property_readonly("base_dir", &SceneHandle::baseDir)
        .def_property_readonly("allow_external_paths", &SceneHandle::allowExternalPaths)
        .def_property_readonly("triangles", [](const SceneHandle& h) {
            size_t n = 0;
            for (const Mesh& mesh : h.scene().meshes) n += mesh.triangleCount();
            return n;
        });
}

}  // namespace shadelab::python
