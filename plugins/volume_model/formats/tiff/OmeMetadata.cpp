#include "OmeMetadata.h"

#include <volume_model/ParseNumber.h>

#include <cstdint>
#include <regex>
#include <stdexcept>

namespace volren::tiff {

namespace {

std::optional<std::string> attribute(const std::string& element, const std::string& key)
{
    const std::regex pattern("\\s" + key + "\\s*=\\s*[\"']([^\"']*)[\"']");
    std::smatch match;
    if (!std::regex_search(element, match, pattern)) return std::nullopt;
    return match[1].str();
}

std::size_t sizeAttribute(const std::string& element, const std::string& key, bool required, const std::string& name)
{
    const auto text = attribute(element, key);
    if (!text) {
        if (required) throw std::runtime_error(name + ": OME-XML <Pixels> has no " + key);
        return 1;
    }
    double v = 0.0;
    if (!parseFiniteNumber(*text, v) || v < 1.0 || v > 2147483647.0 || v != double(std::size_t(v)))
        throw std::runtime_error(name + ": OME-XML " + key + "=\"" + *text + "\" is not a positive count");
    return std::size_t(v);
}

std::optional<double> lengthAttribute(const std::string& element, const std::string& key, const std::string& name)
{
    const auto text = attribute(element, key);
    if (!text) return std::nullopt;
    double v = 0.0;
    if (!parseFiniteNumber(*text, v) || !(v > 0.0))
        throw std::runtime_error(name + ": OME-XML " + key + "=\"" + *text + "\" is not a positive length");
    return v;
}

}  // namespace

bool isOmeDescription(const std::string& description)
{
    return std::regex_search(description, std::regex("<([A-Za-z_][\\w.-]*:)?OME[\\s>]"));
}

OmeMetadata parseOmeDescription(const std::string& description, const std::string& name)
{
    std::smatch match;
    if (!std::regex_search(description, match, std::regex("<([A-Za-z_][\\w.-]*:)?Pixels\\s[^>]*>")))
        throw std::runtime_error(name + ": OME-XML without a <Pixels> element");
    const std::string element = match[0].str();
    OmeMetadata meta;
    meta.sizeX = sizeAttribute(element, "SizeX", true, name);
    meta.sizeY = sizeAttribute(element, "SizeY", true, name);
    meta.sizeZ = sizeAttribute(element, "SizeZ", false, name);
    meta.sizeC = sizeAttribute(element, "SizeC", false, name);
    meta.sizeT = sizeAttribute(element, "SizeT", false, name);
    const std::string order = attribute(element, "DimensionOrder").value_or("XYZCT");
    if (!parseDimensionOrder(order, meta.order))
        throw std::runtime_error(name + ": OME-XML DimensionOrder=\"" + order + "\" is not a permutation XY + Z, C, T");
    meta.physicalX = lengthAttribute(element, "PhysicalSizeX", name);
    meta.physicalY = lengthAttribute(element, "PhysicalSizeY", name);
    meta.physicalZ = lengthAttribute(element, "PhysicalSizeZ", name);
    if (meta.physicalX) meta.physicalUnit = attribute(element, "PhysicalSizeXUnit").value_or("\xC2\xB5m");
    // The <Channel> elements after this <Pixels> (up to the next image's).
    const std::string after = match.suffix().str();
    const std::regex channel("<([A-Za-z_][\\w.-]*:)?(Channel|Image)[\\s>][^>]*>");
    for (auto it = std::sregex_iterator(after.begin(), after.end(), channel); it != std::sregex_iterator(); ++it) {
        if ((*it)[2].str() == "Image") break;
        const std::string tag = (*it)[0].str();
        ChannelHint hint;
        hint.name = attribute(tag, "Name").value_or("");
        if (const auto colour = attribute(tag, "Color")) {
            try {
                std::size_t used = 0;
                const long long value = std::stoll(*colour, &used);
                // -1 (opaque white) is OME's default, which says nothing.
                if (used == colour->size() && value >= INT32_MIN && value <= UINT32_MAX && value != -1 &&
                    value != 0xffffffffLL) {
                    const auto rgba = std::uint32_t(std::int64_t(value) & 0xffffffff);
                    hint.colours = {osg::Vec3f(float((rgba >> 24) & 0xff) / 255.0f, float((rgba >> 16) & 0xff) / 255.0f,
                                               float((rgba >> 8) & 0xff) / 255.0f)};
                }
            } catch (const std::exception&) {  // a hint only: none
            }
        }
        meta.channels.push_back(hint);
    }
    const std::regex image("<([A-Za-z_][\\w.-]*:)?Image[\\s>]");
    meta.images = std::size_t(std::distance(std::sregex_iterator(description.begin(), description.end(), image),
                                            std::sregex_iterator()));
    return meta;
}

StackLayout omeLayout(const OmeMetadata& meta, std::size_t pages, std::size_t samplesPerPixel, const std::string& name)
{
    StackLayout layout;
    layout.order = meta.order;
    layout.slices = meta.sizeZ;
    layout.frames = meta.sizeT;
    layout.channels = meta.sizeC;
    if (samplesPerPixel > 1) {
        if (meta.sizeC % samplesPerPixel != 0)
            throw std::runtime_error(name + ": OME-XML SizeC=" + std::to_string(meta.sizeC) + " does not fit pages of " +
                                     std::to_string(samplesPerPixel) + " samples");
        layout.channels = meta.sizeC / samplesPerPixel;
    }
    if (layout.pageCount() != pages)
        throw std::runtime_error(name + ": OME-XML says SizeZ=" + std::to_string(meta.sizeZ) + " SizeC=" +
                                 std::to_string(meta.sizeC) + " SizeT=" + std::to_string(meta.sizeT) + " (" +
                                 std::to_string(layout.pageCount()) + " pages) but the file has " + std::to_string(pages) +
                                 " pages (multi-file OME-TIFF is not supported)");
    return layout;
}

}  // namespace volren::tiff
