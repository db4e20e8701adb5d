#include "Camera.h"
#include "Conversions.h"

#include <array>
#include <cmath>
#include <string>

namespace py = pybind11;

namespace volren::python {

const char* const cameraDoc =
    "A camera is None (the framing `volren render` uses without camera options: a view from the\n"
    "front-right-above, +z up, fitting the scene's box tightly) or a dict with any of these keys, which\n"
    "may also be given as keyword arguments; what is left out is chosen to frame the scene:\n"
    "  eye, center, up   three numbers each, world coordinates (--eye, --center, --up; up defaults to +z)\n"
    "  fov               vertical field of view in degrees, in (0, 180) (--fov; default 30)\n"
    "  ortho             parallel projection: 'fit' (or True) fits the scene, a number is the visible\n"
    "                    height in world units (--ortho fit|HEIGHT); excludes fov\n"
    "  direction         from the scene towards the eye when eye is unset (default (0.55, 1, 0.35))\n"
    "  margin            fraction of the image left free on each side (default 0.03)\n";

namespace {

constexpr std::array<const char*, 7> keys{"eye", "center", "up", "fov", "ortho", "direction", "margin"};

double number(const py::handle& value, const std::string& what)
{
    if (py::isinstance<py::bool_>(value) || py::isinstance<py::str>(value))
        throw py::value_error(what + ": expected a number, got " + reprOf(value));
    double v = 0.0;
    try {
        v = py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>();
    } catch (const py::error_already_set&) {
        throw py::value_error(what + ": expected a number, got " + reprOf(value));
    }
    if (!std::isfinite(v)) throw py::value_error(what + ": " + reprOf(value) + " is not finite");
    return v;
}

void setKey(CameraRequest& request, const std::string& key, const py::handle& value)
{
    if (value.is_none()) return;  // as if left out
    if (key == "eye") request.eye = vec3From(value, "eye");
    else if (key == "center") request.center = vec3From(value, "center");
    else if (key == "up") request.up = vec3From(value, "up");
    else if (key == "fov") {
        request.fov = number(value, "fov");
        if (!(*request.fov > 0.0 && *request.fov < 180.0)) throw py::value_error("fov: must be in (0, 180) degrees");
    } else if (key == "ortho") {
        if (py::isinstance<py::bool_>(value)) {
            request.orthographic = value.cast<bool>();
        } else if (py::isinstance<py::str>(value)) {
            if (value.cast<std::string>() != "fit")
                throw py::value_error("ortho: expected 'fit' or a height, got " + reprOf(value));
            request.orthographic = true;
        } else {
            request.orthographic = true;
            request.orthoHeight = number(value, "ortho");
            if (!(*request.orthoHeight > 0.0)) throw py::value_error("ortho: height must be positive (or 'fit')");
        }
    } else if (key == "direction") {
        request.direction = vec3From(value, "direction");
        if (request.direction.length() == 0.0) throw py::value_error("direction: must not be zero");
    } else if (key == "margin") {
        request.margin = number(value, "margin");
        if (!(request.margin >= 0.0 && request.margin < 0.5)) throw py::value_error("margin: must be in [0, 0.5)");
    }
}

std::string keyList()
{
    std::string list;
    for (const char* key : keys) list += (list.empty() ? "" : ", ") + std::string(key);
    return list;
}

}  // namespace

CameraRequest cameraRequest(const py::handle& camera, py::dict& keywords)
{
    py::dict given;
    if (!camera.is_none()) {
        if (!py::isinstance<py::dict>(camera))
            throw py::type_error("camera: expected a dict (keys " + keyList() + ") or None, got " + reprOf(camera));
        for (const auto& [key, value] : camera.cast<py::dict>()) {
            const std::string name = py::str(key);
            bool known = false;
            for (const char* k : keys) known = known || name == k;
            if (!known) throw py::value_error("camera: unknown key '" + name + "' (known: " + keyList() + ")");
            given[key] = value;
        }
    }
    for (const char* key : keys)
        if (keywords.contains(key)) {
            if (given.contains(key))
                throw py::value_error(std::string("camera: '") + key + "' given both in camera and as a keyword");
            given[key] = keywords[key];
            PyDict_DelItemString(keywords.ptr(), key);
        }
    CameraRequest request;
    for (const char* key : keys)
        if (given.contains(key)) setKey(request, key, given[key]);
    if (request.fov && request.orthographic) throw py::value_error("fov and ortho exclude each other");
    return request;
}

}  // namespace volren::python
