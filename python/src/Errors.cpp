#include "Errors.h"

#include <exception>
#include <stdexcept>

namespace py = pybind11;

namespace volren::python {

void registerErrors(py::module_& module)
{
    // Never destroyed: a static py::object would be released after the interpreter is gone.
    static auto* error = new py::exception<std::runtime_error>(module, "Error", PyExc_RuntimeError);
    error->doc() = "A volren operation failed (a file that cannot be read or written, a shader that does not "
                  "compile, no EGL context): the C++ message, which names the file and the reason.";
    py::register_exception_translator([](std::exception_ptr thrown) {
        try {
            if (thrown) std::rethrow_exception(thrown);
        } catch (const py::builtin_exception&) {
            throw;  // already a Python exception type (ValueError, TypeError, ...)
        } catch (const py::error_already_set&) {
            throw;
        } catch (const std::invalid_argument& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const std::out_of_range& e) {
            PyErr_SetString(PyExc_IndexError, e.what());
        } catch (const std::bad_alloc&) {
            PyErr_SetString(PyExc_MemoryError, "volren: out of memory");
        } catch (const std::exception& e) {
            (*error)(e.what());
        }
    });
}

}  // namespace volren::python
