// Multi-channel volumes (VolumeNode::channels): every visible channel drawn with its own
// transfer function in one ray, media adding as in a multi-volume set (optical depths add,
// emission mixes by extinction), against closed forms and the reference.
#include "ReferenceComparison.h"
#include "TestData.h"

#include <volume_model/ChannelDisplay.h>
#include <volume_model/DefaultScene.h>
#include <volume_model/ReadVolume.h>
#include <volume_reference/ReferenceSetup.h>
#include <volume_renderer/SceneSettings.h>

#include <osg/MatrixTransform>

#include <cmath>
#include <cstring>

namespace volren::test {
namespace {

class MultiChannel : public RenderFixture
{
protected:
    static constexpr int n = 16;          ///< voxels per axis (spacing 1), centred at the origin
    static constexpr double alpha = 0.1;  ///< each channel's TF opacity per voxel where it is bright

    /// `channels` channels of n^3 8-bit voxels: channel c stores 200 where `bright(c, x, y, z)`, else 0.
    template <class Bright>
    static osg::ref_ptr<Volume> channelVolume(int channels, Bright bright)
    {
        osg::ref_ptr<Volume> v = new Volume;
        v->allocate(VoxelType::UInt8, {n, n, n}, channels);
        for (int c = 0; c < channels; ++c) {
            std::uint8_t* voxels = v->block(c);
            for (int z = 0; z < n; ++z)
                for (int y = 0; y < n; ++y)
                    for (int x = 0; x < n; ++x) voxels[x + n * (y + n * z)] = bright(c, x, y, z) ? 200 : 0;
        }
        v->dirty();
        return v;
    }
    /// A node showing every channel of `volume` in its palette colour, opacity `alpha` above 100.
    static osg::ref_ptr<VolumeNode> channelNode(Volume* volume)
    {
        osg::ref_ptr<VolumeNode> node = volumeNode(volume, colourWindowTransferFunction({1, 1, 1}, 0, 100, alpha).get());
        node->settings.earlyTerminationThreshold = 1.0;
        for (int c = 0; c < volume->channels(); ++c)
            node->channels.push_back({true, colourWindowTransferFunction(channelColour(c), 0, 100, alpha)});
        return node;
    }
    static osg::ref_ptr<VolumeScene> unlit(osg::Node* node)
    {
        osg::ref_ptr<VolumeScene> scene = new VolumeScene;
        scene->addChild(node);
        return scene;
    }
};

TEST_F(MultiChannel, FourChannelsInSlabsShowEachColourWithItsClosedFormOpacity)
{
    // Channel c is bright in the slab 4c <= x < 4c + 4: seen along z, a pixel over the middle of
    // slab c shows channel c's colour through 16 voxels of opacity alpha: 1 - (1 - alpha)^16.
    osg::ref_ptr<Volume> volume = channelVolume(4, [](int c, int x, int, int) { return x / 4 == c; });
    osg::ref_ptr<VolumeNode> node = channelNode(volume.get());
    osg::ref_ptr<VolumeScene> scene = unlit(node.get());
    const Pixels img = renderOrthoFromPlusZ(scene.get(), 32, 32, 16.0);  // two pixels per voxel
    ASSERT_EQ(scene->programs().size(), 1u) << "one program, one ray, for the four channels";
    const double a = 1.0 - std::pow(1.0 - alpha, n);
    for (int c = 0; c < 4; ++c) {
        const osg::Vec3 colour = channelColour(c);
        for (int x = 8 * c + 3; x <= 8 * c + 4; ++x)  // the slab's middle pixels (away from its faces)
            for (int y = 4; y < 28; ++y) {
                ASSERT_NEAR(img.at(x, y).a(), a, 2e-3) << "channel " << c << " pixel " << x << "," << y;
                for (int k = 0; k < 3; ++k) ASSERT_NEAR(img.at(x, y)[k], colour[k] * a, 2e-3) << "channel " << c;
            }
    }
}

TEST_F(MultiChannel, OverlappingChannelsAddTheirOpticalDepthsAndMixTheirColours)
{
    // Two channels bright everywhere: extinctions add (transmittance (1 - alpha)^32 through the
    // box) and, both equally strong, each colour has half the emission: (green + magenta) / 2.
    osg::ref_ptr<Volume> volume = channelVolume(2, [](int, int, int, int) { return true; });
    osg::ref_ptr<VolumeScene> scene = unlit(channelNode(volume.get()).get());
    const Pixels img = renderOrthoFromPlusZ(scene.get(), 32, 32, 32.0);
    const double a = 1.0 - std::pow(1.0 - alpha, 2 * n);
    const osg::Vec3 mixed = (channelColour(0) + channelColour(1)) * 0.5f;
    for (int y = 12; y < 20; ++y)
        for (int x = 12; x < 20; ++x) {
            ASSERT_NEAR(img.at(x, y).a(), a, 2e-3) << x << "," << y;
            for (int k = 0; k < 3; ++k) ASSERT_NEAR(img.at(x, y)[k], mixed[k] * a, 2e-3) << x << "," << y;
        }
}

TEST_F(MultiChannel, TurningChannelOneOffGivesTheChannelZeroImageExactly)
{
    osg::ref_ptr<Volume> volume = channelVolume(2, [](int c, int x, int y, int z) { return (x + y + z + c) % 3 != 0; });
    osg::ref_ptr<VolumeNode> node = channelNode(volume.get());
    osg::ref_ptr<VolumeScene> scene = unlit(node.get());
    applySetting(*scene, "channels", "0");  // as `--set channels=0`
    EXPECT_FALSE(node->channels[1].visible);
    const Pixels one = renderOrthoFromPlusZ(scene.get(), 24, 24, 20.0);
    osg::ref_ptr<VolumeNode> alone = volumeNode(channelOf(*volume, 0).get(), node->channels[0].transferFunction.get());
    alone->settings = node->settings;
    const Pixels zero = renderOrthoFromPlusZ(unlit(alone.get()).get(), 24, 24, 20.0);
    double covered = 0.0;
    for (std::size_t i = 0; i < one.rgba.size(); ++i) {
        covered += one.rgba[i].a();
        for (int k = 0; k < 4; ++k) ASSERT_EQ(one.rgba[i][k], zero.rgba[i][k]) << "pixel " << i;
    }
    EXPECT_GT(covered, 50.0) << "channel 0 shows";
    applySetting(*scene, "channels", "all");
    EXPECT_TRUE(node->channels[1].visible);
    for (const char* bad : {"2", "0,x", "-1", ""}) {
        try {
            applySetting(*scene, "channels", bad);
            ADD_FAILURE() << bad << " was accepted";
        } catch (const SettingError& e) {
            EXPECT_NE(std::string(e.what()).find("channels="), std::string::npos) << e.what();
        }
    }
    EXPECT_TRUE(node->channels[1].visible) << "a refused value changes nothing";
}

TEST_F(MultiChannel, AdditiveBlendingAddsEachChannelsOwnImage)
{
    // `traversal=additive`: no channel occludes another. Two channels bright everywhere each show
    // their own 1 - (1 - alpha)^16 in their colour, and the images add: colour
    // (green + magenta) * a (clamped to 1), coverage 1 - (1 - a)^2.
    osg::ref_ptr<Volume> volume = channelVolume(2, [](int, int, int, int) { return true; });
    osg::ref_ptr<VolumeNode> node = channelNode(volume.get());
    osg::ref_ptr<VolumeScene> scene = unlit(node.get());
    applySetting(*scene, "traversal", "additive");
    const Pixels img = renderOrthoFromPlusZ(scene.get(), 32, 32, 32.0);
    ASSERT_EQ(scene->programs().size(), 1u) << "both channels in one program";
    const double a = 1.0 - std::pow(1.0 - alpha, n);
    const osg::Vec3 sum = channelColour(0) + channelColour(1);
    for (int y = 12; y < 20; ++y)
        for (int x = 12; x < 20; ++x) {
            ASSERT_NEAR(img.at(x, y).a(), 1.0 - (1.0 - a) * (1.0 - a), 2e-3) << x << "," << y;
            for (int k = 0; k < 3; ++k) ASSERT_NEAR(img.at(x, y)[k], std::min(1.0, sum[k] * a), 2e-3) << x << "," << y;
        }
}

TEST_F(MultiChannel, MipThenAdditiveClassifiesEachChannelsMaximumAndAddsThem)
{
    // `traversal=mip` on a multi-channel node (or `mip_additive`): each channel's maximum along
    // the ray through its own TF, the colours added. Channel 0 rises along z as 8z + x (its
    // maximum, seen along z, is at the last voxel: 120 + x), channel 1 is 100 everywhere; both
    // through a window 0..255 at full opacity, so a channel's colour is scaled by max / 255.
    osg::ref_ptr<Volume> volume = new Volume;
    volume->allocate(VoxelType::UInt8, {n, n, n}, 2);
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                volume->block(0)[x + n * (y + n * z)] = std::uint8_t(8 * z + x);
                volume->block(1)[x + n * (y + n * z)] = 100;
            }
    volume->dirty();
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), colourWindowTransferFunction({1, 1, 1}, 0, 255).get());
    for (int c = 0; c < 2; ++c) node->channels.push_back({true, colourWindowTransferFunction(channelColour(c), 0, 255)});
    osg::ref_ptr<VolumeScene> scene = unlit(node.get());
    applySetting(*scene, "traversal", "mip");
    const Pixels img = renderOrthoFromPlusZ(scene.get(), 32, 32, 16.0);  // two pixels per voxel
    ASSERT_EQ(scene->programs().size(), 1u) << "both channels in one program";
    const double a1 = 100.0 / 255.0;
    for (int px = 2; px < 30; ++px) {
        const double x = (px + 0.5) / 2.0 - 0.5;  // voxel coordinate of the pixel's centre
        const double a0 = (120.0 + x) / 255.0;
        for (int y = 4; y < 28; y += 5) {
            ASSERT_NEAR(img.at(px, y).a(), 1.0 - (1.0 - a0) * (1.0 - a1), 3e-3) << px << "," << y;
            for (int k = 0; k < 3; ++k)
                ASSERT_NEAR(img.at(px, y)[k], std::min(1.0, channelColour(0)[k] * a0 + channelColour(1)[k] * a1), 3e-3)
                    << px << "," << y << " component " << k;
        }
    }
    applySetting(*scene, "traversal", "mip_additive");
    const Pixels named = renderOrthoFromPlusZ(scene.get(), 32, 32, 16.0);
    for (std::size_t i = 0; i < img.rgba.size(); ++i) ASSERT_EQ(img.rgba[i], named.rgba[i]) << "pixel " << i;
}

