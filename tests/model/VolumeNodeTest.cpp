#include "TestData.h"

#include <volume_model/DefaultScene.h>
#include <volume_model/VolumeNode.h>

#include <osg/LightSource>
#include <gtest/gtest.h>

namespace volren::test {
namespace {

TEST(VolumeNode, BoundIsTheCentredBoxOfDimsTimesSpacing)
{
    osg::ref_ptr<Volume> v = constantVolume(VoxelType::UInt8, {10, 20, 30}, 0, {2.0, 1.0, 0.5});
    osg::ref_ptr<VolumeNode> node = new VolumeNode;
    EXPECT_FALSE(node->getBound().valid());
    node->setVolume(v.get());
    const osg::BoundingBox box = node->localBox();
    EXPECT_EQ(osg::Vec3d(box._min), osg::Vec3d(-10, -10, -7.5));
    EXPECT_EQ(osg::Vec3d(box._max), osg::Vec3d(10, 10, 7.5));
    const osg::BoundingSphere bound = node->getBound();
    EXPECT_NEAR(bound.center().length(), 0.0, 1e-9);
    EXPECT_NEAR(bound.radius(), std::sqrt(10.0 * 10 + 10 * 10 + 7.5 * 7.5), 1e-4);
}

TEST(VolumeNode, SeveralNodesShareOneVolumeWithTheirOwnSettings)
{
    osg::ref_ptr<Volume> v = constantVolume(VoxelType::UInt8, {4, 4, 4}, 0);
    osg::ref_ptr<VolumeNode> a = new VolumeNode, b = new VolumeNode;
    a->setVolume(v.get());
    b->setVolume(v.get());
    a->settings.sampleDistanceFactor = 2.0;
    EXPECT_EQ(a->getVolume(), b->getVolume());
    EXPECT_NE(a->settings, b->settings);
}

TEST(DefaultScene, HoldsTheVolumeAnAutomaticTransferFunctionAndAHeadlight)
{
    osg::ref_ptr<Volume> v = new Volume;
    v->allocate(VoxelType::UInt8, {16, 16, 16});
    for (std::size_t i = 0; i < v->voxelCount(); ++i) v->data()[i] = std::uint8_t(i % 3 == 0 ? 200 : 10);
    v->dirty();
    osg::ref_ptr<osg::Group> scene = makeDefaultScene(v.get());
    EXPECT_EQ(std::string(scene->libraryName()) + "::" + scene->className(), "volren::VolumeScene")
        << "the root is the volume pass, so a stock OSG viewer renders the volume";
    VolumeNode* node = findFirstVolumeNode(scene.get());
    ASSERT_NE(node, nullptr);
    EXPECT_EQ(node->getVolume(), v.get());
    const TransferFunction* tf = node->getTransferFunction();
    ASSERT_NE(tf, nullptr);
    EXPECT_EQ(tf->evaluate(10.0).a(), 0.0f) << "background below the Otsu threshold is transparent";
    EXPECT_GT(tf->evaluate(200.0).a(), 0.1f) << "the bright population is visible";
    bool light = false;
    for (unsigned i = 0; i < scene->getNumChildren(); ++i) light = light || dynamic_cast<osg::LightSource*>(scene->getChild(i));
    EXPECT_TRUE(light);
}

}  // namespace
}  // namespace volren::test

