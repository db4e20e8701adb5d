#include "SceneSetup.h"

#include <volume_model/DefaultScene.h>
#include <volume_model/ReadVolume.h>
#include <volume_model/TransferFunctionFile.h>
#include <volume_model/VolumeNode.h>

#include <osg/NodeVisitor>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>
#include <osgDB/ReadFile>

#include <cmath>

namespace volren::app {

namespace {

std::vector<VolumeNode*> volumeNodes(osg::Node& root)
{
    struct Collect : osg::NodeVisitor
    {
        Collect() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        std::vector<VolumeNode*> nodes;
        void apply(osg::Node& node) override
        {
            if (auto* v = dynamic_cast<VolumeNode*>(&node)) nodes.push_back(v);
            traverse(node);
        }
    } collect;
    root.accept(collect);
    return collect.nodes;
}

}  // namespace

std::string defaultInput()
{
    return osgDB::concatPaths(shareDirectory(), "data/ch2.nii.gz");
}

osg::ref_ptr<osg::Node> loadScene(const RenderOptions& options)
{
    registerPluginPath();
    const std::string input = options.input.empty() ? defaultInput() : options.input;
    osg::ref_ptr<osg::Node> scene;
    if (isVolumeFile(input)) {
        scene = makeDefaultScene(readVolumeFile(input).get());
    } else {
        if (!osgDB::fileExists(input)) throw std::runtime_error(input + ": no such file");
        osgDB::ReaderWriter::ReadResult result = osgDB::Registry::instance()->readNode(input, nullptr);
        if (!result.validNode()) {
            const std::string why = result.message().empty() ? "no reader for this file type, or the file is invalid"
                                                             : result.message();
            throw std::runtime_error(input + ": cannot read scene: " + why);
        }
        scene = result.getNode();
    }

    const std::vector<VolumeNode*> nodes = volumeNodes(*scene);
    if (!options.tfFile.empty()) {
        osg::ref_ptr<TransferFunction> tf = readTransferFunctionFile(options.tfFile);
        for (VolumeNode* node : nodes) node->setTransferFunction(tf.get());
    }
    for (const auto& [key, value] : options.settings) {
        RenderSettings probe;
        std::string error;
        if (!probe.set(key, value, error)) throw UsageError("--set " + key + "=" + value + ": " + error);
        for (VolumeNode* node : nodes) node->settings.set(key, value, error);
    }
    return scene;
}

void setUpCamera(osg::Camera& camera, const osg::Node& scene, const RenderOptions& options, double aspect)
{
    const osg::BoundingSphere bound = scene.getBound();
    const osg::Vec3d centre = options.center ? *options.center : osg::Vec3d(bound.center());
    const double radius = bound.valid() && bound.radius() > 0 ? bound.radius() : 1.0;
    const double fov = options.fov ? *options.fov : 30.0;

    osg::Vec3d eye;
    if (options.eye) {
        eye = *options.eye;
    } else {
        osg::Vec3d direction(0.55, 1.0, 0.35);
        direction.normalize();
        const double halfV = osg::DegreesToRadians(fov * 0.5);
        const double halfAngle = std::min(halfV, std::atan(std::tan(halfV) * aspect));
        eye = centre + direction * (radius / std::sin(halfAngle) * 1.02);
    }
    const osg::Vec3d up = options.up ? *options.up : osg::Vec3d(0.0, 0.0, 1.0);
    if ((eye - centre).length() == 0.0) throw UsageError("--eye and --center must differ");
    if (((centre - eye) ^ up).length() == 0.0) throw UsageError("--up must not be parallel to the view direction");
    camera.setViewMatrixAsLookAt(eye, centre, up);

    if (options.orthoHeight) {
        const double h = *options.orthoHeight * 0.5;
        camera.setProjectionMatrixAsOrtho(-h * aspect, h * aspect, -h, h, 0.01, 1e6);
    } else {
        camera.setProjectionMatrixAsPerspective(fov, aspect, 0.01, 1e6);
    }
}

}  // namespace volren::app
