#include "SceneSetup.h"
#include "Commands.h"

#include <volume_renderer/SceneSettings.h>

#include <volume_model/DefaultScene.h>
#include <volume_model/ReadScene.h>
#include <volume_model/ReadVolume.h>
#include <volume_model/TransferFunctionFile.h>

#include <cmath>

namespace volren::app {

namespace {

/// A load progress bar on stderr for INPUT when it is a volume file that takes a while.
osg::ref_ptr<osg::Node> readWithProgress(const std::string& input, const std::string& readerOptions)
{
    if (input.empty() || !isVolumeFile(input)) return readInput(input);
    return makeDefaultScene(readVolumeWithProgress(input, readerOptions).get());
}

/// Replaces every volume's transfer function by the one in `file`; ParaView presets are made
/// for any data, so (like ParaView) they are mapped onto each volume's range unless `keepRange`.
void applyTransferFunction(const std::vector<VolumeNode*>& nodes, const std::string& file, bool keepRange)
{
    osg::ref_ptr<TransferFunction> tf = readTransferFunctionFile(file);
    const bool preset = isParaViewPreset(file) && !keepRange;
    for (VolumeNode* node : nodes) {
        if (preset && node->getVolume()) {
            osg::ref_ptr<TransferFunction> fitted = new TransferFunction(*tf);
            const auto [lo, hi] = node->getVolume()->valueRange();
            fitted->remap(lo, hi > lo ? hi : lo + 1.0);
            node->setTransferFunction(fitted.get());
        } else {
            node->setTransferFunction(tf.get());
        }
    }
}

}  // namespace

std::string inputName(const RenderOptions& options)
{
    return volren::inputName(options.input);
}

osg::ref_ptr<VolumeScene> loadScene(const RenderOptions& options)
{
    osg::ref_ptr<VolumeScene> root = asVolumeScene(readWithProgress(options.input, options.readerOptions).get());
    if (!options.tfFile.empty()) applyTransferFunction(findVolumeNodes(*root), options.tfFile, options.tfKeepRange);
    for (const auto& [key, value] : options.settings) {
        try {
            applySetting(*root, key, value);
        } catch (const SettingError& e) {
            throw UsageError(std::string("--set ") + e.what());
        }
    }
    return root;
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
