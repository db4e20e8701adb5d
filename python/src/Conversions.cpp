#include "Conversions.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace py = pybind11;

namespace volren::python {

namespace {

/// The voxel type of a numpy dtype; TypeError for one volren does not store.
VoxelType voxelTypeOf(const py::dtype& dtype)
{
    const char kind = dtype.kind();
    const py::ssize_t size = dtype.itemsize();
    if (kind == 'u' && size == 1) return VoxelType::UInt8;
    if (kind == 'i' && size == 1) return VoxelType::Int8;
    if (kind == 'u' && size == 2) return VoxelType::UInt16;
    if (kind == 'i' && size == 2) return VoxelType::Int16;
    if (kind == 'f' && (size == 4 || size == 8)) return VoxelType::Float32;  // float64: narrowed, as NIfTI and Zarr files are
    throw py::type_error("volume: dtype " + dtype.attr("name").cast<std::string>() +
                         " is not supported; use uint8, int8, uint16, int16, float32 or float64 (e.g. array.astype(numpy.float32))");
}

}  // namespace

osg::ref_ptr<Volume> volumeFromArray(const py::handle& given, const osg::Vec3d& spacing)
{
    const py::module_ numpy = py::module_::import("numpy");
    py::array array = numpy.attr("asarray")(given);
    const VoxelType type = voxelTypeOf(array.dtype());
    if (array.ndim() != 3)
        throw py::value_error("volume: expected a 3-D array indexed [z, y, x], got " + std::to_string(array.ndim()) +
                              " dimension" + (array.ndim() == 1 ? "" : "s"));
    if (array.dtype().kind() == 'f' && array.dtype().itemsize() == 8) {
        // numpy's default float64, stored as float32 (volren's float storage): rounded to float32's
        // 24-bit mantissa; a finite value beyond float32's range is refused, not made infinite.
        const py::object finite = py::reinterpret_borrow<py::object>(array)[numpy.attr("isfinite")(array)];
        if (py::len(finite) > 0) {
            const double largest = numpy.attr("abs")(finite).attr("max")().cast<double>();
            if (largest > double(std::numeric_limits<float>::max()))
                throw py::value_error("volume: a float64 value of magnitude " + reprOf(py::float_(largest)) +
                                      " is beyond float32's range (3.4e38), in which volren stores float voxels");
        }
        array = numpy.attr("asarray")(array, py::arg("dtype") = numpy.attr("float32"));
    }
    // C order in the machine's byte order: voxel (x, y, z) at x + nx * (y + ny * z), as Volume stores it.
    py::object native = array.dtype().attr("newbyteorder")("=");
    array = numpy.attr("ascontiguousarray")(array, py::arg("dtype") = native);
    const osg::Vec3i dims(int(array.shape(2)), int(array.shape(1)), int(array.shape(0)));
    for (int axis = 0; axis < 3; ++axis)
        if (array.shape(axis) < 1 || array.shape(axis) > (py::ssize_t(1) << 30))
            throw py::value_error("volume: array shape " + reprOf(array.attr("shape")) + " has an empty or too long axis");
    std::vector<std::uint8_t> bytes(std::size_t(array.nbytes()));
    std::memcpy(bytes.data(), array.data(), bytes.size());
    osg::ref_ptr<Volume> volume = new Volume;
    volume->assign(type, dims, std::move(bytes));  // std::invalid_argument (ValueError) when too large
    volume->setSpacing(spacing);
    return volume;
}

py::dtype dtypeOf(VoxelType type)
{
    switch (type) {
    case VoxelType::UInt8: return py::dtype::of<std::uint8_t>();
    case VoxelType::Int8: return py::dtype::of<std::int8_t>();
    case VoxelType::UInt16: return py::dtype::of<std::uint16_t>();
    case VoxelType::Int16: return py::dtype::of<std::int16_t>();
    case VoxelType::Float32: return py::dtype::of<float>();
    }
    throw std::logic_error("unknown voxel type");
}

py::array blockView(const Volume& volume, int channel, int frame, const py::handle& owner)
{
    const osg::Vec3i& d = volume.dims();
    const auto item = py::ssize_t(voxelSize(volume.type()));
    const std::vector<py::ssize_t> shape{d.z(), d.y(), d.x()};
    const std::vector<py::ssize_t> strides{item * d.x() * d.y(), item * d.x(), item};
    py::array view(dtypeOf(volume.type()), shape, strides, volume.block(channel, frame), owner);
    // The renderer notices changes of a Volume by its modified count, which numpy cannot bump.
    view.attr("flags").attr("writeable") = false;
    return view;
}

py::array_t<float> imageToArray(const osg::Image& image)
{
    const int w = image.s(), h = image.t();
    py::array_t<float> rgba({py::ssize_t(h), py::ssize_t(w), py::ssize_t(4)});
    float* out = rgba.mutable_data();
    for (int y = 0; y < h; ++y)
        std::memcpy(out + std::size_t(y) * w * 4, image.data(0, h - 1 - y), std::size_t(w) * 4 * sizeof(float));
    return rgba;
}

osg::Vec3d vec3From(const py::handle& value, const std::string& what)
{
    std::vector<double> v;
    if (py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value))
        throw py::value_error(what + ": expected three numbers (x, y, z), got " + reprOf(value));
    try {
        for (const py::handle item : py::iter(value)) v.push_back(py::cast<double>(py::float_(py::reinterpret_borrow<py::object>(item))));
    } catch (const py::error_already_set&) {
        throw py::value_error(what + ": expected three numbers (x, y, z), got " + reprOf(value));
    } catch (const py::cast_error&) {
        throw py::value_error(what + ": expected three numbers (x, y, z), got " + reprOf(value));
    }
    if (v.size() != 3) throw py::value_error(what + ": expected three numbers (x, y, z), got " + reprOf(value));
    for (double c : v)
        if (!std::isfinite(c)) throw py::value_error(what + ": " + reprOf(value) + " is not finite");
    return osg::Vec3d(v[0], v[1], v[2]);
}

std::string pathFrom(const py::handle& value, const std::string& what)
{
    py::object path;
    try {
        path = py::module_::import("os").attr("fspath")(value);
    } catch (const py::error_already_set&) {
        throw py::type_error(what + ": expected a path (str or os.PathLike), got " + reprOf(value));
    }
    if (!py::isinstance<py::str>(path))
        throw py::type_error(what + ": expected a path as str, got " + reprOf(value));
    return path.cast<std::string>();
}

std::string reprOf(const py::handle& value)
{
    return py::repr(value).cast<std::string>();
}

}  // namespace volren::python
