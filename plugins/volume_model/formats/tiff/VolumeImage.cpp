#include "VolumeImage.h"

#include <cstring>

namespace volren::tiff {

osg::ref_ptr<osg::Image> volumeAsImage(const Volume& volume)
{
    const int channels = volume.channels();
    GLenum pixelFormat = 0;
    switch (channels) {
    case 1: pixelFormat = GL_LUMINANCE; break;
    case 3: pixelFormat = GL_RGB; break;
    case 4: pixelFormat = GL_RGBA; break;
    default: return nullptr;
    }
    GLenum dataType = GL_UNSIGNED_BYTE;
    switch (volume.type()) {
    case VoxelType::UInt8: dataType = GL_UNSIGNED_BYTE; break;
    case VoxelType::Int8: dataType = GL_BYTE; break;
    case VoxelType::UInt16: dataType = GL_UNSIGNED_SHORT; break;
    case VoxelType::Int16: dataType = GL_SHORT; break;
    case VoxelType::Float32: dataType = GL_FLOAT; break;
    }
    const osg::Vec3i& d = volume.dims();
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(d.x(), d.y(), d.z(), pixelFormat, dataType);
    const std::size_t bytes = voxelSize(volume.type());
    for (int c = 0; c < channels; ++c) {
        const std::uint8_t* block = volume.block(c, 0);
        for (int z = 0; z < d.z(); ++z)
            for (int y = 0; y < d.y(); ++y) {
                const std::uint8_t* src = block + (std::size_t(z) * d.y() + y) * d.x() * bytes;
                auto* dst = image->data(0, d.y() - 1 - y, z);
                for (int x = 0; x < d.x(); ++x)
                    std::memcpy(dst + (std::size_t(x) * channels + c) * bytes, src + std::size_t(x) * bytes, bytes);
            }
    }
    image->setFileName(volume.sourceFile);
    return image;
}

}  // namespace volren::tiff
