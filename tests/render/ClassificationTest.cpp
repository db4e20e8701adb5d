// Transfer-function extremes: fully transparent shows exactly the background, fully opaque
// shows exactly the TF colour wherever a ray meets the box.
#include "RenderFixture.h"
#include "TestData.h"

namespace volren::test {
namespace {

class Classification : public RenderFixture
{
};

TEST_F(Classification, TransparentTransferFunctionRendersExactlyTheBackground)
{
    osg::ref_ptr<Volume> volume = constantVolume(VoxelType::UInt16, {10, 12, 14}, 3000);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(1, 0.5f, 0.2f, 0.0f), 0, 65535);
    const osg::Vec3 background(0.25f, 0.5f, 0.75f);
    for (bool jitter : {false, true}) {
        const Pixels img = renderOrthoFromPlusZ(volumeNode(volume.get(), tf.get(), jitter).get(), 24, 24, 24.0, background);
        for (const osg::Vec4& p : img.rgba) ASSERT_EQ(p, osg::Vec4(background, 0.0f));
    }
}

TEST_F(Classification, OpaqueTransferFunctionRendersExactlyTheColourInsideTheBox)
{
    osg::ref_ptr<Volume> volume = constantVolume(VoxelType::Int16, {8, 8, 8}, -1200);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0.2f, 0.6f, 0.9f, 1.0f), -2000, 2000);
    const Pixels img = renderOrthoFromPlusZ(volumeNode(volume.get(), tf.get(), true).get(), 16, 16, 16.0,
                                            osg::Vec3(1, 1, 1));
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const bool inside = x >= 4 && x <= 11 && y >= 4 && y <= 11;  // box covers pixels 4..11
            const osg::Vec4 expected = inside ? osg::Vec4(0.2f, 0.6f, 0.9f, 1.0f) : osg::Vec4(1, 1, 1, 0);
            for (int c = 0; c < 4; ++c) ASSERT_NEAR(img.at(x, y)[c], expected[c], 1e-6) << x << "," << y << " c" << c;
        }
}

TEST_F(Classification, ValueWindowSelectsTheTransferFunctionEntryOfTheDataValue)
{
    // Stored 40 with rescale 2.5x - 100 is data value 0; the TF is red below 0, green above.
    osg::ref_ptr<Volume> volume = constantVolume(VoxelType::UInt8, {8, 8, 8}, 40);
    volume->setRescale(2.5, -100.0);
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    tf->setPoint(-50.0, osg::Vec4(1, 0, 0, 1));
    tf->setPoint(-10.0, osg::Vec4(1, 0, 0, 1));
    tf->setPoint(10.0, osg::Vec4(0, 1, 0, 1));
    tf->setPoint(50.0, osg::Vec4(0, 1, 0, 1));
    tf->setResolution(4097);  // texel centres at -50 + k * 100/4096
    const Pixels img = renderOrthoFromPlusZ(volumeNode(volume.get(), tf.get()).get(), 16, 16, 16.0);
    // Data value 0 is halfway between the points at -10 and 10: (0.5, 0.5, 0, 1).
    const osg::Vec4& p = img.at(8, 8);
    EXPECT_NEAR(p.r(), 0.5, 1e-3);
    EXPECT_NEAR(p.g(), 0.5, 1e-3);
    EXPECT_NEAR(p.b(), 0.0, 1e-6);
    EXPECT_NEAR(p.a(), 1.0, 1e-6);
}

}  // namespace
}  // namespace volren::test
