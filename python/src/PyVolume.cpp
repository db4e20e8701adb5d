#include "PyVolume.h"
#include "Conversions.h"

#include <sstream>

namespace py = pybind11;

namespace volren::python {

namespace {

py::tuple xyz(const osg::Vec3i& v)
{
    return py::make_tuple(v.x(), v.y(), v.z());
}

py::tuple xyz(const osg::Vec3d& v)
{
    return py::make_tuple(v.x(), v.y(), v.z());
}

std::string reprOfVolume(const PyVolume& self)
{
    const Volume& v = *self.volume;
    std::ostringstream out;
    out << "volren.Volume(";
    if (!v.sourceFile.empty()) out << reprOf(py::str(v.sourceFile)) << ", ";
    out << "dims=(" << v.dims().x() << ", " << v.dims().y() << ", " << v.dims().z() << "), dtype=" << voxelTypeName(v.type())
        << ", spacing=" << reprOf(xyz(v.spacing()));
    if (v.channels() > 1) out << ", channels=" << v.channels();
    if (v.frames() > 1) out << ", frames=" << v.frames();
    if (v.fullResolution()) {
        const osg::Vec3i f = v.fullDims();
        out << ", lazy: full dims (" << f.x() << ", " << f.y() << ", " << f.z() << ")";
    }
    out << ")";
    return out.str();
}

}  // namespace

void defineVolume(py::module_& module)
{
    py::class_<PyVolume>(module, "Volume", R"doc(A volume: voxels, spacing and the map to data values, as volren renders it.

Made by volren.load(path) or from a numpy array: volren.Volume(array, spacing=(1, 1, 1)).
Pass it to volren.render(volume) to render it as `volren render FILE` renders its file.

Axis order: numpy arrays are indexed [z, y, x] (C order, x fastest, as files store voxels);
`dims` and `spacing` are (x, y, z), as `volren info` and the file headers give them.
)doc")
        .def(py::init([](const py::object& array, const py::object& spacing) {
                 return PyVolume{volumeFromArray(array, vec3From(spacing, "spacing"))};
             }),
             py::arg("array"), py::arg("spacing") = py::make_tuple(1.0, 1.0, 1.0),
             R"doc(A volume holding a copy of `array`, indexed [z, y, x].

array: a 3-D numpy array (or anything numpy.asarray takes) of dtype uint8, int8, uint16, int16,
    float32 or float64 (stored as float32, rounded; a finite value beyond float32's range raises
    ValueError); other dtypes raise TypeError, other dimensions ValueError. NaN voxels are
    allowed (rendered as empty).
spacing: world size of a voxel along (x, y, z), positive.)doc")
        .def_property_readonly(
            "array", [](const py::object& self) { return blockView(*self.cast<PyVolume&>().volume, 0, 0, self); },
            "The voxels as a read-only numpy view indexed [z, y, x] (channel 0, time point 0: what is rendered), "
            "stored values before the rescale. Copy it (array.copy()) to change it. For a volume opened lazily "
            "this is the coarse level held in memory.")
        .def(
            "block", [](const py::object& self, int channel, int frame) {
                return blockView(*self.cast<PyVolume&>().volume, channel, frame, self);
            },
            py::arg("channel") = 0, py::arg("frame") = 0,
            "Read-only numpy view [z, y, x] of one channel at one time point (IndexError when there is none).")
        .def_property_readonly(
            "shape", [](const PyVolume& self) { const osg::Vec3i& d = self.volume->dims(); return py::make_tuple(d.z(), d.y(), d.x()); },
            "(z, y, x): the shape of `array`.")
        .def_property_readonly("dims", [](const PyVolume& self) { return xyz(self.volume->dims()); },
                               "Voxels along (x, y, z).")
        .def_property(
            "spacing", [](const PyVolume& self) { return xyz(self.volume->spacing()); },
            [](PyVolume& self, const py::object& spacing) { self.volume->setSpacing(vec3From(spacing, "spacing")); },
            "World size of one voxel along (x, y, z); settable (positive, finite).")
        .def_property_readonly("dtype", [](const PyVolume& self) { return dtypeOf(self.volume->type()); },
                               "numpy dtype of the stored voxels.")
        .def_property_readonly(
            "path", [](const PyVolume& self) { return self.volume->sourceFile.empty() ? py::object(py::none()) : py::object(py::str(self.volume->sourceFile)); },
            "The file it was read from, or None for a volume made from an array.")
        .def_property_readonly("channels", [](const PyVolume& self) { return self.volume->channels(); },
                               "Channels per time point (rendering shows channel 0).")
        .def_property_readonly("frames", [](const PyVolume& self) { return self.volume->frames(); },
                               "Time points (rendering shows time point 0).")
        .def_property_readonly("value_range", [](const PyVolume& self) { const auto [lo, hi] = self.volume->valueRange(); return py::make_tuple(lo, hi); },
                               "(min, max) of the finite data values (after the rescale).")
        .def_property_readonly("rescale", [](const PyVolume& self) { return py::make_tuple(self.volume->rescaleSlope(), self.volume->rescaleIntercept()); },
                               "(slope, intercept): data value = stored value * slope + intercept.")
        .def_property_readonly("lazy", [](const PyVolume& self) { return self.volume->fullResolution() != nullptr; },
                               "Whether the file was opened lazily (larger than the RAM budget, or reader option lazy): "
                               "`array` is then a coarse level, and the renderer reads bricks from the file.")
        .def_property_readonly("full_dims", [](const PyVolume& self) { return xyz(self.volume->fullDims()); },
                               "Voxels along (x, y, z) at full resolution (dims, unless lazy).")
        .def("__repr__", &reprOfVolume);
}

}  // namespace volren::python
