#pragma once
#include <volume_model/Volume.h>

#include <pybind11/pybind11.h>

#include <osg/ref_ptr>

namespace volren::python {

/// `volren.Volume`: a volren::Volume held by Python, from load() or from a numpy array.
struct PyVolume
{
    osg::ref_ptr<Volume> volume;
};

/// Defines the `volren.Volume` class in `module`.
void defineVolume(pybind11::module_& module);

}  // namespace volren::python
