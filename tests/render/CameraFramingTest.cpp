// The default camera fits the scene's box: every corner inside the image less its margin, and
// as tight as the view allows (both sides of one axis touch the margin), for any aspect ratio,
// perspective and orthographic; turntable views keep one distance and fit in every frame.
#include <volume_renderer/CameraFraming.h>

#include <volume_model/VolumeNode.h>

#include <osg/Geode>
#include <osg/MatrixTransform>
#include <osg/Shape>
#include <osg/ShapeDrawable>
#include <gtest/gtest.h>

#include <algorithm>

namespace volren::test {
namespace {

/// A scene of a VolumeNode of `dims` unit voxels moved by `offset`, and a unit box at `boxAt`.
osg::ref_ptr<osg::Group> scene(const osg::Vec3i& dims, const osg::Vec3d& offset, const osg::Vec3d& boxAt)
{
    osg::ref_ptr<Volume> volume = new Volume;
    volume->assign(VoxelType::UInt8, dims, std::vector<std::uint8_t>(std::size_t(dims.x()) * dims.y() * dims.z(), 0));
    osg::ref_ptr<VolumeNode> node = new VolumeNode;
    node->setVolume(volume.get());
    osg::ref_ptr<osg::MatrixTransform> moved = new osg::MatrixTransform(osg::Matrixd::translate(offset));
    moved->addChild(node);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(new osg::ShapeDrawable(new osg::Box(boxAt, 1.0f)));
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(moved);
    root->addChild(geode);
    return root;
}

/// Normalised device x/y range of the eight corners of `box` seen through `view`.
std::array<double, 4> ndcRange(const osg::BoundingBoxd& box, const CameraView& view)
{
    std::array<double, 4> r{1e9, 1e9, -1e9, -1e9};
    for (int c = 0; c < 8; ++c) {
        const osg::Vec3d ndc = box.corner(c) * view.view * view.projection;
        r[0] = std::min(r[0], ndc.x());
        r[1] = std::min(r[1], ndc.y());
        r[2] = std::max(r[2], ndc.x());
        r[3] = std::max(r[3], ndc.y());
    }
    return r;
}

TEST(CameraFraming, SceneBoxHoldsVolumeBoxesAndDrawablesUnderTransforms)
{
    const osg::BoundingBoxd box = sceneBoundingBox(*scene({40, 4, 2}, {100, 0, 0}, {0, 0, 10}));
    EXPECT_NEAR(box.xMin(), -0.5, 1e-6);
    EXPECT_NEAR(box.xMax(), 120.0, 1e-6);
    EXPECT_NEAR(box.yMin(), -2.0, 1e-6);
    EXPECT_NEAR(box.yMax(), 2.0, 1e-6);
    EXPECT_NEAR(box.zMin(), -1.0, 1e-6);
    EXPECT_NEAR(box.zMax(), 10.5, 1e-6);
}

TEST(CameraFraming, EveryCornerIsInsideAndOneAxisTouchesTheMargin)
{
    const osg::ref_ptr<osg::Group> root = scene({200, 12, 30}, {7, -3, 40}, {-20, 5, 0});
    const osg::BoundingBoxd box = sceneBoundingBox(*root);
    for (double aspect : {0.2, 0.75, 1.0, 1.6, 5.0})
        for (bool ortho : {false, true})
            for (const osg::Vec3d& direction : {osg::Vec3d(0.55, 1.0, 0.35), osg::Vec3d(0, 0, 1), osg::Vec3d(-1, 0.1, 0)}) {
                CameraRequest request;
                request.orthographic = ortho;
                request.direction = direction;
                request.up = direction.z() == 1 ? osg::Vec3d(0, 1, 0) : osg::Vec3d(0, 0, 1);
                SCOPED_TRACE(testing::Message() << "aspect " << aspect << (ortho ? " ortho" : " perspective") << " direction "
                                                << direction.x() << "," << direction.y() << "," << direction.z());
                const auto r = ndcRange(box, frameScene(*root, request, aspect));
                const double fill = 1.0 - 2.0 * request.margin;
                for (double v : r) EXPECT_LE(std::abs(v), fill + 1e-9);
                const bool xTight = r[0] < -fill + 1e-6 && r[2] > fill - 1e-6;
                const bool yTight = r[1] < -fill + 1e-6 && r[3] > fill - 1e-6;
                EXPECT_TRUE(xTight || yTight) << r[0] << " " << r[1] << " " << r[2] << " " << r[3];
            }
}

TEST(CameraFraming, AGivenCentreStaysInTheMiddle)
{
    const osg::ref_ptr<osg::Group> root = scene({50, 50, 50}, {0, 0, 0}, {0, 0, 0});
    CameraRequest request;
    request.center = osg::Vec3d(10, 0, 0);
    const CameraView view = frameScene(*root, request, 1.5);
    const osg::Vec3d ndc = *request.center * view.view * view.projection;
    EXPECT_NEAR(ndc.x(), 0.0, 1e-9);
    EXPECT_NEAR(ndc.y(), 0.0, 1e-9);
    for (double v : ndcRange(sceneBoundingBox(*root), view)) EXPECT_LE(std::abs(v), 0.94 + 1e-9);
}

TEST(CameraFraming, TurntableViewsKeepOneDistanceAndFitEveryFrame)
{
    const osg::ref_ptr<osg::Group> root = scene({120, 20, 10}, {0, 0, 0}, {0, 0, 0});
    const osg::BoundingBoxd box = sceneBoundingBox(*root);
    for (bool ortho : {false, true}) {
        CameraRequest request;
        request.orthographic = ortho;
        const std::vector<CameraView> views = turntableViews(*root, request, 1.0, {0, 0, 1}, 12);
        ASSERT_EQ(views.size(), 12u);
        const double distance = (osg::Vec3d() * osg::Matrixd::inverse(views[0].view) - box.center()).length();
        double widest = 0.0;
        for (const CameraView& v : views) {
            EXPECT_NEAR((osg::Vec3d() * osg::Matrixd::inverse(v.view) - box.center()).length(), distance, 1e-6 * distance);
            EXPECT_TRUE(v.projection == views[0].projection);
            const auto r = ndcRange(box, v);
            for (double x : r) EXPECT_LE(std::abs(x), 0.94 + 1e-9);
            widest = std::max({widest, -r[0], r[2], -r[1], r[3]});
        }
        EXPECT_GT(widest, 0.94 - 1e-6) << "the widest frame touches the margin";
    }
}

TEST(CameraFraming, DegenerateRequestsAreErrors)
{
    const osg::ref_ptr<osg::Group> root = scene({4, 4, 4}, {0, 0, 0}, {0, 0, 0});
    CameraRequest same;
    same.eye = osg::Vec3d(1, 2, 3);
    same.center = osg::Vec3d(1, 2, 3);
    EXPECT_THROW(frameScene(*root, same, 1.0), std::invalid_argument);
    CameraRequest parallel;
    parallel.direction = osg::Vec3d(0, 0, 1);
    EXPECT_THROW(frameScene(*root, parallel, 1.0), std::invalid_argument);
    EXPECT_THROW(frameScene(*root, CameraRequest{}, 0.0), std::invalid_argument);
    EXPECT_THROW(turntableViews(*root, CameraRequest{}, 1.0, {0, 0, 0}, 4), std::invalid_argument);
    // An empty scene still gets a view (of the unit box).
    const osg::ref_ptr<osg::Group> empty = new osg::Group;
    EXPECT_NO_THROW(frameScene(*empty, CameraRequest{}, 1.0));
}

}  // namespace
}  // namespace volren::test
