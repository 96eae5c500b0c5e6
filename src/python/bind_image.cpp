// shadelab.Image: np.asarray(image) is the linear float32 (H, W, 3) view, to_uint8() the 8-bit pixels the binary's
// PNG holds, save() and _repr_png_ the PNG (image/png.h), or save("x.exr") the linear floats (image/exr.h). Images
// also come from PNG and EXR files and numpy arrays.
#include "image/encode.h"
#include "image/exr.h"
#include "image/png.h"
#include "python/bindings.h"
#include "python/image_data.h"
#include "util/input_error.h"
#include "util/output_file.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace py = pybind11;

namespace shadelab::python {
namespace {

using ImagePtr = std::shared_ptr<ImageData>;

Encoding encodingNamed(const std::string& name) {
    if (std::optional<Encoding> e = parseEncoding(name)) return *e;
    throw UsageError("encoding: unknown encoding '" + name + "'; expected " + nameChoices(kEncodingNames));
}

// The linear floats of 8-bit pixels: decoded with the encoding's curve (exact for the levels, not for the floats a
// render had before it was quantised).
ImageF decode(const Image8& p, Encoding e) {
    ImageF f(p.width, p.height);
    for (int y = 0; y < p.height; ++y)
        for (int x = 0; x < p.width; ++x) {
            const uint8_t* src = p.pixel(x, y);
            float* dst = f.pixel(x, y);
            for (int c = 0; c < 3; ++c) {
                const float v = float(src[c]) / 255.0f;
                dst[c] = e == Encoding::Srgb ? srgbToLinear(v) : v;
            }
            dst[3] = p.channels == 4 ? float(src[3]) / 255.0f : 1.0f;
        }
    return f;
}

ImagePtr fromUint8(py::array_t<uint8_t, py::array::c_style | py::array::forcecast> a, Encoding e) {
    if (a.ndim() != 3 || (a.shape(2) != 3 && a.shape(2) != 4) || a.shape(0) < 1 || a.shape(1) < 1)
        throw UsageError("from_array: a uint8 array must have shape (H, W, 3) or (H, W, 4)");
    auto img = std::make_shared<ImageData>();
    img->pixels.height = int(a.shape(0));
    img->pixels.width = int(a.shape(1));
    img->pixels.channels = int(a.shape(2));
    img->pixels.data.assign(a.data(), a.data() + a.size());
    img->linear = decode(img->pixels, e);
    img->encoding = e;
    img->source = "array";
    return img;
}

ImagePtr fromFloat(py::array_t<float, py::array::c_style | py::array::forcecast> a, Encoding e) {
    if (a.ndim() != 3 || (a.shape(2) != 3 && a.shape(2) != 4) || a.shape(0) < 1 || a.shape(1) < 1)
        throw UsageError("from_array: a float array must have shape (H, W, 3) or (H, W, 4), linear RGB");
    auto img = std::make_shared<ImageData>();
    const int h = int(a.shape(0)), w = int(a.shape(1)), c = int(a.shape(2));
    img->linear = ImageF(w, h);
    const float* src = a.data();
    for (size_t i = 0; i < size_t(w) * size_t(h); ++i) {
        for (int k = 0; k < 3; ++k) img->linear.rgba[i * 4 + size_t(k)] = src[i * size_t(c) + size_t(k)];
        img->linear.rgba[i * 4 + 3] = c == 4 ? src[i * size_t(c) + 3] : 1.0f;
    }
    img->pixels = toImage8(img->linear, e, DisplaySettings{}, &img->nonFinite);
    img->encoding = e;
    img->source = "array";
    return img;
}

py::array uint8Array(const ImagePtr& img) {
    const Image8& p = img->pixels;
    py::array_t<uint8_t> out({size_t(p.height), size_t(p.width), size_t(p.channels)});
    std::memcpy(out.mutable_data(), p.data.data(), p.data.size());
    return std::move(out);
}

// The linear floats through the 8-bit conversion's steps but the rounding (image/encode.h displayEncoded): the
// image's exposure and view transform, the clamp, the sRGB curve; float32 (H, W, 3) in [0, 1].
py::array_t<float> srgbArray(const ImagePtr& img) {
    const ImageF& f = img->linear;
    py::array_t<float> out({size_t(f.height), size_t(f.width), size_t(3)});
    float* dst = out.mutable_data();
    const size_t n = size_t(f.width) * size_t(f.height);
    for (size_t i = 0; i < n; ++i)
        for (size_t c = 0; c < 3; ++c) dst[3 * i + c] = displayEncoded(f.rgba[4 * i + c], Encoding::Srgb, img->display);
    return out;
}

py::bytes pngBytes(const ImageData& img) {
    const std::vector<uint8_t> png = encodePng(img.pixels);
    return py::bytes(reinterpret_cast<const char*>(png.data()), png.size());
}

template <typename T>
py::bytes rawBytes(const std::vector<T>& v) {
    return py::bytes(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

template <typename T>
std::vector<T> fromRaw(const std::string& s) {
    std::vector<T> v(s.size() / sizeof(T));
    if (!v.empty()) std::memcpy(v.data(), s.data(), v.size() * sizeof(T));  // no coverage: no buffer at all
    return v;
}

// A pickle state that no Image could have written: one ValueError line.
py::value_error badState(const std::string& reason) {
    return py::value_error("shadelab.Image: bad pickle state: " + reason);
}

std::string typeName(const py::handle& h) { return py::str(py::type::of(h).attr("__name__")); }

// A pickle state's bytes item, or the one-line refusal naming it.
std::string stateBytes(const py::tuple& t, size_t i, const char* what) {
    if (!py::isinstance<py::bytes>(t[i])) throw badState(std::string(what) + " must be bytes, got " + typeName(t[i]));
    return t[i].cast<std::string>();
}

// A pickle state's number item (a float or an int), or the one-line refusal naming it.
double stateNumber(const py::tuple& t, size_t i, const char* what) {
    if (py::isinstance<py::bool_>(t[i]) || !(py::isinstance<py::float_>(t[i]) || py::isinstance<py::int_>(t[i])))
        throw badState(std::string(what) + " must be a number, got " + typeName(t[i]));
    return t[i].cast<double>();
}

// A path argument as Python gives it (str, bytes or os.PathLike), else one TypeError line naming it.
std::filesystem::path pathArg(const char* name, const py::handle& v) {
    if (py::isinstance<py::str>(v) || py::isinstance<py::bytes>(v) || py::hasattr(v, "__fspath__")) {
        const py::module_ os = py::module_::import("os");
        return std::filesystem::path(os.attr("fsdecode")(os.attr("fspath")(v)).cast<std::string>());
    }
    throw py::type_error(std::string(name) + ": expected a path (str or os.PathLike), got " + typeName(v));
}

// An encoding's name as Python gives it, else one TypeError line; the word itself is encodingNamed's to check.
Encoding encodingArg(const py::handle& v) {
    if (!py::isinstance<py::str>(v)) throw py::type_error("encoding: expected a string, got " + typeName(v));
    return encodingNamed(v.cast<std::string>());
}

// The inverse of __getstate__, for a state that may have been tampered with: every field is checked before any
// pixel is touched, so that no later call (save, compare, np.asarray) meets sizes or lengths it cannot trust.
ImagePtr fromPickleState(const py::object& state) {
    // 12 items; 10 from a release before images kept their display (Standard).
    if (!py::isinstance<py::tuple>(state)) throw badState("expected a tuple of 12 items, got " + typeName(state));
    const py::tuple t = state;
    if (t.size() != 12 && t.size() != 10)
        throw badState("expected a tuple of 12 items, got " + std::to_string(t.size()));
    if (!py::isinstance<py::int_>(t[0]) || !py::isinstance<py::int_>(t[1]) || !py::isinstance<py::int_>(t[2]) ||
        py::isinstance<py::bool_>(t[0]) || py::isinstance<py::bool_>(t[1]) || py::isinstance<py::bool_>(t[2]))
        throw badState("width, height and channels must be integers");
    // Python ints of any size: compared as Python objects first, so that a huge one cannot wrap on the way in.
    const auto side = [&](size_t i, const char* what) {
        const py::int_ v = t[i];
        if (v < py::int_(1) || v > py::int_(kMaxImageSide))
            throw badState(std::string(what) + " must be 1.." + std::to_string(kMaxImageSide) + " pixels, got " +
                           std::string(py::repr(v)));
        return v.cast<int>();
    };
    const int width = side(0, "width"), height = side(1, "height");
    const py::int_ channelsValue = t[2];
    if (!(channelsValue.equal(py::int_(3)) || channelsValue.equal(py::int_(4))))
        throw badState("channels must be 3 (RGB) or 4 (RGBA), got " + std::string(py::repr(channelsValue)));
    const int channels = channelsValue.cast<int>();
    // Sizes are at most kMaxImageSide² × 16 bytes (2^32): size_t holds every product below.
    const size_t pixels = size_t(width) * size_t(height);
    const auto bytesOf = [&](size_t i, const char* what, size_t expected, bool optional) {
        const std::string b = stateBytes(t, i, what);
        if (b.size() != expected && !(optional && b.empty()))
            throw badState(std::string(what) + " must be " + std::to_string(expected) + " bytes for a " +
                           std::to_string(width) + "x" + std::to_string(height) + " image, got " +
                           std::to_string(b.size()));
        return b;
    };
    const std::string data = bytesOf(3, "pixels", pixels * size_t(channels), false);
    const std::string linear = bytesOf(4, "linear floats", pixels * 4 * sizeof(float), false);
    const std::string coverage = bytesOf(7, "coverage", pixels * sizeof(uint32_t), true);
    if (!py::isinstance<py::str>(t[5]) || !py::isinstance<py::str>(t[6]))
        throw badState("encoding and source must be strings");
    const std::string encoding = t[5].cast<std::string>(), source = t[6].cast<std::string>();
    const std::optional<Encoding> e = parseEncoding(encoding);
    if (!e) throw badState("unknown encoding '" + encoding.substr(0, 32) + "'");
    if (source != "raster" && source != "trace" && source != "path" && source != "file" && source != "array")
        throw badState("unknown source '" + source.substr(0, 32) + "'");
    auto img = std::make_shared<ImageData>();
    img->pixels.width = img->linear.width = width;
    img->pixels.height = img->linear.height = height;
    img->pixels.channels = channels;
    img->pixels.data.assign(data.begin(), data.end());
    img->linear.rgba = fromRaw<float>(linear);
    img->coverage = fromRaw<uint32_t>(coverage);
    img->encoding = *e;
    img->source = source;
    img->drawMs = stateNumber(t, 8, "draw_ms");
    img->readMs = stateNumber(t, 9, "read_ms");
    if (t.size() == 12) {
        img->display.exposure = stateNumber(t, 10, "exposure");
        if (std::optional<std::string> why = exposureProblem(img->display.exposure)) throw badState("exposure " + *why);
        if (!py::isinstance<py::str>(t[11])) throw badState("view transform must be a string");
        const std::string transform = t[11].cast<std::string>();
        const std::optional<ViewTransform> v = parseViewTransform(transform);
        if (!v) throw badState("unknown view transform '" + transform.substr(0, 32) + "'");
        img->display.transform = *v;
    }
    return img;
}

}  // namespace

void bindImage(py::module_& m) {
    py::class_<ImageData, ImagePtr>(m, "Image", py::buffer_protocol(), R"(A rendered (or read) image.

np.asarray(image) is its linear RGB as float32, shape (H, W, 3), read-only; image.to_uint8() the 8-bit pixels,
encoded as image.encoding says (exactly the bytes `shadelab render` writes); image.save(path) writes the PNG.
In Jupyter an image shows itself.)")
        .def_buffer([](ImageData& img) {
            ImageF& f = img.linear;
            return py::buffer_info(
                f.rgba.data(), sizeof(float), py::format_descriptor<float>::format(), 3,
                {ssize_t(f.height), ssize_t(f.width), ssize_t(3)},
                {ssize_t(sizeof(float)) * 4 * f.width, ssize_t(sizeof(float)) * 4, ssize_t(sizeof(float))},
                /*readonly=*/true);
        })
        .def_property_readonly("width", [](const ImagePtr& held) { return held->pixels.width; })
        .def_property_readonly("height", [](const ImagePtr& held) { return held->pixels.height; })
        .def_property_readonly(
            "size", [](const ImagePtr& held) { return py::make_tuple(held->pixels.width, held->pixels.height); },
            "(width, height), as render(size=...) takes it")
        .def_property_readonly(
            "shape", [](const ImagePtr& held) { return py::make_tuple(held->pixels.height, held->pixels.width, 3); },
            "(H, W, 3): the shape of np.asarray(image)")
        .def_property_readonly("encoding", [](const ImagePtr& held) { return std::string(toString(held->encoding)); })
        .def_property_readonly(
            "source", [](const ImagePtr& held) { return held->source; }, "'raster', 'trace', 'path', 'file' or 'array'")
        .def_property_readonly(
            "coverage",
            [](const ImagePtr& held) -> py::object {
                const ImageData& i = *held;
                if (i.coverage.empty()) return py::none();
                py::array_t<uint32_t> out({size_t(i.pixels.height), size_t(i.pixels.width)});
                std::memcpy(out.mutable_data(), i.coverage.data(), i.coverage.size() * sizeof(uint32_t));
                return std::move(out);
            },
            "Per-pixel object ids (uint32, (H, W); 0 = background) when rendered with coverage=True, else None")
        .def_property_readonly(
            "timings",
            [](const ImagePtr& held) {
                const ImageData& i = *held;
                py::dict d;
                d["draw_ms"] = i.drawMs;
                d["read_ms"] = i.readMs;
                return d;
            },
            "Milliseconds: raster draw (finished) and readback + conversion; trace: tracing and conversion")
        .def_property_readonly(
            "non_finite_pixels", [](const ImagePtr& held) { return held->nonFinite; },
            "Pixels whose linear value had a NaN or an infinity (written black or white); render warns when > 0")
        .def_property_readonly("_non_finite_message",
                               [](const ImagePtr& held) {
                                   return nonFiniteMessage(
                                       held->nonFinite, uint64_t(held->pixels.width) * uint64_t(held->pixels.height));
                               })
        .def("to_uint8", &uint8Array, "The 8-bit pixels, shape (H, W, 3) (or 4 for an RGBA file), a new array")
        .def("to_srgb", &srgbArray,
             "Display-ready sRGB floats in [0, 1], float32 (H, W, 3), a new array: the linear floats through the "
             "image's exposure and view transform, the clamp and the sRGB curve, the PNG's steps before rounding")
        .def_property_readonly(
            "exposure", [](const ImagePtr& held) { return held->display.exposure; },
            "Stops the 8-bit pixels were exposed by (the render's exposure, else the scene's; 0 for a file)")
        .def_property_readonly(
            "view_transform", [](const ImagePtr& held) { return std::string(toString(held->display.transform)); },
            "The view transform the 8-bit pixels were made with: 'standard' or 'filmic'")
        .def(
            "to_png", [](const ImagePtr& held) { return pngBytes(*held); }, "The PNG file's bytes")
        .def("_repr_png_", [](const ImagePtr& held) { return pngBytes(*held); })
        .def(
            "save",
            [](const ImageData& i, const py::object& pathObject, const py::object& precisionObject) {
                const std::filesystem::path path = pathArg("path", pathObject);
                const bool exr = hasExrExtension(path.string());
                std::optional<ExrPrecision> precision;
                if (!precisionObject.is_none()) {
                    if (!py::isinstance<py::str>(precisionObject))
                        throw py::type_error("exr_precision: expected a string, got " + typeName(precisionObject));
                    precision = lookupName(kExrPrecisionNames, precisionObject.cast<std::string>());
                    if (!precision)
                        throw UsageError("exr_precision: expected " + nameChoices(kExrPrecisionNames) + ", got '" +
                                         precisionObject.cast<std::string>() + "'");
                    if (!exr) throw UsageError("exr_precision: only for an .exr path (this one writes a PNG)");
                }
                try {
                    createOutputFolder(path.string());  // as `render -o out/x.png` does
                    if (exr)
                        writeExr(path.string(), exrFromImage(i.linear), precision.value_or(ExrPrecision::Float));
                    else
                        writePng(path.string(), i.pixels);
                } catch (const InputError& e) {
                    PyErr_SetString(PyExc_OSError, e.what());  // the message names the file and the reason
                    throw py::error_already_set();
                }
            },
            py::arg("path"), py::arg("exr_precision") = py::none(),
            "Writes atomically: a path ending in .exr the linear floats as OpenEXR (exr_precision 'float', the "
            "default, or 'half'), any other the PNG (the bytes `shadelab render -o` writes)")
        .def_static(
            "open",
            [](const py::object& path, const py::object& encoding) {
                auto img = std::make_shared<ImageData>();
                const Encoding e = encodingArg(encoding);
                const std::string p = pathArg("path", path).string();
                img->encoding = e;
                if (hasExrExtension(p)) {
                    // The file's linear floats as they are; the 8-bit pixels through the one conversion.
                    img->linear = colourOf(readExr(p), p);
                    img->pixels = toImage8(img->linear, e, DisplaySettings{}, &img->nonFinite);
                } else {
                    img->pixels = readPng(p);
                    img->linear = decode(img->pixels, img->encoding);
                }
                img->source = "file";
                return img;
            },
            py::arg("path"), py::arg("encoding") = "srgb",
            "Reads a PNG (np.asarray gives its pixels decoded with `encoding`'s curve) or an OpenEXR file (.exr: "
            "np.asarray gives its linear floats, the 8-bit pixels are encoded with `encoding`)")
        .def_static(
            "from_array",
            [](const py::object& array, const py::object& encoding) {
                // Anything numpy makes an array of (a list of lists too); else one TypeError line, not
                // pybind11's list of signatures.
                py::array a = py::array::ensure(array);
                if (!a) {
                    PyErr_Clear();
                    throw py::type_error("from_array: expected a numpy array (H, W, 3 or 4) of uint8 or float, got " +
                                         typeName(array));
                }
                const Encoding e = encodingArg(encoding);
                if (a.dtype().kind() == 'u' && a.dtype().itemsize() == 1) return fromUint8(a, e);
                if (a.dtype().kind() == 'f') return fromFloat(a, e);
                throw UsageError("from_array: expected a uint8 (levels) or float (linear) array, got dtype " +
                                 std::string(py::str(a.dtype())));
            },
            py::arg("array"), py::arg("encoding") = "srgb",
            "uint8 (H, W, 3|4): the pixels as they are; float (H, W, 3|4): linear RGB, encoded with `encoding`")
        .def("__repr__",
             [](const ImagePtr& held) {
                 return "<shadelab.Image " + std::to_string(held->pixels.width) + "x" +
                        std::to_string(held->pixels.height) + " " + toString(held->encoding) + " from " + held->source +
                        ">";
             })
        .def(py::pickle(
            [](const ImagePtr& held) -> py::object {
                const ImageData& i = *held;  // a tuple; typed as the state __setstate__ checks
                return py::make_tuple(i.pixels.width, i.pixels.height, i.pixels.channels, rawBytes(i.pixels.data),
                                      rawBytes(i.linear.rgba), std::string(toString(i.encoding)), i.source,
                                      rawBytes(i.coverage), i.drawMs, i.readMs, i.display.exposure,
                                      std::string(toString(i.display.transform)));
            },
            [](const py::object& state) { return fromPickleState(state); }));
}

}  // namespace shadelab::python
