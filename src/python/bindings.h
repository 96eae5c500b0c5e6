// The parts of the _shadelab extension module, one bind function per concept (module.cpp calls them in order).
#pragma once

#include <pybind11/pybind11.h>

namespace shadelab::python {

void bindImage(pybind11::module_& m);     // Image: linear floats, 8-bit pixels, PNG (bind_image.cpp)
void bindScene(pybind11::module_& m);     // _Scene: load, documents, edits (bind_scene.cpp)
void bindRender(pybind11::module_& m);    // _Renderer, _probe (bind_render.cpp)
void bindCompare(pybind11::module_& m);   // _compare (bind_compare.cpp)
void bindLighting(pybind11::module_& m);  // _phong, _blinn_phong, _pbr, _shade (bind_lighting.cpp)
void bindFiles(pybind11::module_& m);     // _write_file, _derived_output (bind_files.cpp)

}  // namespace shadelab::python
