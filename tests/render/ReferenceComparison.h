#pragma once
// GPU images against the CPU reference: the camera both render and the difference of the two.
#include "RenderFixture.h"

#include <volume_reference/ReferenceRenderer.h>

#include <algorithm>
#include <cmath>

namespace volren::test {

/// A square perspective view of `size` pixels from `eye` to `centre`, +z up.
inline ReferenceCamera perspectiveCamera(int size, const osg::Vec3d& eye, const osg::Vec3d& centre, double fovy,
                                         double zNear, double zFar)
{
    ReferenceCamera c;
    c.width = c.height = size;
    c.view = osg::Matrixd::lookAt(eye, centre, osg::Vec3d(0, 0, 1));
    c.projection = osg::Matrixd::perspective(fovy, 1.0, zNear, zFar);
    return c;
}

/// A GPU image against the reference over all four channels.
struct Difference
{
    double rmse = 0.0;
    double worst = 0.0;
    int covered = 0;  ///< pixels the reference covers with alpha > 0.1
};

/// The difference of a square GPU image of `size` pixels and the reference.
inline Difference differenceOf(const Pixels& gpu, const ReferenceImage& truth, int size)
{
    Difference d;
    double sumSquares = 0.0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            d.covered += truth.at(x, y, 3) > 0.1;
            for (int c = 0; c < 4; ++c) {
                const double e = double(gpu.at(x, y)[c]) - truth.at(x, y, c);
                sumSquares += e * e;
                d.worst = std::max(d.worst, std::abs(e));
            }
        }
    d.rmse = std::sqrt(sumSquares / (size * size * 4));
    return d;
}

}  // namespace volren::test
