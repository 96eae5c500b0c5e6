// PathRender: tiles handed to workers through an atomic counter; per-pixel sums in sample order.
#include "trace/path/path_render.h"

#include "image/encode.h"
#include "scene/coverage.h"
#include "shading/lighting.h"
#include "trace/first_hit_passes.h"
#include "trace/path/path_denoise.h"
#include "trace/tile_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace shadelab::trace {
namespace {

// Bits of the pixel jitter's group (SampleRng::draw): apart from every vertex's groups.
constexpr uint32_t kGroupCamera = 0xFFu;

Ray cameraRay(const ViewSetup& v, float px, float py) {
    return Ray{v.eye, shading::cameraRayDirection(v.forward, v.right, v.up, v.tanHalfFovY, float(v.width),
                                                  float(v.height), px, py)};
}

}  // namespace

PathRender::PathRender(std::shared_ptr<const TraceScene> scene, const PathSettings& settings)
    : scene_(std::move(scene)), settings_(settings) {
    validate(settings_);
    if (settings_.maxDepth < 0) settings_.maxDepth = scene_->scene().maxDepth;
    if (settings_.threads == 0) {
        const unsigned n = std::thread::hardware_concurrency();
        settings_.threads = n > 0 ? int(n) : 1;
    }
    view_ = makeViewSetup(scene_->scene(), settings_.width, settings_.height);
    // Built once: its emitter and environment distributions serve every pass.
    integrator_ = std::make_unique<PathIntegrator>(*scene_, settings_);
    integrator_->setPixelFootprint(pixelFootprint(view_));
    const size_t n = size_t(settings_.width) * size_t(settings_.height);
    sum_.assign(3 * n, 0.0);
    sumSq_.assign(3 * n, 0.0);
    count_.reset(new std::atomic<uint32_t>[n]);
    for (size_t i = 0; i < n; ++i) count_[i].store(0u, std::memory_order_relaxed);
    if (settings_.coverage) {
        coverage_.assign(n, kBackgroundId);
        for (int y = 0; y < settings_.height; ++y)
            for (int x = 0; x < settings_.width; ++x)
                if (const std::optional<Hit> h = scene_->intersect(cameraRay(view_, float(x) + 0.5f, float(y) + 0.5f)))
                    coverage_[size_t(y) * size_t(settings_.width) + size_t(x)] = scene_->coverageId(*h);
    }
}

void PathRender::renderPixel(int x, int y, int count) {
    const size_t p = size_t(y) * size_t(settings_.width) + size_t(x);
    SampleRng rng;
    rng.pixel = uint32_t(p);
    rng.seed = settings_.seed;
    rng.sampler = settings_.sampler;
    for (int k = 0; k < count; ++k) {
        const uint32_t done = count_[p].load(std::memory_order_relaxed);
        rng.sample = done;
        const glm::vec4 j = rng.draw(0, kGroupCamera);
        const glm::vec3 c = integrator_->trace(cameraRay(view_, float(x) + j.x, float(y) + j.y), rng).color;
        for (int ch = 0; ch < 3; ++ch) {
            sum_[3 * p + size_t(ch)] += double(c[ch]);
            sumSq_[3 * p + size_t(ch)] += double(c[ch]) * double(c[ch]);
        }
        count_[p].store(done + 1, std::memory_order_release);
    }
}

