#include "Settings.h"
#include "Conversions.h"

#include <volume_renderer/SceneSettings.h>

namespace py = pybind11;

namespace volren::python {

namespace {

std::string scalarText(const std::string& key, const py::handle& value)
{
    const py::module_ numbers = py::module_::import("numbers");
    if (py::isinstance<py::bool_>(value) || py::isinstance(value, py::module_::import("numpy").attr("bool_")))
        return py::cast<bool>(py::bool_(py::reinterpret_borrow<py::object>(value))) ? "on" : "off";
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    if (py::isinstance(value, numbers.attr("Integral"))) return py::str(py::int_(py::reinterpret_borrow<py::object>(value)));
    if (py::isinstance(value, numbers.attr("Real"))) return py::repr(py::float_(py::reinterpret_borrow<py::object>(value)));  // shortest round trip
    throw py::type_error(key + ": expected a str, bool or number, got " + reprOf(value));
}

}  // namespace

std::string settingText(const std::string& key, const py::handle& value)
{
    if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
        std::string joined;
        for (const py::handle item : value) joined += (joined.empty() ? "" : ",") + scalarText(key, item);
        return joined;
    }
    return scalarText(key, value);
}

void applySettings(VolumeScene& scene, const py::dict& settings)
{
    for (const auto& [key, value] : settings) {
        const std::string name = py::str(key);
        try {
            applySetting(scene, name, settingText(name, value));
        } catch (const SettingError& e) {
            throw py::value_error(e.what());
        }
    }
}

}  // namespace volren::python
