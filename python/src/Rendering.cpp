#include "Rendering.h"
#include "Conversions.h"

#include <volume_renderer/OffscreenRenderer.h>

#include <map>
#include <memory>
#include <tuple>

namespace py = pybind11;

namespace volren::python {

namespace {

using RendererKey = std::tuple<int, int, int>;  // width, height, samples

std::map<RendererKey, std::unique_ptr<OffscreenRenderer>>& renderers()
{
    static std::map<RendererKey, std::unique_ptr<OffscreenRenderer>> cache;
    return cache;
}

OffscreenRenderer& rendererFor(const RenderOptions& options)
{
    std::unique_ptr<OffscreenRenderer>& renderer = renderers()[{options.width, options.height, options.samples}];
    if (!renderer) {
        try {
            renderer = std::make_unique<OffscreenRenderer>(options.width, options.height, options.samples);
        } catch (...) {
            renderers().erase({options.width, options.height, options.samples});
            throw;
        }
    }
    return *renderer;
}

/// Leaves the renderer without the scene, so the volumes it showed can be freed, however the
/// frame ended.
struct SceneHeld
{
    OffscreenRenderer& renderer;
    SceneHeld(OffscreenRenderer& r, VolumeScene& scene) : renderer(r) { renderer.setScene(&scene); }
    ~SceneHeld()
    {
        try {
            renderer.setScene(nullptr);
        } catch (...) {
        }
    }
    SceneHeld(const SceneHeld&) = delete;
    SceneHeld& operator=(const SceneHeld&) = delete;
};

}  // namespace

py::array_t<float> renderScene(VolumeScene& scene, const RenderOptions& options)
{
    OffscreenRenderer& renderer = rendererFor(options);
    const SceneHeld held(renderer, scene);
    renderer.setBackground(osg::Vec3(options.background));
    CameraView view;
    try {
        view = frameScene(scene, options.camera, double(options.width) / options.height);
    } catch (const std::invalid_argument& e) {
        throw py::value_error(std::string("camera: ") + e.what() + " (eye, center, up)");
    }
    renderer.camera()->setViewMatrix(view.view);
    renderer.camera()->setProjectionMatrix(view.projection);
    renderer.renderFrame();
    // Streaming bricks (streamBricks=True): frames go on until every brick they plan is in its
    // pool, so the image is the converged one, as without streaming (and as `volren render`).
    if (VolumeScene* volumes = renderer.volumeScene(); volumes && volumes->pass.streamBricks)
        while (volumes->pendingBricks() > 0) {
            volumes->waitForBricks(1.0);
            renderer.renderFrame();
        }
    return imageToArray(*renderer.image());
}

void releaseRenderers()
{
    renderers().clear();
}

}  // namespace volren::python
