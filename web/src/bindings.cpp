// The page's JavaScript view of PageLab and WorkerTracer (embind). Images cross as typed-array views of the
// C++ buffers (valid until the next call that rewrites them; the page copies them into ImageData at once);
// everything else as strings and numbers. Errors come back as strings, never as exceptions, so the page's
// message line shows them and the page keeps working.
#include "page_lab.h"
#include "worker_tracer.h"

#include "util/error_line.h"

#include <emscripten/bind.h>
#include <emscripten/val.h>

namespace shadelab::web {
namespace {

using emscripten::val;

template <typename T>
val view(const std::vector<T>& data) {
    return val(emscripten::typed_memory_view(data.size(), data.data()));
}

template <typename T>
std::vector<T> copyArray(const val& array) {
    return emscripten::convertJSArrayToNumberVector<T>(array);
}

// Why the last createLab or createTracer returned null: the page shows the line (no WebGL2, a scene the
// worker could not rebuild).
std::string lastCreateError;

// A PageLab owned by the page's script (freed with .delete()), or null with lastCreateError set.
PageLab* createLab(const std::string& canvas) {
    try {
        lastCreateError.clear();
        return new PageLab(canvas);
    } catch (const std::exception& e) {
        lastCreateError = errorLine(e.what());
        return nullptr;
    }
}

val renderRaster(PageLab& lab, int width, int height) {
    try {
        return view(lab.renderRaster(width, height));
    } catch (const std::exception& e) {
        return val(errorLine(e.what()));
    }
}

// "" or the error line.
std::string drawRaster(PageLab& lab, int width, int height) {
    try {
        lab.drawRaster(width, height);
        return "";
    } catch (const std::exception& e) {
        return errorLine(e.what());
    }
}

val setReference(PageLab& lab, const val& rgb, const val& coverage, int width, int height) {
    try {
        return view(lab.setReference(copyArray<uint8_t>(rgb), copyArray<uint32_t>(coverage), width, height));
    } catch (const std::exception& e) {
        return val(errorLine(e.what()));
    }
}

val encodeGlobal(PageLab& lab, const val& rgba, int width, int height) {
    try {
        return view(lab.encodeGlobal(copyArray<float>(rgba), width, height));
    } catch (const std::exception& e) {
        return val(errorLine(e.what()));
    }
}

val differenceImage(PageLab& lab) { return view(lab.differenceImage()); }
val rasterCoverageImage(PageLab& lab) { return view(lab.rasterCoverageImage()); }

// A worker's tracer, or null with lastCreateError set.
WorkerTracer* createTracer(const std::string& sceneJson, const std::string& baseDir) {
    try {
        lastCreateError.clear();
        return new WorkerTracer(sceneJson, baseDir);
    } catch (const std::exception& e) {
        lastCreateError = errorLine(e.what());
        return nullptr;
    }
}

std::string createError() { return lastCreateError; }

// {tiles: Int32Array, rgb: Uint8Array, coverage: Uint32Array}: views of the tracer's batch (WorkerTracer::TileBatch)
// in the module's memory, valid until the next call into the module; the worker copies them into the arrays it
// sends (worker.js).
val tileBatch(const WorkerTracer& tracer) {
    const WorkerTracer::TileBatch& b = tracer.batch();
    val out = val::object();
    out.set("tiles", view(b.tiles));
    out.set("rgb", view(b.rgb));
    out.set("coverage", view(b.coverage));
    return out;
}

val globalImage(const WorkerTracer& tracer) {
    const ImageF image = tracer.globalImage();
    const size_t n = size_t(image.width) * size_t(image.height) * 4;
    return val::global("Float32Array")
        .new_(val(emscripten::typed_memory_view(n, image.width ? image.pixel(0, 0) : nullptr)));
}

val globalRows(const WorkerTracer& tracer, int first, int step) {
    return val::global("Float32Array").new_(view(tracer.globalRows(first, step)));
}

}  // namespace

EMSCRIPTEN_BINDINGS(shadelab) {
    emscripten::function("createLab", &createLab, emscripten::allow_raw_pointers());
    emscripten::function("createError", &createError);
    emscripten::class_<PageLab>("Lab")
        .function("open", &PageLab::open)
        .function("act", &PageLab::act)
        .function("setMaterialColor", &PageLab::setMaterialColor)
        .function("setLightColor", &PageLab::setLightColor)
        .function("orbit", &PageLab::orbit)
        .function("pan", &PageLab::pan)
        .function("zoom", &PageLab::zoom)
        .function("stateJson", &PageLab::stateJson)
        .function("sceneJson", &PageLab::sceneJson)
        .function("sceneDir", &PageLab::sceneDir)
        .function("referenceRevision", &PageLab::referenceRevision)
        .function("revision", &PageLab::revision)
        .function("renderRaster", &renderRaster)
        .function("drawRaster", &drawRaster)
        .function("objectAt", &PageLab::objectAt)
        .function("rasterCoverageImage", &rasterCoverageImage)
        .function("setReference", &setReference)
        .function("encodeGlobal", &encodeGlobal)
        .function("differenceImage", &differenceImage)
        .function("differenceText", &PageLab::differenceText)
        .function("probe", &PageLab::probe)
        .function("lobePlotJson", &PageLab::lobePlotJson)
        .function("albedoPlotJson", &PageLab::albedoPlotJson)
        .function("glRenderer", &PageLab::glRenderer);
    emscripten::function("createTracer", &createTracer, emscripten::allow_raw_pointers());
    emscripten::class_<WorkerTracer>("Tracer")
        .function("startReference", &WorkerTracer::startReference)
        .function("traceTile", &WorkerTracer::traceTile)
        .function("batch", &tileBatch)
        .function("clearBatch", &WorkerTracer::clearBatch)
        .function("startGlobal", &WorkerTracer::startGlobal)
        .function("addGlobalSamples", &WorkerTracer::addGlobalSamples)
        .function("globalSamples", &WorkerTracer::globalSamples)
        .function("globalImage", &globalImage)
        .function("addGlobalRowSamples", &WorkerTracer::addGlobalRowSamples)
        .function("globalRows", &globalRows);
}

}  // namespace shadelab::web
