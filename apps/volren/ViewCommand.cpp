#include "Commands.h"
#include "SceneSetup.h"

#include <volume_renderer/VolumeScene.h>

#include <osgGA/TrackballManipulator>
#include <osg/DisplaySettings>
#include <osgViewer/Viewer>
#include <osgViewer/ViewerEventHandlers>

#include <cstdlib>
#include <iostream>

namespace volren::app {

int viewCommand(const std::vector<std::string>& args)
{
    const RenderOptions options = parseRenderOptions(args, false);
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display)
        throw std::runtime_error("volren view needs a display and DISPLAY is not set; use 'volren render' for images");

    osg::ref_ptr<VolumeScene> root = loadScene(options);
    if (options.samples > 1) osg::DisplaySettings::instance()->setNumMultiSamples(options.samples);  // an MSAA window
    osgViewer::Viewer viewer;
    viewer.setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
    viewer.setUpViewInWindow(50, 50, options.width, options.height);
    viewer.setSceneData(root.get());
    viewer.setCameraManipulator(new osgGA::TrackballManipulator);
    viewer.addEventHandler(new osgViewer::StatsHandler);          // 's': frame time
    viewer.addEventHandler(new osgViewer::ScreenCaptureHandler);  // 'c': screenshot
    viewer.getCamera()->setClearColor(osg::Vec4(options.background, 1.0f));
    viewer.realize();
    if (!viewer.isRealized()) throw std::runtime_error("volren view: cannot open a window on display " + std::string(display));
    // OSG's default state (fixed-function matrices and vertex arrays), as in any OSG viewer: the
    // volume proxies feed their own matrix, and polygon models keep their normals and colours.
    std::cout << "volren view: 's' shows frame times, 'c' saves a screenshot, Esc quits" << std::endl;
    return viewer.run();
}

}  // namespace volren::app
