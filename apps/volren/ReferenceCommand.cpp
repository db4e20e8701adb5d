#include "CommandLine.h"
#include "Commands.h"
#include "ImageWriter.h"
#include "SceneSetup.h"

#include <volume_reference/ReferenceRenderer.h>

#include <osg/Camera>
#include <osg/LightSource>
#include <osg/NodeVisitor>

#include <chrono>
#include <iostream>

namespace volren::app {

int referenceCommand(const std::vector<std::string>& args)
{
    const RenderOptions options = parseRenderOptions(args, true);
    osg::ref_ptr<VolumeScene> scene = loadScene(options);
    osg::ref_ptr<osg::Camera> camera = new osg::Camera;  // the view `volren render` would use
    setUpCamera(*camera, *scene, options, double(options.width) / options.height);

    ReferenceCamera view;
    view.view = camera->getViewMatrix();
    view.projection = camera->getProjectionMatrix();
    view.width = options.width;
    view.height = options.height;
    ReferenceOptions reference;
    reference.background = options.background;
    const auto start = std::chrono::steady_clock::now();
    const ReferenceScene content = ReferenceScene::collect(*scene);
    if (content.volumes.empty()) throw std::runtime_error(inputName(options) + ": the scene shows no volume");
    struct Lights : osg::NodeVisitor
    {
        Lights() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        int count = 0;
        void apply(osg::LightSource& light) override { ++count, traverse(light); }
    } lights;
    scene->accept(lights);
    if (scene->get("lighting") == "on" && lights.count > 0)
        std::cerr << "volren: note: the reference renders emission and absorption only (no lights yet); compare it "
                     "with 'volren render ... --set lighting=off'" << std::endl;
    const ReferenceImage image = renderReference(content, view, reference);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    osg::ref_ptr<osg::Image> out = new osg::Image;
    out->allocateImage(image.width, image.height, 1, GL_RGBA, GL_FLOAT);
    auto* pixels = reinterpret_cast<float*>(out->data());
    for (std::size_t i = 0; i < image.rgba.size(); ++i) pixels[i] = float(image.rgba[i]);
    writeImage(*out, options.output);
    std::cout << "volren: wrote " << options.output << " (" << image.width << "x" << image.height << ", " << inputName(options)
              << "; reference in " << seconds << " s, finest step " << image.finestStepUsed << ", "
              << image.unconverged << " rays not converged to " << reference.tolerance << ")" << std::endl;
    return 0;
}

}  // namespace volren::app
