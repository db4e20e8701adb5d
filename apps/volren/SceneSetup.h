#pragma once
#include "CommandLine.h"

#include <osg/Camera>
#include <osg/Node>

namespace volren::app {

/// Path of the embedded default volume (share/volren/data/ch2.nii.gz).
std::string defaultInput();

/// Loads INPUT (a scene file, or a bare volume file that gets the default scene), then applies
/// --tf and --set to every VolumeNode; throws std::runtime_error / UsageError naming the file.
osg::ref_ptr<osg::Node> loadScene(const RenderOptions& options);

/// Sets the camera's view and projection from the options, defaulting to a view that frames
/// the scene's bound from the front-right-above (+x, +y, +z up: anterior for RAS volumes).
void setUpCamera(osg::Camera& camera, const osg::Node& scene, const RenderOptions& options, double aspect);

}  // namespace volren::app
