// A volume's mip levels, built on the CPU by the model's mean reduction (separable passes, x then
// y then z per level), so NaN voxels and odd sizes follow one rule on every driver and in files
// opened lazily.
#include <volume_renderer/VolumeMipChain.h>
#include <volume_renderer/VolumeTextures.h>

#include <volume_model/MeanReduction.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace volren {

osg::Vec3i mipDims(const osg::Vec3i& dims, int level)
{
    return meanLevelDims(dims, level);
}

int mipLevelCount(const osg::Vec3i& dims)
{
    return meanLevelCount(dims);
}

double mipVoxelSpan(const osg::Vec3i& dims, int level)
{
    const osg::Vec3i d = mipDims(dims, level);
    return std::max({double(dims.x()) / d.x(), double(dims.y()) / d.y(), double(dims.z()) / d.z()});
}

std::vector<osg::ref_ptr<osg::Image>> mipLevelImages(const Volume& volume, int levels)
{
    const osg::Vec3i d0 = volume.dims();
    levels = std::clamp(levels, 0, mipLevelCount(d0) - 1);
    const std::size_t voxelBytes = voxelSize(volume.type());
    std::vector<osg::ref_ptr<osg::Image>> out;
    if (levels == 0) return out;
    // The model's reduction (MeanReduction.h), so levels a lazy file computes equal these.
    std::vector<float> values(volume.voxelCount());
    storedToFloat(volume.type(), volume.data(), values.size(), values.data());
    osg::Vec3i dims = d0;
    for (int l = 1; l <= levels; ++l) {
        values = meanNextLevel(values, dims);
        dims = mipDims(d0, l);
        auto* data = new unsigned char[values.size() * voxelBytes];
        floatToStored(volume.type(), values.data(), values.size(), data);
        osg::ref_ptr<osg::Image> image = new osg::Image;
        image->setImage(dims.x(), dims.y(), dims.z(), internalFormatFor(volume.type()), GL_RED, pixelTypeFor(volume.type()),
                        data, osg::Image::USE_NEW_DELETE, 1);
        out.push_back(image);
    }
    return out;
}

}  // namespace volren
