#include "CommandLine.h"
#include "Commands.h"
#include "ImageWriter.h"
#include "SceneSetup.h"

#include <volume_reference/ReferenceSetup.h>

#include <osg/Camera>

#include <chrono>
#include <iostream>

namespace volren::app {

int referenceCommand(const std::vector<std::string>& arguments)
{
    // --normals central|exact is the reference's own; the rest are render's options.
    std::vector<std::string> args;
    ReferenceOptions reference;
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        if (arguments[i] != "--normals") {
            args.push_back(arguments[i]);
            continue;
        }
        if (i + 1 >= arguments.size()) throw UsageError("--normals needs a value");
        const std::string& v = arguments[++i];
        if (v == "exact") reference.gradient = ReferenceOptions::Gradient::Exact;
        else if (v == "central") reference.gradient = ReferenceOptions::Gradient::CentralDifferences;
        else throw UsageError("--normals: exact or central, got '" + v + "'");
    }
    const RenderOptions options = parseRenderOptions(args, true);
    osg::ref_ptr<VolumeScene> scene = loadScene(options);
    osg::ref_ptr<osg::Camera> camera = new osg::Camera;  // the view `volren render` would use
    setUpCamera(*camera, *scene, options, double(options.width) / options.height);

    ReferenceCamera view;
    view.view = camera->getViewMatrix();
    view.projection = camera->getProjectionMatrix();
    view.width = options.width;
    view.height = options.height;
    reference.background = options.background;
    const auto start = std::chrono::steady_clock::now();
    ReferenceSetup setup;
    try {
        setup = referenceSetup(*scene, view, reference);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(inputName(options) + ": " + e.what());
    }
    const ReferenceImage image = renderReference(setup.scene, view, setup.options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    osg::ref_ptr<osg::Image> out = new osg::Image;
    out->allocateImage(image.width, image.height, 1, GL_RGBA, GL_FLOAT);
    auto* pixels = reinterpret_cast<float*>(out->data());
    for (std::size_t i = 0; i < image.rgba.size(); ++i) pixels[i] = float(image.rgba[i]);
    writeImage(*out, options.output);
    std::cout << "volren: wrote " << options.output << " (" << image.width << "x" << image.height << ", " << inputName(options)
              << "; reference in " << seconds << " s, finest step " << image.finestStepUsed << ", "
              << image.unconverged << " rays not converged to " << setup.options.tolerance << ")" << std::endl;
    return 0;
}

}  // namespace volren::app