TEST_F(MultiChannel, ASingleVolumeNamedAdditiveIsDrawnAsPlainDvr)
{
    osg::ref_ptr<Volume> volume = channelVolume(1, [](int, int x, int y, int z) { return (x + y + z) % 3 != 0; });
    osg::ref_ptr<VolumeNode> node = channelNode(volume.get());
    osg::ref_ptr<VolumeScene> scene = unlit(node.get());
    const Pixels dvr = renderOrthoFromPlusZ(scene.get(), 24, 24, 20.0);
    applySetting(*scene, "traversal", "additive");
    const Pixels additive = renderOrthoFromPlusZ(scene.get(), 24, 24, 20.0);
    for (std::size_t i = 0; i < dvr.rgba.size(); ++i) ASSERT_EQ(dvr.rgba[i], additive.rgba[i]) << "pixel " << i;
}

TEST_F(MultiChannel, AChannelsOpacityScaleActsAsItsTransferFunctionWithScaledOpacity)
{
    // `channelOpacity=1:3`: channel 1 shows as through its TF with three times the opacity
    // (0.3 per voxel); in the overlap slab test, channel 1's slab reaches 1 - 0.7^16.
    osg::ref_ptr<Volume> volume = channelVolume(2, [](int c, int x, int, int) { return x / 8 == c; });
    osg::ref_ptr<VolumeNode> node = channelNode(volume.get());
    osg::ref_ptr<VolumeScene> scene = unlit(node.get());
    applySetting(*scene, "channelOpacity", "1:3");
    EXPECT_EQ(node->channels[0].opacity, 1.0);
    EXPECT_EQ(node->channels[1].opacity, 3.0);
    const Pixels img = renderOrthoFromPlusZ(scene.get(), 32, 32, 16.0);
    for (int y = 4; y < 28; ++y) {
        ASSERT_NEAR(img.at(7, y).a(), 1.0 - std::pow(1.0 - alpha, n), 2e-3) << y;
        ASSERT_NEAR(img.at(24, y).a(), 1.0 - std::pow(1.0 - 3.0 * alpha, n), 2e-3) << y;
    }
    const unsigned int edits = node->channels[1].transferFunction->modifiedCount();
    applySetting(*scene, "channelOpacity", "0.5");
    EXPECT_EQ(node->channels[0].opacity, 0.5);
    EXPECT_EQ(node->channels[1].opacity, 0.5);
    EXPECT_EQ(node->channels[1].transferFunction->modifiedCount(), edits) << "the channel's own TF is not edited";
    const Pixels half = renderOrthoFromPlusZ(scene.get(), 32, 32, 16.0);
    EXPECT_NEAR(half.at(7, 16).a(), 1.0 - std::pow(1.0 - 0.5 * alpha, n), 2e-3);
    for (const char* bad : {"-1", "x", "0:", "2:1", "1:2,3", ""}) {
        try {
            applySetting(*scene, "channelOpacity", bad);
            ADD_FAILURE() << bad << " was accepted";
        } catch (const SettingError& e) {
            EXPECT_NE(std::string(e.what()).find("channelOpacity="), std::string::npos) << e.what();
        }
    }
}

