#include <volume_reference/ReferenceRenderer.h>

#include "Integrator.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace volren {

using reference::Integrator;
using reference::Ray;
using reference::ShadowTally;
using reference::toGlm;

ReferenceImage renderReference(const ReferenceScene& scene, const ReferenceCamera& camera, const ReferenceOptions& options)
{
    ReferenceImage image;
    image.width = camera.width;
    image.height = camera.height;
    image.rgba.assign(std::size_t(camera.width) * camera.height * 4, 0.0);
    const Integrator integrator(scene, camera, options);
    const osg::Matrixd clipToWorld = osg::Matrixd::inverse(camera.view * camera.projection);

    const std::size_t pixels = std::size_t(camera.width) * camera.height;
    const bool withGeometry = !options.geometryDepth.empty();
    if (withGeometry && (options.geometryDepth.size() != pixels || options.geometryColour.size() != pixels * 4))
        throw std::invalid_argument("reference: geometry depth and colour must have one value (four) per pixel");
    // Work is handed out in runs of a few pixels, not rows: a lit ray through noise may need
    // thousands of times the steps of its neighbours, so rows left one thread working alone at
    // the end; with small runs every thread works until the last few pixels.
    constexpr std::size_t run = 8;
    std::atomic<std::size_t> nextPixel{0};
    std::atomic<std::size_t> unconverged{0}, unconvergedShadows{0};
    double finest = std::numeric_limits<double>::infinity();
    std::mutex finestMutex;
    auto work = [&] {
        double localFinest = std::numeric_limits<double>::infinity();
        for (std::size_t first; (first = nextPixel.fetch_add(run)) < pixels;) {
            for (std::size_t pixel = first; pixel < std::min(first + run, pixels); ++pixel) {
                const int x = int(pixel % std::size_t(camera.width)), y = int(pixel / std::size_t(camera.width));
                const double nx = 2.0 * (x + 0.5) / camera.width - 1.0, ny = 2.0 * (y + 0.5) / camera.height - 1.0;
                const osg::Vec3d nearPoint = osg::Vec3d(nx, ny, -1.0) * clipToWorld;
                const osg::Vec3d farPoint = osg::Vec3d(nx, ny, 1.0) * clipToWorld;
                Ray ray;
                ray.origin = toGlm(nearPoint);
                ray.direction = toGlm(farPoint - nearPoint);
                ray.length = glm::length(ray.direction);
                // Opaque geometry ends the ray at its depth and lies behind the volumes.
                double end = 1.0;
                glm::dvec4 behind(toGlm(options.background), 0.0);
                bool converged = true, shadowsConverged = true;
                double geometryLight = 1.0;  // what the volumes that shadow it let through
                if (withGeometry && options.geometryDepth[pixel] < 1.0f) {
                    const osg::Vec3d hit = osg::Vec3d(nx, ny, 2.0 * options.geometryDepth[pixel] - 1.0) * clipToWorld;
                    end = glm::length(toGlm(hit - nearPoint)) / ray.length;
                    ShadowTally tally;
                    geometryLight = integrator.lightOnGeometry(toGlm(hit), tally);
                    shadowsConverged = tally.converged;
                    localFinest = std::min(localFinest, tally.finest);
                }
                if (withGeometry)
                    for (int k = 0; k < 4; ++k) behind[k] = options.geometryColour[pixel * 4 + k] * (k < 3 ? geometryLight : 1.0);
                bool shadowsOfRay = true;
                const glm::dvec4 c = integrator.integrate(ray, end, converged, shadowsOfRay, localFinest);
                shadowsConverged = shadowsConverged && shadowsOfRay;
                if (!converged || !shadowsConverged) ++unconverged;
                if (!shadowsConverged) ++unconvergedShadows;
                double* out = &image.rgba[pixel * 4];
                for (int k = 0; k < 4; ++k) out[k] = c[k] + (1.0 - c.a) * behind[k];
            }
        }
        std::lock_guard<std::mutex> lock(finestMutex);
        finest = std::min(finest, localFinest);
    };
    unsigned int threads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> pool;
    for (unsigned int t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    image.unconverged = unconverged;
    image.unconvergedShadows = unconvergedShadows;
    image.finestStepUsed = std::isfinite(finest) ? finest : 0.0;
    return image;
}

}  // namespace volren
