// Screen annotations (Annotations.h): the scale bar's round length against closed forms of the
// camera, drawn where and as long as it says, the axis gizmo turning with the view, and the
// rest of the image left exactly as it was.
#include "RenderFixture.h"

#include <volume_renderer/Annotations.h>
#include <volume_renderer/VolumeScene.h>

#include <volume_model/ChannelDisplay.h>

#include <cmath>

namespace volren::test {
namespace {

TEST(ScaleBar, OrthographicAndPerspectiveLengthsMatchTheirClosedForms)
{
    // Orthographic, 100 world units over 200 pixels: 2 px per unit; at most 40 px: 20 units.
    const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, 50), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 1, 0));
    const ScaleBar ortho = scaleBarFor(view, osg::Matrixd::ortho(-50, 50, -50, 50, 1, 100), 200, {3, -2, 7}, 40);
    EXPECT_DOUBLE_EQ(ortho.length, 20.0);
    EXPECT_NEAR(ortho.pixels, 40.0, 1e-9);
    // Perspective, 60 degrees vertical, square, 300 px, the point 10 units ahead: the view is
    // 2 * 10 * tan(30 deg) = 11.547 units wide, 25.98 px per unit; at most 60 px: 2 units.
    const osg::Matrixd perspective = osg::Matrixd::perspective(60, 1, 0.1, 100);
    const double perUnit = 300.0 / (20.0 * std::tan(osg::DegreesToRadians(30.0)));
    EXPECT_NEAR(pixelsPerWorldUnit(view, perspective, 300, {0, 0, 40}), perUnit, 1e-9);
    const ScaleBar far = scaleBarFor(view, perspective, 300, {4, 1, 40}, 60);
    EXPECT_DOUBLE_EQ(far.length, 2.0);
    EXPECT_NEAR(far.pixels, 2.0 * perUnit, 1e-9);
    EXPECT_DOUBLE_EQ(scaleBarFor(view, perspective, 300, {0, 0, 40}, 5.0 * perUnit).length, 5.0);
    EXPECT_DOUBLE_EQ(scaleBarFor(view, perspective, 300, {0, 0, 40}, 0.99 * perUnit).length, 0.5);
    EXPECT_EQ(scaleBarFor(view, perspective, 300, {0, 0, 60}, 60).length, 0.0) << "behind the camera: no bar";
}

class AnnotationsRender : public RenderFixture
{
protected:
    /// A 16-voxel cube of spacing 0.5 µm, 8 µm wide, faintly grey, at the origin.
    static osg::ref_ptr<VolumeScene> cubeScene()
    {
        osg::ref_ptr<Volume> volume = new Volume;
        volume->allocate(VoxelType::UInt8, {16, 16, 16});
        std::fill(volume->data(), volume->data() + volume->voxelCount(), std::uint8_t(200));
        volume->setSpacing({0.5, 0.5, 0.5});
        volume->dirty();
        osg::ref_ptr<VolumeScene> scene = new VolumeScene;
        scene->addChild(volumeNode(volume.get(), colourWindowTransferFunction({0.2f, 0.2f, 0.2f}, 0, 100, 0.05).get()).get());
        return scene;
    }
};

TEST_F(AnnotationsRender, TheScaleBarSpansItsLengthInPixelsAndTheRestOfTheImageIsUntouched)
{
    // 64 px over 20 world units: 3.2 px per unit; a fifth of the width is 12.8 px: a 2 unit bar,
    // 6.4 px long, its right end barMargin from the right edge, barThickness high.
    osg::ref_ptr<VolumeScene> scene = cubeScene();
    const Pixels plain = renderOrthoFromPlusZ(scene.get(), 64, 64, 20.0);
    osg::ref_ptr<Annotations> annotations = new Annotations;
    annotations->setScaleBar(true);
    annotations->setUnit("\xC2\xB5m");
    scene->addChild(annotations.get());
    const Pixels marked = renderOrthoFromPlusZ(scene.get(), 64, 64, 20.0);
    EXPECT_DOUBLE_EQ(annotations->shownScaleBar().length, 2.0);
    EXPECT_NEAR(annotations->shownScaleBar().pixels, 6.4, 1e-9);
    EXPECT_EQ(annotations->shownLabel(), "2 \xC2\xB5m");
    const int row = int(Annotations::barMargin + 1);  // inside the bar's rows 20..24
    int white = 0, first = 64, last = -1;
    for (int x = 0; x < 64; ++x)
        if (marked.at(x, row).r() > 0.99f && marked.at(x, row).g() > 0.99f) ++white, first = std::min(first, x), last = std::max(last, x);
    EXPECT_EQ(last, 64 - int(Annotations::barMargin) - 1) << "the bar's right end";
    EXPECT_NEAR(white, 6.4, 1.0) << "pixel centres inside [64 - 20 - 6.4, 64 - 20]";
    // Away from the bar and its label (centred over the bar, 14 px high), the image is the plain one.
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            if (x >= 12 && y < 46) continue;
            ASSERT_EQ(marked.at(x, y), plain.at(x, y)) << x << "," << y;
        }
    // The label is drawn above the bar.
    int labelled = 0;
    for (int y = row + 4; y < 44; ++y)
        for (int x = 12; x < 64; ++x) labelled += marked.at(x, y).r() > 0.5f && !(plain.at(x, y).r() > 0.5f);
    EXPECT_GT(labelled, 5) << "the label's glyphs";
}