TEST_F(MultiChannel, MipVolumesThatDoNotOverlapCompositeFrontToBackInTheRendererAndTheReference)
{
    // Two MIP cubes one behind the other along z (boxes apart: two ray groups): each shows its
    // classified maximum, the front one over the back one: c_f a_f + (1 - a_f) c_b a_b; the
    // reference composites its groups the same way (it adds maxima only within a group).
    auto cube = [](std::uint8_t value, const osg::Vec3& colour, double z) {
        osg::ref_ptr<Volume> v = new Volume;
        v->allocate(VoxelType::UInt8, {n, n, n});
        std::fill(v->data(), v->data() + v->voxelCount(), value);
        v->dirty();
        osg::ref_ptr<osg::MatrixTransform> placed = new osg::MatrixTransform(osg::Matrixd::translate(0, 0, z));
        placed->addChild(volumeNode(v.get(), colourWindowTransferFunction(colour, 0, 255).get()).get());
        return placed;
    };
    osg::ref_ptr<VolumeScene> scene = new VolumeScene;
    scene->addChild(cube(100, {0, 1, 0}, 10.0).get());   // front (nearer the camera at +z)
    scene->addChild(cube(200, {1, 0, 1}, -10.0).get());  // back
    applySetting(*scene, "traversal", "mip");
    const int size = 24;
    const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, 60), osg::Vec3d(), osg::Vec3d(0, 1, 0));
    const osg::Matrixd projection = osg::Matrixd::ortho(-12, 12, -12, 12, 1, 120);
    const Pixels gpu = render(scene.get(), size, size, view, projection);
    ReferenceCamera camera;
    camera.view = view;
    camera.projection = projection;
    camera.width = camera.height = size;
    const ReferenceSetup setup = referenceSetup(*scene, camera, {});
    const ReferenceImage truth = renderReference(setup.scene, camera, setup.options);
    const double af = 100.0 / 255.0, ab = 200.0 / 255.0;
    const osg::Vec3 expected = osg::Vec3(0, 1, 0) * float(af) + osg::Vec3(1, 0, 1) * float((1.0 - af) * ab);
    for (int y = 6; y < 18; ++y)
        for (int x = 6; x < 18; ++x) {
            ASSERT_NEAR(gpu.at(x, y).a(), 1.0 - (1.0 - af) * (1.0 - ab), 3e-3) << x << "," << y;
            ASSERT_NEAR(truth.at(x, y, 3), 1.0 - (1.0 - af) * (1.0 - ab), 1e-6) << x << "," << y;
            for (int k = 0; k < 3; ++k) {
                ASSERT_NEAR(gpu.at(x, y)[k], expected[k], 3e-3) << x << "," << y << " component " << k;
                ASSERT_NEAR(truth.at(x, y, k), expected[k], 1e-6) << x << "," << y << " component " << k;
            }
        }
}

