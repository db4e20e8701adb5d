#pragma once
#include "CommandLine.h"

#include <volume_renderer/VolumeScene.h>

#include <osg/Camera>
#include <osg/Node>

#include <vector>

namespace volren::app {

/// INPUT as messages name it ("the default scene (scenes/default.osgt)" when there is none).
std::string inputName(const RenderOptions& options);

/// Reads INPUT (volume_model's readInput: a scene file strictly, a bare volume file with its
/// default scene and a progress bar, or nothing: the default scene) under a VolumeScene, then
/// applies --tf and --set (routed by volren::applySetting); throws std::runtime_error /
/// UsageError naming the file or setting.
osg::ref_ptr<VolumeScene> loadScene(const RenderOptions& options);
/// Sets the camera's view and projection from the options, defaulting to a view that frames
/// the scene's bound from the front-right-above (+x, +y, +z up: anterior for RAS volumes).
void setUpCamera(osg::Camera& camera, const osg::Node& scene, const RenderOptions& options, double aspect);

}  // namespace volren::app