TEST_F(AnnotationsRender, TheAxisGizmoTurnsWithTheView)
{
    osg::ref_ptr<VolumeScene> scene = cubeScene();
    osg::ref_ptr<Annotations> annotations = new Annotations;
    annotations->setAxes(true);
    scene->addChild(annotations.get());
    const int size = 128;
    const double o = Annotations::gizmoOffset, l = Annotations::gizmoLength;
    auto colourAt = [](const Pixels& p, double x, double y) { return p.at(int(x), int(y)); };
    auto red = [](const osg::Vec4& c) { return c.r() > 0.8f && c.g() < 0.4f; };
    auto green = [](const osg::Vec4& c) { return c.g() > 0.7f && c.r() < 0.4f; };
    auto blue = [](const osg::Vec4& c) { return c.b() > 0.9f && c.r() < 0.4f; };
    // From +z, y up: x points right, y up, z at the viewer (a dot at the origin).
    const osg::Matrixd fromZ = osg::Matrixd::lookAt(osg::Vec3d(0, 0, 30), osg::Vec3d(), osg::Vec3d(0, 1, 0));
    const osg::Matrixd projection = osg::Matrixd::ortho(-10, 10, -10, 10, 1, 60);
    const Pixels z = render(scene.get(), size, size, fromZ, projection);
    EXPECT_TRUE(red(colourAt(z, o + 0.7 * l, o))) << "x to the right";
    EXPECT_TRUE(green(colourAt(z, o, o + 0.7 * l))) << "y up";
    EXPECT_FALSE(red(colourAt(z, o - 0.7 * l, o)));
    EXPECT_FALSE(green(colourAt(z, o, o - 0.7 * l)));
    // From +x, z up: y points right, z up, x at the viewer.
    const osg::Matrixd fromX = osg::Matrixd::lookAt(osg::Vec3d(30, 0, 0), osg::Vec3d(), osg::Vec3d(0, 0, 1));
    const Pixels x = render(scene.get(), size, size, fromX, projection);
    EXPECT_TRUE(green(colourAt(x, o + 0.7 * l, o))) << "y to the right";
    EXPECT_TRUE(blue(colourAt(x, o, o + 0.7 * l))) << "z up";
    EXPECT_FALSE(red(colourAt(x, o + 0.7 * l, o)));
    // Beside a panel column (volren view), the gizmo moves right of it.
    annotations->setLeftMargin(40.0);
    const Pixels moved = render(scene.get(), size, size, fromX, projection);
    EXPECT_TRUE(green(colourAt(moved, 40.0 + o + 0.7 * l, o))) << "y to the right, 40 pixels on";
    EXPECT_FALSE(green(colourAt(moved, o + 0.7 * l, o))) << "not where it was";
    annotations->setLeftMargin(0.0);
    // Turned 45 degrees about z from the +x view: x and y both lean, at 0.707 of their length.
    const osg::Matrixd diagonal = osg::Matrixd::lookAt(osg::Vec3d(30, 30, 0), osg::Vec3d(), osg::Vec3d(0, 0, 1));
    const Pixels d = render(scene.get(), size, size, diagonal, projection);
    const double s = 0.5 * l * std::sqrt(0.5);  // half way along each leaning axis
    EXPECT_TRUE(red(colourAt(d, o - s, o))) << "x leans left";
    EXPECT_TRUE(green(colourAt(d, o + s, o))) << "y leans right";
}

}  // namespace
}  // namespace volren::test
