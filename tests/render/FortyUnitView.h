#pragma once
// The view the multi-volume tests read pixels from: renderOrthoFromPlusZ at 40x40 pixels over
// 40 world units centred on the origin (pixel (i, j) covers x in [i - 20, i - 19]), and the
// check of one pixel against an expected colour and opacity.
#include "RenderFixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace volren::test {

/// The pixel of world point (x, y) in that view.
inline const osg::Vec4& pixelAt(const Pixels& p, double x, double y)
{
    return p.at(int(std::floor(x + 20.0)), int(std::floor(y + 20.0)));
}

/// `got` within `tolerance` of `want` in every channel (`what` names the pixel).
inline void expectNear(const osg::Vec4& got, const osg::Vec4d& want, double tolerance, const std::string& what)
{
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], tolerance) << what << ", channel " << c;
}

}  // namespace volren::test