/// The shared 2-channel DNA stack (confocal, widefield) in its default scene: both channels
/// through the file's LUTs (magenta, green) over their windows, unlit, one ray, blended as
/// `traversal` says; against the reference of the same blending.
class ConfocalBlending : public RenderFixture, public ::testing::WithParamInterface<const char*>
{
};

TEST_P(ConfocalBlending, TheSharedConfocalStackShowsBothChannelsAsTheReferenceOfItsBlendingDoes)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string mode = GetParam();
    osg::ref_ptr<Volume> stack = readVolumeFile(sharedData("microscopy/xyzc_16bit__dna_conf_wf.tif"));
    ASSERT_EQ(stack->channels(), 2);
    osg::ref_ptr<osg::Group> loaded = makeDefaultScene(stack.get());
    auto* scene = dynamic_cast<VolumeScene*>(loaded.get());
    ASSERT_TRUE(scene);
    ASSERT_EQ(findFirstVolumeNode(scene)->channels.size(), 2u);
    applySetting(*scene, "traversal", mode);
    applySetting(*scene, "earlyTermination", "1");
    applySetting(*scene, "samplerate", "2");
    const int size = 40;
    const osg::BoundingSphere bound = scene->getBound();
    const ReferenceCamera camera = perspectiveCamera(size, osg::Vec3d(bound.center()) + osg::Vec3d(0.6, -1.2, 0.9) * (2.2 * bound.radius()),
                                                     osg::Vec3d(bound.center()), 40, 0.5 * bound.radius(), 6.0 * bound.radius());
    const Pixels gpu = render(scene, size, size, camera.view, camera.projection);
    ASSERT_EQ(scene->programs().size(), 1u) << "both channels in one program";
    const ReferenceSetup setup = referenceSetup(*scene, camera, {});
    ASSERT_EQ(setup.scene.volumes.size(), 2u) << "the reference places both channels";
    EXPECT_EQ(setup.scene.volumes[1].blending, mode == "composite"  ? ReferenceScene::Blending::Media
                                    : mode == "additive" ? ReferenceScene::Blending::Images
                                                         : ReferenceScene::Blending::Maxima);
    const ReferenceImage truth = renderReference(setup.scene, camera, setup.options);
    const Difference d = differenceOf(gpu, truth, size);
    RecordProperty("rmse", std::to_string(d.rmse));
    RecordProperty("max", std::to_string(d.worst));
    // Both colours appear: magenta (red and blue) of the confocal channel, green of the widefield.
    double green = 0.0, magenta = 0.0;
    int shown = 0;  // MIP shows a channel's colour times its opacity: at most 0.2 by default
    for (const osg::Vec4& p : gpu.rgba) green += p.g(), magenta += std::min(p.r(), p.b()), shown += p.a() > 0.02f;
    EXPECT_GT(green, 0.5);
    EXPECT_GT(magenta, 0.5);
    EXPECT_GT(shown, 100);
    // Measured on llvmpipe: composite 7.9e-5 (max 4.4e-3), additive 1.8e-4 (9.3e-3), mip 2.2e-4 (0.011).
    EXPECT_LT(d.rmse, mode == "composite" ? 4e-4 : 6e-4) << "max " << d.worst;
    EXPECT_LT(d.worst, mode == "composite" ? 0.02 : 0.03);
}

INSTANTIATE_TEST_SUITE_P(Modes, ConfocalBlending, ::testing::Values("composite", "additive", "mip"));

}  // namespace
}  // namespace volren::test