bool PathRender::addSamples(int count, const std::atomic<bool>* cancel, const std::function<void(float)>& progress) {
    if (count <= 0) return true;
    const std::vector<Tile> tiles = makeTiles(settings_.width, settings_.height, settings_.tileSize);
    std::atomic<size_t> next{0}, done{0};
    std::atomic<bool> stopped{false};
    std::mutex mutex;
    std::condition_variable finished;
    auto worker = [&] {
        for (size_t t; !stopped.load() && (t = next.fetch_add(1)) < tiles.size();) {
            const Tile& tile = tiles[t];
            for (int y = tile.y0; y < tile.y0 + tile.height && !stopped.load(); ++y)
                for (int x = tile.x0; x < tile.x0 + tile.width; ++x) {
                    if (cancel && cancel->load(std::memory_order_relaxed)) {
                        stopped = true;
                        break;
                    }
                    renderPixel(x, y, count);
                }
            done.fetch_add(1);
        }
        std::lock_guard<std::mutex> lock(mutex);
        finished.notify_all();
    };
    // With a progress callback every worker is a thread and this one reports; else this one works too.
    std::vector<std::thread> workers;
    for (int i = progress ? 0 : 1; i < settings_.threads; ++i) workers.emplace_back(worker);
    if (progress) {
        std::unique_lock<std::mutex> lock(mutex);
        auto over = [&] { return done.load() >= tiles.size() || stopped.load(); };
        while (!over()) {
            finished.wait_for(lock, std::chrono::milliseconds(50), over);
            progress(float(done.load()) / float(tiles.size()));
        }
    } else {
        worker();
    }
    for (std::thread& w : workers) w.join();
    return !stopped.load();
}

void PathRender::addSamplesToRows(int count, int first, int step) {
    if (count <= 0 || step <= 0 || first < 0) return;
    for (int y = first; y < settings_.height; y += step)
        for (int x = 0; x < settings_.width; ++x) renderPixel(x, y, count);
}

int PathRender::samples() const {
    uint32_t fewest = ~0u;
    const size_t n = size_t(settings_.width) * size_t(settings_.height);
    for (size_t i = 0; i < n; ++i) fewest = std::min(fewest, count_[i].load(std::memory_order_acquire));
    return n == 0 ? 0 : int(fewest);
}

glm::vec3 PathRender::mean(int x, int y) const {
    const size_t p = size_t(y) * size_t(settings_.width) + size_t(x);
    const uint32_t count = count_[p].load(std::memory_order_acquire);
    if (count == 0) return glm::vec3(0.0f);
    const double n = double(count);
    return {float(sum_[3 * p] / n), float(sum_[3 * p + 1] / n), float(sum_[3 * p + 2] / n)};
}

double PathRender::meanStandardError8(Encoding encoding) const {
    auto encode = [encoding](float v) {
        v = std::clamp(v, 0.0f, 1.0f);
        return encoding == Encoding::Srgb ? linearToSrgb(v) : v;
    };
    double total = 0.0;
    for (int y = 0; y < settings_.height; ++y)
        for (int x = 0; x < settings_.width; ++x) {
            const glm::vec3 m = mean(x, y), se = standardError(x, y);
            for (int ch = 0; ch < 3; ++ch) total += 127.5 * double(encode(m[ch] + se[ch]) - encode(m[ch] - se[ch]));
        }
    return total / (3.0 * double(settings_.width) * double(settings_.height));
}

PathOutput pathTraceImage(std::shared_ptr<const TraceScene> scene, const PathSettings& settings,
                          const std::function<void(float)>& progress) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    PathRender render(scene, settings);
    if (settings.timeLimit <= 0.0) {
        render.addSamples(settings.spp, nullptr, progress);
    } else {
        // One sample per pass: the limit ends the render at a whole sample count.
        const auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
        for (int k = 0; k < settings.spp && (k == 0 || elapsed() < settings.timeLimit); ++k) {
            render.addSamples(1, nullptr,
                              progress ? std::function<void(float)>([&](float f) {
                                  const float byTime = float(std::min(1.0, (elapsed()) / settings.timeLimit));
                                  progress(std::max(byTime, (float(k) + f) / float(settings.spp)));
                              })
                                       : std::function<void(float)>());
        }
    }
    if (progress) progress(1.0f);
    PathOutput out;
    out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    out.color = render.image();
    out.coverage = render.coverage();
    out.spp = render.samples();
    out.meanStandardError8 = render.meanStandardError8(Encoding::Srgb);
    out.variance = luminanceVariance(render);
    if (settings.denoise) {
        out.passes = firstHitPasses(*scene, render.width(), render.height(), render.settings().threads);
        DenoiseSettings d;
        d.threads = render.settings().threads;
        out.raw = std::move(out.color);
        out.color = denoisedImage(render, out.variance, out.passes, d);
    }
    return out;
}

}  // namespace shadelab::trace
