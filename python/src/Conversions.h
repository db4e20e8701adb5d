#pragma once
#include <volume_model/Volume.h>

#include <osg/Image>
#include <osg/Vec3d>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

namespace volren::python {

/// A Volume holding a copy of `array` (anything numpy.asarray takes), indexed [z, y, x]: 3-D,
/// of dtype uint8, int8, uint16, int16 or float32 (any byte order, any strides). TypeError for
/// another dtype, ValueError for another number of dimensions or an empty axis.
osg::ref_ptr<Volume> volumeFromArray(const pybind11::handle& array, const osg::Vec3d& spacing);

/// numpy's dtype of a voxel type.
pybind11::dtype dtypeOf(VoxelType type);

/// A read-only numpy view [z, y, x] of block (channel, frame) of `volume`; `owner` (the Python
/// object holding the volume) is kept alive by the view.
pybind11::array blockView(const Volume& volume, int channel, int frame, const pybind11::handle& owner);

/// A read-back image (RGBA float, row 0 at the bottom) as a new float32 array (height, width, 4),
/// top row first.
pybind11::array_t<float> imageToArray(const osg::Image& image);

/// Three finite numbers (a tuple, list or array) as a vector; ValueError naming `what`.
osg::Vec3d vec3From(const pybind11::handle& value, const std::string& what);

/// A str or os.PathLike as a path; TypeError naming `what` otherwise.
std::string pathFrom(const pybind11::handle& value, const std::string& what);

/// Python's repr() of `value`, for messages.
std::string reprOf(const pybind11::handle& value);

}  // namespace volren::python
