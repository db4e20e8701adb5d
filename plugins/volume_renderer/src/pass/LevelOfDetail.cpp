#include "LevelOfDetail.h"

#include <volume_renderer/VolumeMipChain.h>

#include <algorithm>
#include <cmath>

namespace volren {

int levelOfDetail(const VolumeCandidate& candidate, osgUtil::CullVisitor& cv)
{
    const VolumeNode& node = *candidate.node;
    const Volume& volume = *node.getVolume();
    const int last = mipLevelCount(volume.dims()) - 1;
    int level = node.settings.lod;
    if (node.settings.lodByDistance) {
        // The eye and the box's nearest point in the VolumeScene's axes (the cull's current frame).
        const osg::Vec3d eye = osg::Vec3d(0.0, 0.0, 0.0) * osg::Matrixd::inverse(*cv.getModelViewMatrix());
        const osg::BoundingBoxd& box = candidate.bound;
        const osg::Vec3d nearest(std::clamp(eye.x(), box.xMin(), box.xMax()), std::clamp(eye.y(), box.yMin(), box.yMax()),
                                 std::clamp(eye.z(), box.zMin(), box.zMax()));
        // OSG's pixel size of a sphere is its diameter in pixels: that of radius 1/2 spans one unit.
        const double pixelsPerUnit = cv.pixelSize(osg::Vec3(nearest), 0.5f);
        const osg::Vec3d scale = candidate.matrix.getScale();
        const double voxel = volume.minSpacing() * std::min({scale.x(), scale.y(), scale.z()});  // in scene units
        const double voxelsPerPixel = 1.0 / (std::abs(pixelsPerUnit) * voxel);
        if (nearest != eye && std::isfinite(voxelsPerPixel) && voxelsPerPixel >= 2.0)
            level += int(std::floor(std::log2(voxelsPerPixel)));
    }
    return std::clamp(level, 0, last);
}

}  // namespace volren
