// shadelab.Image: np.asarray(image) is the linear float32 (H, W, 3) view, to_uint8() the 8-bit pixels the binary's
// PNG holds, save() and _repr_png_ the PNG (image/png.h). Images also come from PNG files and numpy arrays.
#include "image/encode.h"
#include "image/png.h"
#include "python/bindings.h"
#include "python/image_data.h"
#include "util/input_error.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstring>
#include <filesystem>
#include <memory>

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
    img->pixels = toImage8(img->linear, e, &img->nonFinite);
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

py::bytes pngBytes(const ImageData& img) {
    const std::vector<uint8_t> png = encodePng(img.pixels);
    return py::bytes(reinterpret_cast<const char*>(png.data()), png.size());
}

template <typename T>
py::bytes rawBytes(const std::vector<T>& v) {
    return py::bytes(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

template <typename T>
std::vector<T> fromRaw(const py::bytes& b) {
    const std::string s = b;
    std::vector<T> v(s.size() / sizeof(T));
    std::memcpy(v.data(), s.data(), v.size() * sizeof(T));
    return v;
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
        .def_property_readonly("width", [](const ImageData& i) { return i.pixels.width; })
        .def_property_readonly("height", [](const ImageData& i) { return i.pixels.height; })
        .def_property_readonly(
            "size", [](const ImageData& i) { return py::make_tuple(i.pixels.width, i.pixels.height); },
            "(width, height), as render(size=...) takes it")
        .def_property_readonly(
            "shape", [](const ImageData& i) { return py::make_tuple(i.pixels.height, i.pixels.width, 3); },
            "(H, W, 3): the shape of np.asarray(image)")
        .def_property_readonly("encoding", [](const ImageData& i) { return std::string(toString(i.encoding)); })
        .def_property_readonly(
            "source", [](const ImageData& i) { return i.source; }, "'raster', 'trace', 'path', 'file' or 'array'")
        .def_property_readonly(
            "coverage",
            [](const ImageData& i) -> py::object {
                if (i.coverage.empty()) return py::none();
                py::array_t<uint32_t> out({size_t(i.pixels.height), size_t(i.pixels.width)});
                std::memcpy(out.mutable_data(), i.coverage.data(), i.coverage.size() * sizeof(uint32_t));
                return std::move(out);
            },
            "Per-pixel object ids (uint32, (H, W); 0 = background) when rendered with coverage=True, else None")
        .def_property_readonly(
            "timings",
            [](const ImageData& i) {
                py::dict d;
                d["draw_ms"] = i.drawMs;
                d["read_ms"] = i.readMs;
                return d;
            },
            "Milliseconds: raster draw (finished) and readback + conversion; trace: tracing and conversion")
        .def_property_readonly(
            "non_finite_pixels", [](const ImageData& i) { return i.nonFinite; },
            "Pixels whose linear value had a NaN or an infinity (written black or white); render warns when > 0")
        .def_property_readonly("_non_finite_message",
                               [](const ImageData& i) {
                                   return nonFiniteMessage(i.nonFinite,
                                                           uint64_t(i.pixels.width) * uint64_t(i.pixels.height));
                               })
        .def("to_uint8", &uint8Array, "The 8-bit pixels, shape (H, W, 3) (or 4 for an RGBA file), a new array")
        .def(
            "to_png", [](const ImageData& i) { return pngBytes(i); }, "The PNG file's bytes")
        .def("_repr_png_", [](const ImageData& i) { return pngBytes(i); })
        .def(
            "save",
            [](const ImageData& i, const std::filesystem::path& path) {
                try {
                    writePng(path.string(), i.pixels);
                } catch (const InputError& e) {
                    PyErr_SetString(PyExc_OSError, e.what());  // the message names the file and the reason
                    throw py::error_already_set();
                }
            },
            py::arg("path"), "Writes the PNG atomically (the bytes `shadelab render -o` writes)")
        .def_static(
            "open",
            [](const std::filesystem::path& path, const std::string& encoding) {
                auto img = std::make_shared<ImageData>();
                img->pixels = readPng(path.string());
                img->encoding = encodingNamed(encoding);
                img->linear = decode(img->pixels, img->encoding);
                img->source = "file";
                return img;
            },
            py::arg("path"), py::arg("encoding") = "srgb",
            "Reads a PNG; np.asarray gives its pixels decoded with `encoding`'s curve")
        .def_static(
            "from_array",
            [](py::array a, const std::string& encoding) {
                const Encoding e = encodingNamed(encoding);
                if (a.dtype().kind() == 'u' && a.dtype().itemsize() == 1) return fromUint8(a, e);
                if (a.dtype().kind() == 'f') return fromFloat(a, e);
                throw UsageError("from_array: expected a uint8 (levels) or float (linear) array, got dtype " +
                                 std::string(py::str(a.dtype())));
            },
            py::arg("array"), py::arg("encoding") = "srgb",
            "uint8 (H, W, 3|4): the pixels as they are; float (H, W, 3|4): linear RGB, encoded with `encoding`")
        .def("__repr__",
             [](const ImageData& i) {
                 return "<shadelab.Image " + std::to_string(i.pixels.width) + "x" + std::to_string(i.pixels.height) +
                        " " + toString(i.encoding) + " from " + i.source + ">";
             })
        .def(py::pickle(
            [](const ImageData& i) {
                return py::make_tuple(i.pixels.width, i.pixels.height, i.pixels.channels, rawBytes(i.pixels.data),
                                      rawBytes(i.linear.rgba), std::string(toString(i.encoding)), i.source,
                                      rawBytes(i.coverage), i.drawMs, i.readMs);
            },
            [](const py::tuple& t) {
                if (t.size() != 10) throw std::runtime_error("shadelab.Image: bad pickle state");
                auto img = std::make_shared<ImageData>();
                img->pixels.width = img->linear.width = t[0].cast<int>();
                img->pixels.height = img->linear.height = t[1].cast<int>();
                img->pixels.channels = t[2].cast<int>();
                img->pixels.data = fromRaw<uint8_t>(t[3]);
                img->linear.rgba = fromRaw<float>(t[4]);
                img->encoding = encodingNamed(t[5].cast<std::string>());
                img->source = t[6].cast<std::string>();
                img->coverage = fromRaw<uint32_t>(t[7]);
                img->drawMs = t[8].cast<double>();
                img->readMs = t[9].cast<double>();
                const size_t pixels = size_t(img->pixels.width) * size_t(img->pixels.height);
                if (img->pixels.data.size() != pixels * size_t(img->pixels.channels) ||
                    img->linear.rgba.size() != pixels * 4 || (!img->coverage.empty() && img->coverage.size() != pixels))
                    throw std::runtime_error("shadelab.Image: bad pickle state");
                return img;
            }));
}

}  // namespace shadelab::python
