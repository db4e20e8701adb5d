#pragma once
#include "CommandLine.h"

#include <volume_renderer/VolumeScene.h>

#include <osg/Camera>
#include <osg/Node>

#include <vector>

namespace volren::app {

/// INPUT as messages name it ("the default scene (scenes/default.osgt)" when there is none).
std::string inputName(const RenderOptions& options);

/// Loads INPUT (a scene file, a bare volume file that gets the default scene, or nothing: the
/// compiled-in scenes/default.osgt) under a
/// VolumeScene, then applies --tf and --set (pass settings to the VolumeScene, the others to
/// every VolumeNode, implementation names checked against the registry); throws
/// std::runtime_error / UsageError naming the file or setting.
osg::ref_ptr<VolumeScene> loadScene(const RenderOptions& options);

/// Text of `volren render --help-settings`: every setting with its value, and every slot's
/// implementations.
std::string settingsHelp();

/// Every VolumeNode below `root`, in traversal order (all children, whatever their masks).
std::vector<VolumeNode*> volumeNodes(osg::Node& root);
/// Sets the camera's view and projection from the options, defaulting to a view that frames
/// the scene's bound from the front-right-above (+x, +y, +z up: anterior for RAS volumes).
void setUpCamera(osg::Camera& camera, const osg::Node& scene, const RenderOptions& options, double aspect);

}  // namespace volren::app
