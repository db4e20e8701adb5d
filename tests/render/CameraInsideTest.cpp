// A camera inside the volume sees the medium between its near plane and the box faces.
// Expected per pixel in closed form: 1 - (1-alpha)^(L/d0), L = near plane -> box exit.
#include "RenderFixture.h"
#include "TestData.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace volren::test {
namespace {

class CameraInside : public RenderFixture
{
};

/// Distance along the unit ray (origin p, direction d) to the exit of the box |x_i| <= half_i.
double exitDistance(const osg::Vec3d& p, const osg::Vec3d& d, const osg::Vec3d& half)
{
    double t = 1e300;
    for (int a = 0; a < 3; ++a)
        if (d[a] != 0.0) t = std::min(t, ((d[a] > 0 ? half[a] : -half[a]) - p[a]) / d[a]);
    return t;
}

TEST_F(CameraInside, PerspectiveCameraSeesTheMediumInFrontOfItsNearPlane)
{
    const osg::Vec3i dims(20, 16, 24);
    const osg::Vec3d spacing(1.0, 1.5, 1.0);
    const double alpha = 0.04, nearDistance = 0.5;
    osg::ref_ptr<Volume> volume = constantVolume(VoxelType::Float32, dims, 0.5, spacing);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(1, 1, 1, float(alpha)), 0.0, 1.0);
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get(), true);
    node->settings.earlyTerminationThreshold = 1.0;

    // Camera at (1, -2, 3) inside the box (half sizes 10, 12, 12), looking along -z.
    const osg::Vec3d eye(1.0, -2.0, 3.0);
    const int w = 33, h = 25;
    const double fovy = 60.0, aspect = double(w) / h;
    const osg::Matrixd view = osg::Matrixd::lookAt(eye, eye + osg::Vec3d(0, 0, -1), osg::Vec3d(0, 1, 0));
    const osg::Matrixd projection = osg::Matrixd::perspective(fovy, aspect, nearDistance, 100.0);
    const Pixels img = render(node.get(), w, h, view, projection);

    const osg::Vec3d half(10.0, 12.0, 12.0);
    const double tanY = std::tan(osg::DegreesToRadians(fovy) * 0.5), tanX = tanY * aspect;
    double worst = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // Pixel centre on the near plane, in world coordinates (camera axes = world axes).
            const double nx = ((x + 0.5) / w * 2.0 - 1.0) * tanX, ny = ((y + 0.5) / h * 2.0 - 1.0) * tanY;
            osg::Vec3d onNear = eye + osg::Vec3d(nx, ny, -1.0) * nearDistance;
            osg::Vec3d dir(nx, ny, -1.0);
            dir.normalize();
            const double length = exitDistance(onNear, dir, half);
            const double expected = -std::expm1(length / 1.0 * std::log1p(-alpha));
            const osg::Vec4& p = img.at(x, y);
            worst = std::max(worst, std::abs(p.a() - expected));
            ASSERT_NEAR(p.a(), expected, 2e-5) << "pixel " << x << "," << y << " path " << length;
            ASSERT_NEAR(p.r(), expected, 2e-5) << "pixel " << x << "," << y;
        }
    std::ostringstream error;
    error << std::scientific << std::setprecision(2) << worst;
    RecordProperty("max_abs_error", error.str());
}

TEST_F(CameraInside, OrthographicCameraInsideStartsAtTheNearPlane)
{
    osg::ref_ptr<Volume> volume = constantVolume(VoxelType::UInt8, {16, 16, 16}, 200);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0.5f, 1, 0.25f, 0.1f));
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get());
    node->settings.earlyTerminationThreshold = 1.0;
    // Eye at the centre; near plane 3 units ahead: 5 units of medium remain before the face at z=-8.
    const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, 0), osg::Vec3d(0, 0, -1), osg::Vec3d(0, 1, 0));
    const osg::Matrixd projection = osg::Matrixd::ortho(-4, 4, -4, 4, 3.0, 50.0);
    const Pixels img = render(node.get(), 8, 8, view, projection);
    const double expected = 1.0 - std::pow(0.9, 5.0);
    for (const osg::Vec4& p : img.rgba) {
        ASSERT_NEAR(p.a(), expected, 1e-4);
        ASSERT_NEAR(p.r(), 0.5 * expected, 1e-4);
        ASSERT_NEAR(p.b(), 0.25 * expected, 1e-4);
    }
}

}  // namespace
}  // namespace volren::test
