// _Renderer and _probe: rendering and the lighting probe, with the GIL released while they run so that other Python
// threads (a notebook's widgets, a Dask worker's heartbeat) keep going.
#include "image/image.h"
#include "probe/probe.h"
#include "probe/ray_tree_view.h"
#include "python/bindings.h"
#include "python/py_json.h"
#include "python/renderer.h"
#include "python/scene_handle.h"
#include "render/memory_budget.h"
#include "trace/trace_scene.h"
#include "util/input_error.h"

#include <pybind11/stl.h>

#include <cstdint>
#include <memory>

namespace py = pybind11;

namespace shadelab::python {
namespace {

template <typename E, size_t N>
E named(const EnumName<E> (&table)[N], const std::string& word, const char* argument) {
    if (std::optional<E> v = lookupName(table, word)) return *v;
    throw UsageError(std::string(argument) + ": unknown value '" + word + "'; expected " + nameChoices(table));
}

template <typename E, size_t N>
std::optional<E> namedIfGiven(const EnumName<E> (&table)[N], const std::optional<std::string>& word,
                              const char* argument) {
    if (!word) return std::nullopt;
    return named(table, *word, argument);
}

// max_memory as Python gives it: None (the command line's default), a number of bytes, or a size as
// --max-memory writes it ("512M", "2G"; a bare number in a string is MiB, as on the command line).
uint64_t memoryLimitOf(const py::handle& v) {
    if (v.is_none()) return render::defaultMaxMemory();
    if (py::isinstance<py::str>(v)) {
        try {
            return render::parseMemorySize(v.cast<std::string>());
        } catch (const SettingError& e) {
            throw UsageError(e.what());  // "max_memory: expected a size such as 512M or 2G, got 'lots'"
        }
    }
    if (!py::isinstance<py::bool_>(v) && PyIndex_Check(v.ptr())) {  // int, numpy integers
        const py::int_ bytes = py::reinterpret_steal<py::int_>(PyNumber_Index(v.ptr()));
        if (!bytes) throw py::error_already_set();
        if (bytes < py::int_(1) || bytes > py::int_(uint64_t(1e18)))
            throw UsageError("max_memory: expected a number of bytes from 1 to 1e18, or a size such as '512M', got " +
                             std::string(py::repr(bytes)).substr(0, 40));
        return bytes.cast<uint64_t>();
    }
    throw py::type_error("max_memory: expected a number of bytes, a size such as '512M' or None, got " +
                         std::string(py::str(py::type::of(v).attr("__name__"))));
}

}  // namespace

void bindRender(py::module_& m) {
    m.def(
        "_memory_limit", [](const py::object& maxMemory) { return memoryLimitOf(maxMemory); }, py::arg("max_memory"),
        "The limit in bytes that render(max_memory=...) means: None, the command line's default (half of physical "
        "memory, within ulimit -v); a number of bytes; or a size such as '512M' or '2G'");

    py::class_<Renderer>(m, "_Renderer")
        .def(py::init([](const std::string& backend) {
                 return std::make_unique<Renderer>(named(gl::kGlBackendNames, backend, "backend"));
             }),
             py::arg("backend") = "auto")
        .def(
            "render",
            [](Renderer& r, const SceneHandle& scene, int width, int height, const std::string& engine,
               std::optional<int> spp, const std::string& encoding, std::optional<int> depth, int threads,
               bool coverage, std::optional<double> timeLimit, const std::optional<std::string>& estimator,
               const std::optional<std::string>& lightPaths, const std::optional<std::string>& sampler, bool denoise,
               std::optional<uint64_t> maxMemory, std::optional<double> exposure,
               const std::optional<std::string>& viewTransform, std::optional<int64_t> seed) {
                render::RenderRequest request;
                request.width = width;
                request.height = height;
                request.engine = named(render::kEngineNames, engine, "renderer");
                request.spp = spp;
                request.encoding = named(kEncodingNames, encoding, "encoding");
                request.depth = depth;
                request.threads = threads;
                request.coverage = coverage;
                request.path.timeLimit = timeLimit;
                request.path.estimator = namedIfGiven(trace::kPathEstimatorNames, estimator, "estimator");
                request.path.part = namedIfGiven(trace::kPathPartNames, lightPaths, "light_paths");
                request.path.sampler = namedIfGiven(trace::kPathSamplerNames, sampler, "sampler");
                request.path.denoise = denoise;
                request.path.seed = seed;
                request.maxMemory = maxMemory;
                request.exposure = exposure;  // unset: the scene's display
                request.viewTransform = namedIfGiven(kViewTransformNames, viewTransform, "view_transform");
                validate(request);
                const Scene copy = scene.scene();  // O(objects); Python may edit the original meanwhile
                auto image = std::make_shared<ImageData>();
                {
                    py::gil_scoped_release released;
                    *image = r.render(copy, request);
                }
                return image;
            },
            py::arg("scene"), py::arg("width"), py::arg("height"), py::arg("renderer") = "raster",
            py::arg("spp") = py::none(), py::arg("encoding") = "srgb", py::arg("depth") = py::none(),
            py::arg("threads") = 0, py::arg("coverage") = false, py::arg("time_limit") = py::none(),
            py::arg("estimator") = py::none(), py::arg("light_paths") = py::none(), py::arg("sampler") = py::none(),
            py::arg("denoise") = false, py::arg("max_memory") = py::none(), py::arg("exposure") = py::none(),
            py::arg("view_transform") = py::none(), py::arg("seed") = py::none())
        .def("context_info",
             [](Renderer& r) {
                 gl::ContextInfo info;
                 {
                     py::gil_scoped_release released;
                     info = r.contextInfo();
                 }
                 py::dict d;
                 d["backend"] = gl::toString(info.backend);
                 d["device"] = info.device;
                 d["gl_renderer"] = info.renderer;
                 d["gl_version"] = info.version;
                 return d;
             })
        .def("close",
             [](Renderer& r) {
                 py::gil_scoped_release released;
                 r.close();
             })
        .def_property_readonly("busy", &Renderer::busy);

    m.def(
        "_probe",
        [](const SceneHandle& scene, int x, int y, int width, int height, bool rayTree) {
            if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
                throw UsageError("size: each side must be 1.." + std::to_string(kMaxImageSide) + " pixels, got " +
                                 std::to_string(width) + "x" + std::to_string(height));
            if (x < 0 || y < 0 || x >= width || y >= height)
                throw UsageError("pixel: (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside a " +
                                 std::to_string(width) + "x" + std::to_string(height) + " image");
            const Scene copy = scene.scene();
            std::string report;
            {
                py::gil_scoped_release released;
                const trace::TraceScene prepared(copy);
                const ProbeResult probe = probePixel(prepared, width, height, x, y);
                // The Whitted tree of the pixel, as the viewer's ray view records it (probe/ray_tree_view.h).
                std::optional<RayTreeView> tree;
                if (rayTree && probe.hit) tree = recordRayTree(prepared, width, height, x, y);
                // The tracer's own coverage id stands where the viewer puts the rasterizer's.
                report = probeReportJson(probe, copy, probe.objectId, tree ? &*tree : nullptr);
            }
            return jsonTextToPython(report);
        },
        py::arg("scene"), py::arg("x"), py::arg("y"), py::arg("width"), py::arg("height"), py::arg("ray_tree") = false);
}

}  // namespace shadelab::python
