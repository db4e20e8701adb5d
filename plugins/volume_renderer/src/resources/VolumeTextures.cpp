#include <volume_renderer/VolumeTextures.h>

#include <osg/Image>

namespace volren {

GLenum pixelTypeFor(VoxelType type)
{
    switch (type) {
    case VoxelType::UInt8: return GL_UNSIGNED_BYTE;
    case VoxelType::Int8: return GL_BYTE;
    case VoxelType::UInt16: return GL_UNSIGNED_SHORT;
    case VoxelType::Int16: return GL_SHORT;
    case VoxelType::Float32: return GL_FLOAT;
    }
    return GL_UNSIGNED_BYTE;
}

GLenum internalFormatFor(VoxelType type)
{
    switch (type) {
    case VoxelType::UInt8: return GL_R8;
    case VoxelType::Int8: return GL_R8_SNORM;
    case VoxelType::UInt16: return GL_R16;
    case VoxelType::Int16: return GL_R16_SNORM;
    case VoxelType::Float32: return GL_R32F;
    }
    return GL_R8;
}

GLenum volumeTextureFormat(VoxelType type, bool wide)
{
    return !wide ? internalFormatFor(type)
           : type == VoxelType::UInt8 ? GLenum(GL_R16)
           : type == VoxelType::Int8  ? GLenum(GL_R16_SNORM)
                                      : internalFormatFor(type);
}

osg::ref_ptr<osg::Texture3D> makeVolumeTexture(const Volume& volume, bool wide, osg::Image* level)
{
    // 8-bit data as 16-bit texels: GL converts on upload, v / 255 becomes v * 257 / 65535, the same value.
    const GLenum format = volumeTextureFormat(volume.type(), wide);
    osg::ref_ptr<osg::Image> image = level;
    if (!image) {
        image = new osg::Image;
        const osg::Vec3i& d = volume.dims();
        image->setImage(d.x(), d.y(), d.z(), format, GL_RED, pixelTypeFor(volume.type()),
                        const_cast<unsigned char*>(volume.data()), osg::Image::NO_DELETE, 1);
    }
    image->setInternalTextureFormat(format);
    osg::ref_ptr<osg::Texture3D> texture = makeTexture3D(image.get(), format, osg::Texture::LINEAR);
    texture->setName(volume.getName());
    return texture;
}

osg::ref_ptr<osg::Texture3D> makeTexture3D(osg::Image* image, GLenum internalFormat, osg::Texture::FilterMode filter)
{
    osg::ref_ptr<osg::Texture3D> texture = new osg::Texture3D(image);
    texture->setInternalFormat(internalFormat);
    texture->setResizeNonPowerOfTwoHint(false);
    texture->setUnRefImageDataAfterApply(false);
    texture->setFilter(osg::Texture::MIN_FILTER, filter);
    texture->setFilter(osg::Texture::MAG_FILTER, filter);
    for (auto wrap : {osg::Texture::WRAP_S, osg::Texture::WRAP_T, osg::Texture::WRAP_R})
        texture->setWrap(wrap, osg::Texture::CLAMP_TO_EDGE);
    return texture;
}

osg::ref_ptr<osg::Texture1D> makeTransferFunctionTexture(const TransferFunction& tf, bool premultiplied)
{
    std::vector<osg::Vec4> table = tf.lookupTable();
    if (premultiplied)
        for (osg::Vec4& c : table) c = osg::Vec4(c.r() * c.a(), c.g() * c.a(), c.b() * c.a(), c.a());
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(int(table.size()), 1, 1, GL_RGBA, GL_FLOAT);
    image->setInternalTextureFormat(GL_RGBA32F_ARB);
    std::copy(table.begin(), table.end(), reinterpret_cast<osg::Vec4*>(image->data()));
    osg::ref_ptr<osg::Texture1D> texture = new osg::Texture1D(image.get());
    texture->setInternalFormat(GL_RGBA32F_ARB);
    texture->setResizeNonPowerOfTwoHint(false);
    texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::LINEAR);
    texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::LINEAR);
    texture->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_EDGE);
    return texture;
}

}  // namespace volren
