#pragma once
#include <volume_renderer/CameraFraming.h>

#include <pybind11/pybind11.h>

namespace volren::python {

/// The camera asked for by a `camera` dict (or None) and by the camera keywords among
/// `keywords` (eye, center, up, fov, ortho, direction, margin), which are taken out of it; the
/// same key in both is a ValueError. Checked as `volren render` checks --eye, --center, --up,
/// --fov and --ortho: ValueError naming the key, TypeError for a camera that is not a dict.
CameraRequest cameraRequest(const pybind11::handle& camera, pybind11::dict& keywords);

/// Text for docstrings: what a camera dict holds.
extern const char* const cameraDoc;

}  // namespace volren::python
