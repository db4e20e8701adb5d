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
