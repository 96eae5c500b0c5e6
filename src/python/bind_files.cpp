// _write_file and _derived_output: how the pure-Python package writes its own files (a compare report's
// JSON, the pytest plugin's baselines and evidence), through the same atomic writer and the same output rules
// as the binary: no output replaces a file a live scene reads (util/input_files.h), a device or stdout never
// names derived outputs (util/output_file.h).
#include "python/bindings.h"
#include "util/atomic_file.h"
#include "util/output_file.h"

#include <string>

namespace py = pybind11;

namespace shadelab::python {

void bindFiles(py::module_& m) {
    m.def(
        "_write_file",
        [](const std::string& path, const py::bytes& data) {
            const std::string bytes = data;
            py::gil_scoped_release release;
            createOutputFolder(path);
            writeFileAtomic(path, bytes);
        },
        py::arg("path"), py::arg("data"));
    m.def("_derived_output", &derivedOutput, py::arg("stem"), py::arg("suffix"));
}

}  // namespace shadelab::python
