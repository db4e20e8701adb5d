#pragma once
#include "CommandLine.h"

#include <volume_renderer/Annotations.h>
#include <volume_renderer/CameraFraming.h>
#include <volume_renderer/VolumeScene.h>

#include <osg/Camera>
#include <osg/Node>

#include <vector>

namespace volren::app {

/// The inputs as messages name them ("a.nii.gz + tool.obj"; "the default scene
/// (scenes/default.osgt)" when there is none).
std::string inputName(const RenderOptions& options);

/// Reads the inputs (readSceneInputs: scene files strictly, volume files with a progress bar
/// and the -O options, models; --place) under one VolumeScene, or the default scene when there
/// are none, then applies --tf and --set (routed by volren::applySetting); throws
/// std::runtime_error / UsageError naming the file or setting.
osg::ref_ptr<VolumeScene> loadScene(const RenderOptions& options);
/// Adds the screen annotations the options ask for (--scale-bar, --axes; unset: `byDefault`) to
/// `scene`: the scale bar in the first volume's length unit (none when its placement scales it),
/// white (black over a light background). Returns them (null when neither is shown).
osg::ref_ptr<Annotations> addAnnotations(VolumeScene& scene, const RenderOptions& options, bool byDefault);
/// The camera the options ask for (--eye, --center, --up, --fov, --ortho).
CameraRequest cameraRequest(const RenderOptions& options);
/// Sets the camera's view and projection from the options, defaulting to a view from the
/// front-right-above (+x, +y, +z up: anterior for RAS volumes) that fits the scene's box tightly.
void setUpCamera(osg::Camera& camera, const osg::Node& scene, const RenderOptions& options, double aspect);

}  // namespace volren::app
