#pragma once
#include <pybind11/pybind11.h>

namespace volren::python {

/// Adds `volren.Error` (a RuntimeError) to `module` and translates C++ exceptions at the
/// module's boundary, messages unchanged: std::invalid_argument -> ValueError,
/// std::out_of_range -> IndexError, any other
/// std::exception (std::runtime_error from readers, the renderer, image files) -> volren.Error.
/// pybind11's own exceptions (pybind11::value_error, type_error, ...) pass through as they are.
void registerErrors(pybind11::module_& module);

}  // namespace volren::python
