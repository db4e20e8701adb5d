#include "ImageStackReader.h"

#include "SpacingOption.h"

#include <volume_model/LoadProgress.h>

#include <osg/Notify>

#include <OpenImageIO/imageio.h>

#include <cstring>
#include <stdexcept>

namespace volren::imagestack {

namespace {

/// Size, channels and pixel type that every image of the stack must share.
struct ImageFormat
{
    int width = 0, height = 0, channels = 0;
    OIIO::TypeDesc fileType;

    std::string describe() const
    {
        return std::to_string(width) + "x" + std::to_string(height) + ", " + std::to_string(channels) + " channel(s) of " +
               fileType.c_str();
    }
    bool operator==(const ImageFormat& o) const
    {
        return width == o.width && height == o.height && channels == o.channels && fileType == o.fileType;
    }
};

/// Stored voxel type for pixels of `type`, and the type OIIO converts them to.
VoxelType storedType(OIIO::TypeDesc type, OIIO::TypeDesc& readAs)
{
    switch (type.basetype) {
    case OIIO::TypeDesc::UINT8: readAs = OIIO::TypeDesc::UINT8; return VoxelType::UInt8;
    case OIIO::TypeDesc::INT8: readAs = OIIO::TypeDesc::INT8; return VoxelType::Int8;
    case OIIO::TypeDesc::UINT16: readAs = OIIO::TypeDesc::UINT16; return VoxelType::UInt16;
    case OIIO::TypeDesc::INT16: readAs = OIIO::TypeDesc::INT16; return VoxelType::Int16;
    default: readAs = OIIO::TypeDesc::FLOAT; return VoxelType::Float32;
    }
}

std::unique_ptr<OIIO::ImageInput> openImage(const std::string& path, ImageFormat& format)
{
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        std::string why = OIIO::geterror();
        throw std::runtime_error(path + ": cannot read image" + (why.empty() ? "" : ": " + why));
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.depth > 1) throw std::runtime_error(path + ": is a 3D image (depth " + std::to_string(spec.depth) + "); expected 2D");
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
        throw std::runtime_error(path + ": empty image");
    format = ImageFormat{spec.width, spec.height, spec.nchannels, spec.format};
    return in;
}

}  // namespace

const std::vector<std::string>& imageExtensions()
{
    static const std::vector<std::string> list{"png", "jpg", "jpeg", "tif", "tiff", "bmp", "exr", "hdr", "pgm",
                                               "ppm", "pnm", "tga", "webp", "jp2", "dpx", "sgi", "rgb"};
    return list;
}

osg::ref_ptr<Volume> readImageStack(const std::vector<std::string>& files, const std::string& name,
                                    const osgDB::Options* options)
{
    if (files.empty()) throw std::runtime_error(name + ": zero images");
    std::optional<osg::Vec3d> spacing;
    try {
        spacing = stack::spacingOption(options);
    } catch (const std::exception& e) {
        throw std::runtime_error(name + ": " + e.what());
    }

    ImageFormat first;
    openImage(files.front(), first);
    OIIO::TypeDesc readAs;
    const VoxelType type = storedType(first.fileType, readAs);
    if (files.size() > 2147483647u) throw std::runtime_error(name + ": too many images");
    osg::ref_ptr<Volume> volume = new Volume;
    try {
        volume->allocate(type, osg::Vec3i(first.width, first.height, int(files.size())), first.channels, 1);
    } catch (const std::bad_alloc&) {
        throw std::runtime_error(name + ": not enough memory for " + std::to_string(files.size()) + " images of " + first.describe());
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(name + ": " + e.what());
    }

    const std::size_t bytes = voxelSize(type);
    const std::size_t pixels = std::size_t(first.width) * std::size_t(first.height);
    std::vector<std::uint8_t> interleaved(pixels * std::size_t(first.channels) * bytes);
    for (std::size_t z = 0; z < files.size(); ++z) {
        ImageFormat format;
        auto in = openImage(files[z], format);
        if (!(format == first))
            throw std::runtime_error(files[z] + ": image is " + format.describe() + " but " + files.front() + " is " +
                                     first.describe());
        if (!in->read_image(0, 0, 0, first.channels, readAs, interleaved.data())) {
            std::string why = in->geterror();
            throw std::runtime_error(files[z] + ": cannot decode image" + (why.empty() ? "" : ": " + why));
        }
        for (int c = 0; c < first.channels; ++c) {
            std::uint8_t* dst = volume->block(c, 0) + z * pixels * bytes;
            for (std::size_t i = 0; i < pixels; ++i)
                std::memcpy(dst + i * bytes, interleaved.data() + (i * std::size_t(first.channels) + std::size_t(c)) * bytes, bytes);
        }
        if (!reportLoadProgress(options, double(z + 1), double(files.size())))
            throw std::runtime_error(name + ": cancelled");
    }
    if (spacing) volume->setSpacing(*spacing);
    volume->dirty();
    volume->sourceFile = name;
    volume->setName(name);
    if (type == VoxelType::Float32 && first.fileType.basetype != OIIO::TypeDesc::FLOAT)
        OSG_NOTICE << name << ": " << first.fileType.c_str() << " pixels stored as float32" << std::endl;
    if (type == VoxelType::Float32 && volume->nonFiniteCount() > 0)
        OSG_WARN << name << ": " << volume->nonFiniteCount() << " NaN/Inf voxels; they are treated as empty" << std::endl;
    return volume;
}

}  // namespace volren::imagestack
