#include <volume_renderer/ScaleBar.h>

#include <cmath>

namespace volren {

double pixelsPerWorldUnit(const osg::Matrixd& view, const osg::Matrixd& projection, double viewportWidth,
                          const osg::Vec3d& at)
{
    // Two points one unit apart along the eye's x axis, at the depth of `at`, projected.
    const osg::Vec3d eye = at * view;
    const osg::Vec4d a = osg::Vec4d(eye, 1.0) * projection;
    const osg::Vec4d b = osg::Vec4d(eye + osg::Vec3d(1.0, 0.0, 0.0), 1.0) * projection;
    if (!(a.w() > 0.0) || !(b.w() > 0.0)) return 0.0;
    const double ndc = std::abs(b.x() / b.w() - a.x() / a.w());
    return std::isfinite(ndc) ? 0.5 * viewportWidth * ndc : 0.0;
}

ScaleBar scaleBarFor(const osg::Matrixd& view, const osg::Matrixd& projection, double viewportWidth,
                     const osg::Vec3d& at, double maxPixels)
{
    const double perUnit = pixelsPerWorldUnit(view, projection, viewportWidth, at);
    if (!(perUnit > 0.0) || !(maxPixels > 0.0)) return {};
    const double longest = maxPixels / perUnit;
    double decade = std::pow(10.0, std::floor(std::log10(longest)));
    double length = decade;
    for (double step : {2.0, 5.0, 10.0})
        if (step * decade <= longest * (1.0 + 1e-12)) length = step * decade;
    return {length, length * perUnit};
}

}  // namespace volren
