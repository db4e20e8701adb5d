// CPU definitions of the clip shapes: what they keep, and when they change nothing.
#include <volume_model/ClipBoxNode.h>
#include <volume_model/ClipEllipsoidNode.h>
#include <volume_model/ClipMaskNode.h>
#include <volume_model/ClipPlaneNode.h>

#include <algorithm>
#include <cmath>

namespace volren {

namespace {

bool allKept(const ClipNode& clip, const std::array<osg::Vec3d, 8>& corners)
{
    for (const osg::Vec3d& c : corners)
        if (!clip.keeps(c)) return false;
    return true;
}

osg::BoundingBoxd boundsOf(const std::array<osg::Vec3d, 8>& corners)
{
    osg::BoundingBoxd b;
    for (const osg::Vec3d& c : corners) b.expandBy(c);
    return b;
}

}  // namespace

bool ClipPlaneNode::leavesUnchanged(const std::array<osg::Vec3d, 8>& corners) const
{
    return allKept(*this, corners);  // half-spaces are convex: corners decide
}

bool ClipBoxNode::leavesUnchanged(const std::array<osg::Vec3d, 8>& corners) const
{
    if (!invert) return allKept(*this, corners);  // box is convex
    return !boundsOf(corners).intersects(box);    // cut-away box misses the volume
}

osg::BoundingSphere ClipBoxNode::computeBound() const
{
    return osg::BoundingSphere(osg::BoundingBox(box._min, box._max));
}

bool ClipEllipsoidNode::inside(const osg::Vec3d& p) const
{
    const osg::Vec3d d(p - center);
    const double q = (d.x() / radii.x()) * (d.x() / radii.x()) + (d.y() / radii.y()) * (d.y() / radii.y()) +
                     (d.z() / radii.z()) * (d.z() / radii.z());
    return q <= 1.0;
}

bool ClipEllipsoidNode::leavesUnchanged(const std::array<osg::Vec3d, 8>& corners) const
{
    if (!invert) return allKept(*this, corners);  // ellipsoid is convex
    const osg::BoundingBoxd own(center - radii, center + radii);
    return !boundsOf(corners).intersects(own);
}

osg::BoundingSphere ClipEllipsoidNode::computeBound() const
{
    return osg::BoundingSphere(osg::Vec3(center), float(std::max({radii.x(), radii.y(), radii.z()})));
}

bool ClipMaskNode::inside(const osg::Vec3d& p) const
{
    if (!mask || mask->voxelCount() == 0) return false;
    const osg::Vec3d size = mask->worldSize();
    int index[3];
    for (int a = 0; a < 3; ++a) {
        const double t = (p[a] + 0.5 * size[a]) / size[a];  // [0,1] across the mask's box
        if (t < 0.0 || t > 1.0) return false;
        index[a] = std::min(int(t * mask->dims()[a]), mask->dims()[a] - 1);
    }
    return mask->value(index[0], index[1], index[2]) >= threshold;
}

osg::BoundingSphere ClipMaskNode::computeBound() const
{
    if (!mask) return osg::BoundingSphere();
    return osg::BoundingSphere(osg::Vec3(), float(mask->worldSize().length() * 0.5));
}

}  // namespace volren
