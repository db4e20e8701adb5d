#include "SceneSetup.h"
#include "Commands.h"

#include <volume_renderer/SceneSettings.h>

#include <volume_model/AssignTransferFunction.h>
#include <volume_model/DefaultScene.h>
#include <volume_model/LengthUnit.h>
#include <volume_model/ReadScene.h>
#include <volume_model/SceneInputs.h>
#include <volume_model/TimeSeries.h>

#include <osg/Transform>

#include <cmath>

namespace volren::app {

std::string inputName(const RenderOptions& options)
{
    if (options.inputs.empty()) return volren::inputName("");
    std::string names;
    for (const std::string& input : options.inputs) names += (names.empty() ? "" : " + ") + input;
    return names;
}

osg::ref_ptr<VolumeScene> loadScene(const RenderOptions& options)
{
    osg::ref_ptr<osg::Node> scene;
    if (options.inputs.empty()) {
        scene = readDefaultScene();
    } else {
        std::vector<SceneInput> inputs;
        for (std::size_t i = 0; i < options.inputs.size(); ++i) {
            const auto placed = options.placements.find(i);
            inputs.push_back({options.inputs[i], placed == options.placements.end() ? std::nullopt
                                                                                    : std::optional<Placement>(placed->second)});
        }
        scene = readSceneInputs(inputs, [&](const std::string& path) { return readVolumeWithProgress(path, options.readerOptions); });
    }
    osg::ref_ptr<VolumeScene> root = asVolumeScene(scene.get());
    if (options.time) {
        try {
            TimeSeries(*root).show(*options.time);
        } catch (const std::out_of_range& e) {
            throw UsageError(std::string("--time: ") + e.what());
        }
    }
    if (!options.tfFile.empty()) assignTransferFunctionFile(findVolumeNodes(*root), options.tfFile, options.tfKeepRange);
    for (const auto& [key, value] : options.settings) {
        try {
            applySetting(*root, key, value);
        } catch (const SettingError& e) {
            throw UsageError(std::string("--set ") + e.what());
        }
    }
    return root;
}

osg::ref_ptr<Annotations> addAnnotations(VolumeScene& scene, const RenderOptions& options, bool byDefault)
{
    const bool scaleBar = options.scaleBar.value_or(byDefault), axes = options.axes.value_or(byDefault);
    if (!scaleBar && !axes) return nullptr;
    osg::ref_ptr<Annotations> annotations = new Annotations;
    annotations->setScaleBar(scaleBar);
    annotations->setAxes(axes);
    // The first volume's unit, where its world lengths are its own (a scaled placement: none).
    for (VolumeNode* node : findVolumeNodes(scene))
        if (node->getVolume()) {
            const osg::NodePathList paths = node->getParentalNodePaths();
            const osg::Matrixd m = paths.empty() ? osg::Matrixd() : osg::computeLocalToWorld(paths.front());
            bool own = true;  // a rotation at most: the 3x3 part times its transpose is the identity
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    own = own && std::abs(m(i, 0) * m(j, 0) + m(i, 1) * m(j, 1) + m(i, 2) * m(j, 2) - (i == j)) < 1e-9;
            annotations->setUnit(own ? lengthUnitOf(*node->getVolume()) : std::string());
            break;
        }
    const osg::Vec3d& b = options.background;
    if (0.2126 * b.x() + 0.7152 * b.y() + 0.0722 * b.z() > 0.5) annotations->setColour(osg::Vec4(0, 0, 0, 1));
    scene.addChild(annotations.get());
    return annotations;
}

CameraRequest cameraRequest(const RenderOptions& options)
{
    CameraRequest request;
    request.eye = options.eye;
    request.center = options.center;
    request.up = options.up;
    request.fov = options.fov;
    request.orthographic = options.ortho;
    request.orthoHeight = options.orthoHeight;
    return request;
}

void setUpCamera(osg::Camera& camera, const osg::Node& scene, const RenderOptions& options, double aspect)
{
    try {
        const CameraView view = frameScene(scene, cameraRequest(options), aspect);
        camera.setViewMatrix(view.view);
        camera.setProjectionMatrix(view.projection);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("camera: ") + e.what() + " (--eye, --center, --up)");
    }
}

}  // namespace volren::app
