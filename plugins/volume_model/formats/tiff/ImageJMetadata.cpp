#include "ImageJMetadata.h"

#include <volume_model/ParseNumber.h>

#include <sstream>
#include <stdexcept>

namespace volren::tiff {

namespace {

std::size_t parseCount(const std::string& key, const std::string& value, const std::string& name)
{
    double v = 0.0;
    if (!parseFiniteNumber(value, v) || v < 1.0 || v > 2147483647.0 || v != double(std::size_t(v)))
        throw std::runtime_error(name + ": ImageJ " + key + "=" + value + " is not a positive count");
    return std::size_t(v);
}

}  // namespace

bool isImageJDescription(const std::string& description)
{
    return description.rfind("ImageJ=", 0) == 0;
}

ImageJMetadata parseImageJDescription(const std::string& description, const std::string& name)
{
    ImageJMetadata meta;
    std::istringstream lines(description);
    std::string line;
    while (std::getline(lines, line)) {
        const std::size_t eq = line.find('=');
        if (eq == std::string::npos) continue;
        const std::string key = line.substr(0, eq), value = line.substr(eq + 1);
        if (key == "images") meta.images = parseCount(key, value, name);
        else if (key == "channels") meta.channels = parseCount(key, value, name);
        else if (key == "slices") meta.slices = parseCount(key, value, name);
        else if (key == "frames") meta.frames = parseCount(key, value, name);
        else if (key == "unit") {
            meta.unit = value;
            for (std::size_t at; (at = meta.unit.find("\\u00B5")) != std::string::npos;) meta.unit.replace(at, 6, "\xC2\xB5");
        } else if (key == "spacing") {
            double v = 0.0;
            if (!parseFiniteNumber(value, v) || !(v > 0.0))
                throw std::runtime_error(name + ": ImageJ spacing=" + value + " is not a positive number");
            meta.spacing = v;
        }
    }
    return meta;
}

StackLayout imageJLayout(const ImageJMetadata& meta, std::size_t pages, const std::string& name)
{
    StackLayout layout;
    layout.order = "CZT";
    layout.channels = meta.channels.value_or(1);
    layout.frames = meta.frames.value_or(1);
    const std::size_t images = meta.images.value_or(pages);
    if (meta.slices) {
        layout.slices = *meta.slices;
    } else {
        // ImageJ omits slices= for a plain time series or channel stack: the rest are slices.
        const std::size_t per = layout.channels * layout.frames;
        layout.slices = per > 0 && images % per == 0 ? images / per : 0;
    }
    const std::size_t product = layout.pageCount();
    const std::string counts = "channels=" + std::to_string(layout.channels) + " slices=" + std::to_string(layout.slices) +
                               " frames=" + std::to_string(layout.frames);
    if (product == 0 || product != images)
        throw std::runtime_error(name + ": ImageJ metadata does not add up: " + counts + " but images=" + std::to_string(images));
    if (images != pages)
        throw std::runtime_error(name + ": ImageJ metadata says images=" + std::to_string(images) + " (" + counts +
                                 ") but the file has " + std::to_string(pages) + " pages");
    return layout;
}

}  // namespace volren::tiff
