#pragma once
#include <volume_model/TransferFunction.h>
#include <volume_renderer/VolumeScene.h>

#include <pybind11/pybind11.h>

namespace volren::python {

/// A transfer function of control points, each a sequence (value, r, g, b, a) with the value in
/// data units and components in [0, 1] (a list of tuples, or an N x 5 array); ValueError else.
osg::ref_ptr<TransferFunction> transferFunctionFromPoints(const pybind11::handle& points);

/// Gives every volume of `scene` the transfer function `tf` asks for: None keeps theirs (a default
/// scene's is made from the volume's histogram), a path is read as `volren render --tf PATH
/// [--tf-keep-range]` reads it (assignTransferFunctionFile), a sequence of points is
/// transferFunctionFromPoints's.
void applyTransferFunction(VolumeScene& scene, const pybind11::handle& tf, bool keepRange);

}  // namespace volren::python
