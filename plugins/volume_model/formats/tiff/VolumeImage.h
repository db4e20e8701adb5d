#pragma once
#include <volume_model/Volume.h>

#include <osg/Image>

namespace volren::tiff {

/// The volume as an osg::Image (s, t, r = x, y, z; rows bottom-up as OSG expects), so that
/// osgDB::readImageFile on a .tif still gives an image: 1 channel → luminance, 3 → RGB,
/// 4 → RGBA of the first time point. Null for other channel counts.
osg::ref_ptr<osg::Image> volumeAsImage(const Volume& volume);

}  // namespace volren::tiff
