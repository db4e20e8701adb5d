#pragma once
#include <volume_model/TransferFunction.h>
#include <volume_model/Volume.h>

#include <osg/Texture1D>
#include <osg/Texture3D>

namespace volren {

/// GL internal format keeping a voxel type's precision: R8, R8_SNORM, R16, R16_SNORM, R32F.
GLenum internalFormatFor(VoxelType type);
/// The internal format of a volume texture of `type`: 8-bit data in 16-bit texels when `wide`.
GLenum volumeTextureFormat(VoxelType type, bool wide);

/// GL pixel type of a voxel type's stored values.
GLenum pixelTypeFor(VoxelType type);

/// 3D texture of the volume's voxels at full precision; the image references (does not copy)
/// the Volume's buffer, so keep the Volume alive as long as the texture. `wide`: 8-bit data in
/// 16-bit texels (the same values; texturePrecision). `level`: instead of the voxels, that image
/// of a coarser level (VolumeMipChain.h), kept by the texture.
osg::ref_ptr<osg::Texture3D> makeVolumeTexture(const Volume& volume, bool wide = false, osg::Image* level = nullptr);

/// 3D texture of `image` (kept, not copied) in `internalFormat`, clamped to its edges, with
/// `filter` for minification and magnification.
osg::ref_ptr<osg::Texture3D> makeTexture3D(osg::Image* image, GLenum internalFormat, osg::Texture::FilterMode filter);

/// RGBA32F 1D lookup table of the transfer function (resolution() texels); `premultiplied`
/// stores associated colours (r*a, g*a, b*a, a).
osg::ref_ptr<osg::Texture1D> makeTransferFunctionTexture(const TransferFunction& tf, bool premultiplied = false);

}  // namespace volren
