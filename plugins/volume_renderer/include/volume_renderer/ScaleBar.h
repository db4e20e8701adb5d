#pragma once
#include <osg/Matrixd>
#include <osg/Vec3d>

namespace volren {

/// A scale bar for one view: a round length in world units and the pixels it spans on screen.
struct ScaleBar
{
    double length = 0.0;  ///< world units: 1, 2 or 5 times a power of ten (0: no bar fits)
    double pixels = 0.0;  ///< its image's length in pixels
};

/// Pixels one world unit spans on screen in the plane through world point `at` facing the
/// camera (`view`, `projection` as an osg::Camera's, a viewport `viewportWidth` pixels wide);
/// 0 when `at` is not in front of the camera.
double pixelsPerWorldUnit(const osg::Matrixd& view, const osg::Matrixd& projection, double viewportWidth,
                          const osg::Vec3d& at);

/// The longest round length (1, 2 or 5 times a power of ten) whose image at `at` spans at most
/// `maxPixels`; no bar (length 0) where `at` is not in front of the camera.
ScaleBar scaleBarFor(const osg::Matrixd& view, const osg::Matrixd& projection, double viewportWidth,
                     const osg::Vec3d& at, double maxPixels);

}  // namespace volren
