#include "ImageFiles.h"
#include "Conversions.h"

#include <OpenImageIO/imageio.h>
#include <osgDB/FileNameUtils>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace py = pybind11;

namespace volren::python {

void saveImage(const py::handle& given, const std::string& path)
{
    using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;
    FloatArray image;
    try {
        image = FloatArray::ensure(given);
    } catch (const py::error_already_set&) {
    }
    if (!image) throw py::type_error("image: expected a numpy array of numbers, got " + reprOf(py::type::handle_of(given)));
    if (image.ndim() != 3 || (image.shape(2) != 3 && image.shape(2) != 4))
        throw py::value_error("image: expected shape (height, width, 3 or 4), got " + reprOf(image.attr("shape")));
    const int h = int(image.shape(0)), w = int(image.shape(1)), givenChannels = int(image.shape(2));
    if (w < 1 || h < 1) throw py::value_error("image: empty");
    const std::string ext = osgDB::getLowerCaseFileExtension(path);
    const bool floatOutput = ext == "exr";

    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) throw std::runtime_error(path + ": cannot write images of type '." + ext + "' (" + OIIO::geterror() + ")");
    const int channels = floatOutput ? givenChannels : 3;
    const OIIO::ImageSpec spec(w, h, channels, floatOutput ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    if (!out->open(path, spec)) throw std::runtime_error(path + ": " + out->geterror());
    const float* src = image.data();
    bool ok = false;
    if (floatOutput) {
        ok = out->write_image(OIIO::TypeDesc::FLOAT, src);
    } else {
        std::vector<std::uint8_t> rgb(std::size_t(w) * h * 3);
        for (std::size_t p = 0; p < std::size_t(w) * h; ++p)
            for (int c = 0; c < 3; ++c) {
                const float v = src[p * givenChannels + c];
                const float clamped = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
                rgb[p * 3 + c] = std::uint8_t(std::lround(clamped * 255.0f));
            }
        ok = out->write_image(OIIO::TypeDesc::UINT8, rgb.data());
    }
    if (!ok || !out->close()) throw std::runtime_error(path + ": " + out->geterror());
}

py::array_t<float> readImage(const std::string& path)
{
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error(path + ": cannot read image (" + OIIO::geterror() + ")");
    const OIIO::ImageSpec& spec = in->spec();
    py::array_t<float> image({py::ssize_t(spec.height), py::ssize_t(spec.width), py::ssize_t(spec.nchannels)});
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.mutable_data()))
        throw std::runtime_error(path + ": " + in->geterror());
    in->close();
    return image;
}

}  // namespace volren::python
