// A scene written to .osgt / .osgb and read back (osgdb_serializers_volren) renders
// bit-identically to the original: clip plane, light, two volumes with their settings.
#include "RenderFixture.h"
#include "TestData.h"

#include <volume_model/ClipPlaneNode.h>
#include <volume_model/ReadVolume.h>

#include <osg/LightSource>
#include <osg/MatrixTransform>
#include <osgDB/Registry>

#include <cstring>

namespace volren::test {
namespace {

class SceneRoundTrip : public RenderFixture, public ::testing::WithParamInterface<std::string>
{
};

/// A volume with a bright ball in a dim ramp, so lighting, gradients and clipping all show.
osg::ref_ptr<Volume> ballVolume()
{
    osg::ref_ptr<Volume> v = new Volume;
    const osg::Vec3i dims(20, 18, 16);
    v->allocate(VoxelType::UInt8, dims);
    v->setSpacing({1.0, 1.0, 1.25});
    std::size_t i = 0;
    for (int z = 0; z < dims.z(); ++z)
        for (int y = 0; y < dims.y(); ++y)
            for (int x = 0; x < dims.x(); ++x, ++i) {
                const osg::Vec3 d(x - 9.5f, y - 8.5f, z - 7.5f);
                v->data()[i] = std::uint8_t(d.length() < 6.0f ? 200 : 10 + 5 * x);
            }
    v->dirty();
    return v;
}

osg::ref_ptr<VolumeScene> makeScene()
{
    osg::ref_ptr<VolumeScene> scene = new VolumeScene;
    osg::ref_ptr<Volume> volume = ballVolume();
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    tf->setPoint(0.0, osg::Vec4(0.1f, 0.2f, 0.9f, 0.0f));
    tf->setPoint(100.0, osg::Vec4(0.2f, 0.8f, 0.3f, 0.05f));
    tf->setPoint(220.0, osg::Vec4(1.0f, 0.6f, 0.2f, 0.6f));

    osg::ref_ptr<VolumeNode> left = RenderFixture::volumeNode(volume.get(), tf.get());
    osg::ref_ptr<VolumeNode> right = RenderFixture::volumeNode(volume.get(), tf.get());
    std::string error;
    EXPECT_TRUE(right->settings.set("traversal", "mip", error)) << error;
    EXPECT_TRUE(right->settings.set("samplerate", "3", error)) << error;
    osg::ref_ptr<osg::MatrixTransform> leftPlace = new osg::MatrixTransform(osg::Matrix::translate(-11, 0, 0));
    leftPlace->addChild(left.get());
    // Turned about z by the angle of cos 0.6, sin 0.8: OSG writes its own matrices in .osgt with
    // 6 significant digits, so only entries exact in 6 digits come back as written (with 16-bit
    // texels, a rotation of 0.3 rad rounded to 0.955336 shows in the image).
    osg::ref_ptr<osg::MatrixTransform> rightPlace =
        new osg::MatrixTransform(osg::Matrix(0.6, 0.8, 0, 0, -0.8, 0.6, 0, 0, 0, 0, 1, 0, 11, 0, 0, 1));
    rightPlace->addChild(right.get());

    osg::ref_ptr<ClipPlaneNode> plane = new ClipPlaneNode;
    plane->plane.set(0.3, 1.0, 0.0, 2.0);
    osg::ref_ptr<osg::LightSource> light = new osg::LightSource;
    light->getLight()->setPosition(osg::Vec4(0.3f, 0.4f, 1.0f, 0.0f));

    scene->addChild(leftPlace.get());
    scene->addChild(rightPlace.get());
    scene->addChild(plane.get());
    scene->addChild(light.get());
    return scene;
}

TEST_P(SceneRoundTrip, ReadBackSceneRendersBitIdentical)
{
    registerPluginPath();
    osg::ref_ptr<VolumeScene> scene = makeScene();
    const Pixels before = renderOrthoFromPlusZ(scene.get(), 64, 48, 40.0, {0.05f, 0.05f, 0.05f});
    int covered = 0;
    for (const osg::Vec4& p : before.rgba) covered += p.a() > 0.05f;
    EXPECT_GT(covered, 200) << "the scene should show both volumes";

    const std::string path = tempDirectory() + "/scene." + GetParam();
    const auto written = osgDB::Registry::instance()->writeNode(*scene, path, nullptr);
    ASSERT_TRUE(written.success()) << written.message();
    osgDB::ReaderWriter::ReadResult read = osgDB::Registry::instance()->readNode(path, nullptr);
    ASSERT_TRUE(read.validNode()) << read.message();
    osg::ref_ptr<osg::Node> back = read.getNode();
    ASSERT_TRUE(dynamic_cast<VolumeScene*>(back.get()));

    const Pixels after = renderOrthoFromPlusZ(back.get(), 64, 48, 40.0, {0.05f, 0.05f, 0.05f});
    ASSERT_EQ(before.rgba.size(), after.rgba.size());
    EXPECT_EQ(0, std::memcmp(before.rgba.data(), after.rgba.data(), before.rgba.size() * sizeof(osg::Vec4)))
        << "the image changed after the round trip through ." << GetParam();
    // Same composition chosen from the read-back scene.
    EXPECT_EQ(scene->compositionKeys(), dynamic_cast<VolumeScene*>(back.get())->compositionKeys());
}

INSTANTIATE_TEST_SUITE_P(SceneRoundTrip, SceneRoundTrip, ::testing::Values("osgt", "osgb"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace volren::test
