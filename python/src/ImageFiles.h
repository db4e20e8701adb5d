#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

namespace volren::python {

/// Writes an image (height, width, 3 or 4), top row first, through OpenImageIO with the rules
/// of `volren render -o`: float channels as they are for .exr, 8-bit RGB (clamped to [0, 1],
/// rounded, non-finite as 0) for every other extension. volren.Error when it cannot be written.
void saveImage(const pybind11::handle& image, const std::string& path);

/// Reads an image file through OpenImageIO as float32 (height, width, channels), top row first
/// (8-bit files scaled to [0, 1]): what saveImage wrote, or `volren render`'s .exr. volren.Error
/// when it cannot be read.
pybind11::array_t<float> readImage(const std::string& path);

}  // namespace volren::python
