#pragma once
#include "RenderOptions.h"

#include <volume_renderer/VolumeScene.h>

#include <pybind11/numpy.h>

namespace volren::python {

/// Renders `scene` as `volren render` does (background, camera framed for the image's aspect,
/// frames until streamed bricks converge) and returns the image: float32 (height, width, 4), top
/// row first, premultiplied RGBA over the background (alpha = coverage), as the CLI writes .exr.
/// One OffscreenRenderer (EGL context) per (width, height, samples) serves the whole process.
pybind11::array_t<float> renderScene(VolumeScene& scene, const RenderOptions& options);

/// Destroys the process's renderers (their EGL contexts and GL objects); the next render makes
/// new ones. Called at interpreter exit.
void releaseRenderers();

}  // namespace volren::python
