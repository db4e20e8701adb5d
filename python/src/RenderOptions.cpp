#include "RenderOptions.h"
#include "Camera.h"
#include "Conversions.h"

#include <vector>

namespace py = pybind11;

namespace volren::python {

namespace {

int wholeNumber(const py::handle& value, const std::string& what, int lo, int hi)
{
    const std::string range = " must be a whole number in " + std::to_string(lo) + ".." + std::to_string(hi);
    if (py::isinstance<py::bool_>(value) || !py::isinstance(value, py::module_::import("numbers").attr("Integral")))
        throw py::type_error(what + range + ", got " + reprOf(value));
    const long long v = py::int_(py::reinterpret_borrow<py::object>(value)).cast<long long>();
    if (v < lo || v > hi) throw py::value_error(what + range + ", got " + reprOf(value));
    return int(v);
}

}  // namespace

RenderOptions renderOptions(const py::handle& size, const py::handle& camera, const py::handle& background,
                            const py::handle& samples, py::dict& keywords)
{
    RenderOptions o;
    std::vector<py::handle> wh;
    if (!py::isinstance<py::str>(size) && py::isinstance<py::sequence>(size))
        for (const py::handle item : size) wh.push_back(item);
    if (wh.size() != 2) throw py::value_error("size: expected (width, height), got " + reprOf(size));
    o.width = wholeNumber(wh[0], "size width", 1, 16384);
    o.height = wholeNumber(wh[1], "size height", 1, 16384);
    o.samples = wholeNumber(samples, "samples", 1, 64);
    o.background = vec3From(background, "background");
    for (int c = 0; c < 3; ++c)
        if (o.background[c] < 0.0 || o.background[c] > 1.0) throw py::value_error("background: components must be in [0,1]");
    o.camera = cameraRequest(camera, keywords);
    return o;
}

}  // namespace volren::python
