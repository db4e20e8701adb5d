#include "ImageWriter.h"

#include <OpenImageIO/imageio.h>
#include <osgDB/FileNameUtils>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace volren::app {

namespace {

/// 8-bit RGB rows, top row first, of a read-back RGBA float image (row 0 at the bottom).
std::vector<std::uint8_t> rgb8TopDown(const osg::Image& image)
{
    const int w = image.s(), h = image.t();
    const float* src = reinterpret_cast<const float*>(image.data());
    std::vector<std::uint8_t> rows(std::size_t(w) * h * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                const float v = src[(std::size_t(h - 1 - y) * w + x) * 4 + c];
                const float clamped = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
                rows[(std::size_t(y) * w + x) * 3 + c] = std::uint8_t(std::lround(clamped * 255.0f));
            }
    return rows;
}

}  // namespace

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
        ok = out->write_image(OIIO::TypeDesc::UINT8, rgb8TopDown(image).data());
    }
    if (!ok || !out->close()) throw std::runtime_error(path + ": " + out->geterror());
}

void writeAnimatedGif(const std::vector<osg::ref_ptr<osg::Image>>& frames, const std::string& path, int fps)
{
    if (frames.empty()) throw std::runtime_error(path + ": no frames to write");
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) throw std::runtime_error(path + ": cannot write GIF images (" + OIIO::geterror() + ")");
    if (!out->supports("multiimage")) throw std::runtime_error(path + ": OpenImageIO's GIF writer cannot append frames");
    std::vector<OIIO::ImageSpec> specs;
    for (const auto& frame : frames) {
        OIIO::ImageSpec spec(frame->s(), frame->t(), 3, OIIO::TypeDesc::UINT8);
        const int rate[2] = {fps, 1};
        spec.attribute("FramesPerSecond", OIIO::TypeRational, rate);
        spec.attribute("oiio:Movie", 1);
        spec.attribute("oiio:LoopCount", 0);  // forever
        specs.push_back(spec);
    }
    if (!out->open(path, int(specs.size()), specs.data())) throw std::runtime_error(path + ": " + out->geterror());
    for (std::size_t i = 0; i < frames.size(); ++i) {
        if (i > 0 && !out->open(path, specs[i], OIIO::ImageOutput::AppendSubimage))
            throw std::runtime_error(path + ": " + out->geterror());
        if (!out->write_image(OIIO::TypeDesc::UINT8, rgb8TopDown(*frames[i]).data()))
            throw std::runtime_error(path + ": " + out->geterror());
    }
    if (!out->close()) throw std::runtime_error(path + ": " + out->geterror());
}

std::string numberedPath(const std::string& path, int frame)
{
    char number[16];
    std::snprintf(number, sizeof number, "_%04d", frame);
    const std::string ext = osgDB::getFileExtensionIncludingDot(path);
    return osgDB::getNameLessExtension(path) + number + ext;
}

}  // namespace volren::app