namespace volren::test {
namespace {

/// Two channels of 10^3 16-bit voxels: channel c holds (c + 1) * 1000 + the voxel index mod 100.
osg::ref_ptr<Volume> twoChannels()
{
    osg::ref_ptr<Volume> v = new Volume;
    v->allocate(VoxelType::UInt16, {10, 10, 10}, 2);
    for (int c = 0; c < 2; ++c) {
        auto* voxels = reinterpret_cast<std::uint16_t*>(v->block(c));
        for (int i = 0; i < 1000; ++i) voxels[i] = std::uint16_t((c + 1) * 1000 + i % 100);
    }
    v->dirty();
    return v;
}

TEST(VolumeNodeChannels, EachChannelIsDrawnByANodeOfItsOwnVoxelsTfAndSettings)
{
    osg::ref_ptr<Volume> v = twoChannels();
    osg::ref_ptr<VolumeNode> node = makeDefaultVolumeNode(v.get());
    ASSERT_EQ(node->channels.size(), 2u);
    ASSERT_TRUE(node->drawsBlocks());
    node->settings.parameters["ambient"] = 0.5;
    std::vector<VolumeNode*> drawn = node->drawnNodes();
    ASSERT_EQ(drawn.size(), 2u);
    for (int c = 0; c < 2; ++c) {
        const Volume& one = *drawn[std::size_t(c)]->getVolume();
        EXPECT_EQ(one.channels(), 1);
        EXPECT_EQ(one.value(3, 0, 0), (c + 1) * 1000 + 3);  // its own channel's voxels
        EXPECT_EQ(drawn[std::size_t(c)]->getTransferFunction(), node->channels[std::size_t(c)].transferFunction.get());
        EXPECT_EQ(drawn[std::size_t(c)]->settings.parameters.at("ambient"), ParameterValue(0.5));
    }
    EXPECT_EQ(node->drawnNodes(), drawn) << "the same nodes from call to call (renderers keep their textures)";
    node->showChannels({1});
    ASSERT_EQ(node->drawnNodes().size(), 1u);
    EXPECT_EQ(node->drawnNodes()[0], drawn[1]);
    EXPECT_THROW(node->showChannels({2}), std::out_of_range);
    // A changed volume is copied again (into the same node); a single-channel node draws itself.
    osg::ref_ptr<const Volume> before = drawn[0]->getVolume();  // held: its address stays its own
    v->dirty();
    node->showChannels({0, 1});
    EXPECT_EQ(node->drawnNodes()[0], drawn[0]);
    EXPECT_NE(drawn[0]->getVolume(), before.get());
    osg::ref_ptr<VolumeNode> plain = makeDefaultVolumeNode(constantVolume(VoxelType::UInt8, {4, 4, 4}, 7).get());
    EXPECT_TRUE(plain->channels.empty());
    EXPECT_EQ(plain->drawnNodes(), std::vector<VolumeNode*>{plain.get()});
}

TEST(VolumeNodeChannels, TheFluorescenceDefaultGivesEachChannelItsPaletteColourAndWindow)
{
    osg::ref_ptr<Volume> v = twoChannels();
    osg::ref_ptr<VolumeNode> node = makeDefaultVolumeNode(v.get());
    EXPECT_EQ(node->settings.functions.at("Shading"), "null") << "fluorescence emits, unlit";
    for (int c = 0; c < 2; ++c) {
        const TransferFunction& tf = *node->channels[std::size_t(c)].transferFunction;
        // The channel's values are uniform over (c + 1) * 1000 + [0, 99]: its window lies in them.
        const double low = (c + 1) * 1000.0, high = low + 99.0;
        ASSERT_EQ(tf.points().size(), 2u);
        const double from = tf.points().begin()->first, to = tf.points().rbegin()->first;
        EXPECT_GE(from, low - 1.0);
        EXPECT_LE(to, high + 1.0);
        EXPECT_GT(to - from, 40.0);
        const osg::Vec3 colour = channelColour(c);
        const osg::Vec4 top = tf.evaluate(high + 10.0);
        EXPECT_EQ(osg::Vec3(top.r(), top.g(), top.b()), colour);
        EXPECT_FLOAT_EQ(top.a(), float(defaultChannelOpacity));
        EXPECT_FLOAT_EQ(tf.evaluate(low - 10.0).a(), 0.0f);
    }
    EXPECT_EQ(channelColour(0), osg::Vec3(0, 1, 0));  // green, magenta, cyan, yellow
    EXPECT_EQ(channelColour(1), osg::Vec3(1, 0, 1));
    EXPECT_EQ(channelColour(2), osg::Vec3(0, 1, 1));
    EXPECT_EQ(channelColour(3), osg::Vec3(1, 1, 0));
}

}  // namespace
}  // namespace volren::test
