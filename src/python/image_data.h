// ImageData: what a Python shadelab.Image holds: the linear floats, the 8-bit pixels made from them by the one
// conversion (image/encode.h) with the encoding they used, and optionally coverage ids. Plain data.
#pragma once

#include "image/encoding.h"
#include "image/image.h"
#include "image/view_transform.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shadelab::python {

struct ImageData {
    ImageF linear;  // RGBA, linear RGB; for an image read from a file, its pixels decoded
    Image8 pixels;  // RGB (RGBA when read from an RGBA file): exactly what the binary's PNG holds
    Encoding encoding = Encoding::Srgb;
    DisplaySettings display;         // the exposure and view transform the 8-bit pixels were made with (Standard: none)
    std::vector<uint32_t> coverage;  // width x height ids (scene/coverage.h) when asked for; else empty
    std::string source;              // "raster", "trace", "path", "file" or "array"
    double drawMs = 0.0;             // raster: draw (glFinish'ed); trace: the whole trace
    double readMs = 0.0;             // raster: readback + conversion; trace: conversion
    uint64_t nonFinite = 0;          // pixels whose linear value had a NaN or infinity (toImage8)
};

}  // namespace shadelab::python
