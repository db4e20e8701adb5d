#include "TransferFunctionArgument.h"
#include "Conversions.h"

#include <volume_model/AssignTransferFunction.h>
#include <volume_model/DefaultScene.h>

#include <cmath>
#include <vector>

namespace py = pybind11;

namespace volren::python {

namespace {

bool isPath(const py::handle& value)
{
    return py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__");
}

std::vector<double> pointNumbers(const py::handle& point)
{
    const std::string expected = "tf: expected points (value, r, g, b, a), got " + reprOf(point);
    if (isPath(point) || py::isinstance<py::bytes>(point)) throw py::value_error(expected);
    std::vector<double> v;
    try {
        for (const py::handle item : py::iter(point)) {
            if (py::isinstance<py::str>(item)) throw py::value_error(expected);
            v.push_back(py::float_(py::reinterpret_borrow<py::object>(item)).cast<double>());
        }
    } catch (const py::error_already_set&) {
        throw py::value_error(expected);
    }
    if (v.size() != 5) throw py::value_error(expected);
    return v;
}

}  // namespace

osg::ref_ptr<TransferFunction> transferFunctionFromPoints(const py::handle& points)
{
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    try {
        for (const py::handle point : py::iter(points)) {
            const std::vector<double> v = pointNumbers(point);
            tf->setPoint(v[0], osg::Vec4(float(v[1]), float(v[2]), float(v[3]), float(v[4])));
        }
    } catch (const std::invalid_argument& e) {  // TransferFunction::setPoint: value or colour out of range
        throw py::value_error(std::string("tf: ") + e.what());
    } catch (const py::error_already_set&) {
        throw py::type_error("tf: expected None, a path or a list of (value, r, g, b, a), got " + reprOf(points));
    }
    if (tf->points().empty()) throw py::value_error("tf: the list of points is empty");
    return tf;
}

void applyTransferFunction(VolumeScene& scene, const py::handle& tf, bool keepRange)
{
    if (tf.is_none()) return;
    if (isPath(tf)) {
        assignTransferFunctionFile(findVolumeNodes(scene), pathFrom(tf, "tf"), keepRange);
        return;
    }
    osg::ref_ptr<TransferFunction> shared = transferFunctionFromPoints(tf);
    for (VolumeNode* node : findVolumeNodes(scene)) node->setTransferFunction(shared.get());
}

}  // namespace volren::python
