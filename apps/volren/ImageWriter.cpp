#include "ImageWriter.h"

#include <OpenImageIO/imageio.h>
#include <osgDB/FileNameUtils>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace volren::app {

void writeImage(const osg::Image& image, const std::string& path)
{
    const int w = image.s(), h = image.t();
    const float* src = reinterpret_cast<const float*>(image.data());
    const std::string ext = osgDB::getLowerCaseFileExtension(path);
    const bool floatOutput = ext == "exr";

    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) throw std::runtime_error(path + ": cannot write images of type '." + ext + "' (" + OIIO::geterror() + ")");
    const int channels = floatOutput ? 4 : 3;
    OIIO::ImageSpec spec(w, h, channels, floatOutput ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    if (!out->open(path, spec)) throw std::runtime_error(path + ": " + out->geterror());

    bool ok = false;
    if (floatOutput) {
        std::vector<float> rows(std::size_t(w) * h * 4);
        for (int y = 0; y < h; ++y)
            std::copy_n(src + std::size_t(h - 1 - y) * w * 4, std::size_t(w) * 4, rows.data() + std::size_t(y) * w * 4);
        ok = out->write_image(OIIO::TypeDesc::FLOAT, rows.data());
    } else {
        std::vector<std::uint8_t> rows(std::size_t(w) * h * 3);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c) {
                    const float v = src[(std::size_t(h - 1 - y) * w + x) * 4 + c];
                    const float clamped = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
                    rows[(std::size_t(y) * w + x) * 3 + c] = std::uint8_t(std::lround(clamped * 255.0f));
                }
        ok = out->write_image(OIIO::TypeDesc::UINT8, rows.data());
    }
    if (!ok || !out->close()) throw std::runtime_error(path + ": " + out->geterror());
}

}  // namespace volren::app
