#include "CommandLine.h"
#include "Commands.h"
#include "ImageWriter.h"
#include "SceneSetup.h"

#include <volume_reference/ReferenceRenderer.h>
#include <volume_renderer/OffscreenRenderer.h>

#include <osg/Camera>

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
    // The pass settings the reference follows: lighting on/off, and slots forced null for all.
    reference.lighting = scene->lighting;
    for (const auto& placed : content.volumes)
        for (const std::string& slot : scene->forceNull)
            const_cast<VolumeNode&>(static_cast<const VolumeNode&>(*placed.node)).settings.forceNull.insert(slot);
    // Opaque geometry is rasterised once for the same camera, with every volume hidden: the rays
    // end at its depth and the volumes are composited over its colour.
    {
        std::vector<std::pair<osg::Node*, osg::Node::NodeMask>> hidden;
        for (const auto& placed : content.volumes) {
            auto* node = const_cast<osg::Node*>(placed.node.get());
            hidden.emplace_back(node, node->getNodeMask());
            node->setNodeMask(0);
        }
        OffscreenRenderer geometry(options.width, options.height);
        geometry.setReadDepth(true);
        geometry.setScene(scene.get());
        geometry.setBackground(osg::Vec3(options.background));
        geometry.camera()->setViewMatrix(view.view);
        geometry.camera()->setProjectionMatrix(view.projection);
        geometry.camera()->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
        geometry.renderFrame();
        for (auto& [node, mask] : hidden) node->setNodeMask(mask);
        const auto* depth = reinterpret_cast<const float*>(geometry.depthImage()->data());
        const auto* colour = reinterpret_cast<const float*>(geometry.image()->data());
        const std::size_t pixels = std::size_t(options.width) * options.height;
        bool any = false;
        for (std::size_t i = 0; i < pixels && !any; ++i) any = depth[i] < 1.0f;
        if (any) {
            reference.geometryDepth.assign(depth, depth + pixels);
            reference.geometryColour.assign(colour, colour + pixels * 4);
        }
    }
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
