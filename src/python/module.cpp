// The _shadelab extension module: Python access to the same module libraries the shadelab binary links. The
// pure-Python package (python/shadelab/) is the public face; names starting with _ here are its plumbing.
#include "gl/headless_context.h"
#include "python/bindings.h"
#include "util/input_error.h"

#include <string>

namespace py = pybind11;

PYBIND11_MODULE(_shadelab, m) {
    m.doc() = "shadelab's compiled core; use the shadelab package, not this module";

    // Bad input (a scene field, a file) is a ValueError naming the file and the JSON path, as the binary's
    // one-line errors do; a bad argument is a plain ValueError; no GL context at all is a RuntimeError.
    static py::exception<shadelab::InputError> inputError(m, "InputError", PyExc_ValueError);
    static py::exception<shadelab::gl::ContextError> contextError(m, "ContextError", PyExc_RuntimeError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const shadelab::InputError& e) {
            PyErr_SetString(inputError.ptr(), e.what());
        } catch (const shadelab::UsageError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const shadelab::gl::ContextError& e) {
            PyErr_SetString(contextError.ptr(), e.what());
        } catch (const py::cast_error& e) {
            // An object made by __new__ alone (a pickle whose state is None skips __setstate__) holds nothing:
            // its methods take the holder, which pybind11 refuses to cast. Say so in one line.
            const std::string what = e.what();
            PyErr_SetString(PyExc_TypeError,
                            what.find("non-held to held") != std::string::npos
                                ? "this shadelab object was never initialised (made by __new__ without __init__ or "
                                  "__setstate__)"
                                : what.c_str());
        }
    });

    shadelab::python::bindImage(m);
    shadelab::python::bindScene(m);
    shadelab::python::bindRender(m);
    shadelab::python::bindCompare(m);
    shadelab::python::bindLighting(m);
    shadelab::python::bindFiles(m);

    py::dict build;
    build["version"] = SHADELAB_VERSION;
    build["build_type"] = SHADELAB_BUILD_TYPE;
    build["sanitize"] = SHADELAB_SANITIZE_FLAGS;  // e.g. "address,undefined" in build-asan
    m.attr("build_info") = build;
}
