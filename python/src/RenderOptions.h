#pragma once
#include <volume_renderer/CameraFraming.h>

#include <osg/Vec3d>
#include <pybind11/pybind11.h>

namespace volren::python {

/// How one image is rendered, checked as `volren render` checks --size, --samples, --background.
struct RenderOptions
{
    int width = 512, height = 512;        ///< size=(w, h), 1..16384 each
    int samples = 1;                      ///< samples=N, 1..64 (multisampled framebuffer)
    osg::Vec3d background{0.0, 0.0, 0.0};  ///< background=(r, g, b), each in [0, 1]
    CameraRequest camera;                 ///< what is left open frames the scene
};

/// RenderOptions from the arguments of render / render_scene (`keywords` loses its camera keys);
/// ValueError or TypeError naming the argument.
RenderOptions renderOptions(const pybind11::handle& size, const pybind11::handle& camera,
                            const pybind11::handle& background, const pybind11::handle& samples, pybind11::dict& keywords);

}  // namespace volren::python
