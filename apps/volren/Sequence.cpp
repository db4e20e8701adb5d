#include "Sequence.h"
#include "ImageWriter.h"
#include "SceneSetup.h"

#include <volume_renderer/CameraFraming.h>

#include <volume_model/TimeSeries.h>

#include <osgDB/FileNameUtils>

namespace volren::app {

bool isSequence(const RenderOptions& options)
{
    return options.turntable > 0 || options.everyTime;
}

WrittenFrames renderSequence(OffscreenRenderer& renderer, osg::Node& scene, const RenderOptions& options,
                           const std::function<void()>& converge, std::vector<FrameTiming>& timings)
{
    const double aspect = double(options.width) / options.height;
    std::vector<CameraView> views;
    if (options.turntable > 0)
        views = turntableViews(scene, cameraRequest(options), aspect, options.turntableAxis, options.turntable);
    else
        views = {{renderer.camera()->getViewMatrix(), renderer.camera()->getProjectionMatrix()}};
    TimeSeries series(scene);
    const int timePoints = options.everyTime ? series.timePoints() : 1;
    const int count = options.turntable > 0 ? options.turntable : timePoints;

    const bool gif = osgDB::getLowerCaseFileExtension(options.output) == "gif";
    std::vector<osg::ref_ptr<osg::Image>> images;
    for (int k = 0; k < count; ++k) {
        const CameraView& view = views[options.turntable > 0 ? std::size_t(k) : 0];
        renderer.camera()->setViewMatrix(view.view);
        renderer.camera()->setProjectionMatrix(view.projection);
        if (options.everyTime) series.show(int(std::int64_t(k) * timePoints / count));
        timings.push_back(renderer.renderFrame());
        converge();
        if (gif) images.push_back(new osg::Image(*renderer.image(), osg::CopyOp::DEEP_COPY_ALL));
        else writeImage(*renderer.image(), numberedPath(options.output, k + 1));
    }
    if (gif) {
        writeAnimatedGif(images, options.output, options.turntable > 0 ? 25 : 10);
        return {osgDB::getRealPath(options.output), count};
    }
    return {osgDB::getRealPath(numberedPath(options.output, 1)) + " ... " +
                osgDB::getSimpleFileName(numberedPath(options.output, count)),
            count};
}

}  // namespace volren::app
