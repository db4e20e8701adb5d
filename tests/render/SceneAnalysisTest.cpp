// Scene analysis: the composition follows the scene (lights, clip shapes, settings), and only
// what the composition uses is compiled, bound or allocated.
#include "RenderFixture.h"
#include "TestData.h"

#include <volume_model/ClipBoxNode.h>
#include <volume_model/ClipEllipsoidNode.h>
#include <volume_model/ClipPlaneNode.h>

#include <osg/MatrixTransform>
#include <osg/LightSource>

namespace volren::test {
namespace {

class SceneAnalysis : public RenderFixture
{
protected:
    void SetUp() override
    {
        scene = new VolumeScene;
        node = volumeNode(constantVolume(VoxelType::UInt8, {10, 10, 10}, 100).get(),
                          constantTransferFunction(osg::Vec4(1, 1, 1, 0.1f)).get());
        scene->addChild(node.get());
    }
    std::string keyAfterFrame()
    {
        renderOrthoFromPlusZ(scene.get(), 8, 8, 12.0);
        EXPECT_EQ(scene->compositionKeys().size(), 1u);
        return scene->compositionKeys().empty() ? "" : scene->compositionKeys()[0];
    }
    static osg::ref_ptr<osg::LightSource> light()
    {
        osg::ref_ptr<osg::LightSource> l = new osg::LightSource;
        l->getLight()->setPosition(osg::Vec4(0, 0, 1, 0));
        return l;
    }
    osg::ref_ptr<VolumeScene> scene;
    osg::ref_ptr<VolumeNode> node;
};

TEST_F(SceneAnalysis, NoLightsNoClipsGivesTheMinimalComposition)
{
    const std::string key = keyAfterFrame();
    for (const char* part : {"Shading=null;", "Illumination=null;", "Gradient=null;", "GradientInput=null;",
                             "ClipRay=[];", "ClipPosition=[];", "lights=0;"})
        EXPECT_NE(key.find(part), std::string::npos) << part << " in " << key;
}

TEST_F(SceneAnalysis, LightsSwitchOnShadingAndCountInTheKey)
{
    scene->addChild(light().get());
    scene->addChild(light().get());
    std::string key = keyAfterFrame();
    for (const char* part : {"Shading=lighting;", "Illumination=blinn_phong;", "Gradient=central;",
                             "GradientInput=scalar;", "lights=2;"})
        EXPECT_NE(key.find(part), std::string::npos) << part << " in " << key;
    std::string error;
    ASSERT_TRUE(scene->pass.set("lighting", "off", error)) << error;
    key = keyAfterFrame();
    EXPECT_NE(key.find("Shading=null;"), std::string::npos) << key;
    EXPECT_NE(key.find("lights=0;"), std::string::npos) << key;
}

TEST_F(SceneAnalysis, ClipShapesThatCutTheVolumeBecomeTemplateInstances)
{
    osg::ref_ptr<ClipPlaneNode> plane = new ClipPlaneNode;
    plane->plane.set(1, 0, 0, 1);  // cuts the 10-wide box at x = -1
    osg::ref_ptr<ClipEllipsoidNode> ellipsoid = new ClipEllipsoidNode;
    ellipsoid->radii.set(3, 3, 3);
    osg::ref_ptr<ClipBoxNode> faraway = new ClipBoxNode;
    faraway->box.set(100, 100, 100, 101, 101, 101);
    faraway->invert = true;  // cuts away a box the volume never reaches: changes nothing
    scene->addChild(plane.get());
    scene->addChild(ellipsoid.get());
    scene->addChild(faraway.get());
    std::string key = keyAfterFrame();
    EXPECT_NE(key.find("ClipRay=[plane];"), std::string::npos) << key;
    EXPECT_NE(key.find("ClipPosition=[ellipsoid];"), std::string::npos) << key;

    node->settings.functions["ClipRay"] = "null";  // planes then clip sample by sample
    key = keyAfterFrame();
    EXPECT_NE(key.find("ClipRay=[];"), std::string::npos) << key;
    EXPECT_NE(key.find("ClipPosition=[plane,ellipsoid];"), std::string::npos) << key;

    node->settings.forceNull = {"ClipPosition", "ClipRay"};
    key = keyAfterFrame();
    EXPECT_NE(key.find("ClipPosition=[];"), std::string::npos) << key;
    EXPECT_NE(key.find("ClipRay=[];"), std::string::npos) << key;
}

TEST_F(SceneAnalysis, SettingsChooseImplementationsAndForceNullWins)
{
    scene->addChild(light().get());
    node->settings.functions["RayTraversal"] = "mida";
    node->settings.functions["Illumination"] = "cook_torrance";
    node->settings.functions["Gradient"] = "central9";
    std::string key = keyAfterFrame();
    for (const char* part : {"RayTraversal=mida;", "Illumination=cook_torrance;", "Gradient=central9;"})
        EXPECT_NE(key.find(part), std::string::npos) << part << " in " << key;
    node->settings.forceNull.insert("Gradient");
    key = keyAfterFrame();
    EXPECT_NE(key.find("Gradient=null;"), std::string::npos) << key;
}

TEST_F(SceneAnalysis, OnlyTheAuxiliaryDataAnImplementationNeedsIsAllocated)
{
    keyAfterFrame();
    EXPECT_EQ(scene->auxiliaryTextureCount(), 3u) << "volume texture + 1D TF table + occupancy grid";
    node->settings.functions["Classification"] = "null";
    keyAfterFrame();
    keyAfterFrame();
    keyAfterFrame();
    EXPECT_EQ(scene->auxiliaryTextureCount(), 2u) << "no TF table without TF classification";
    node->settings.functions["Classification"] = "premultiplied";
    keyAfterFrame();
    keyAfterFrame();
    keyAfterFrame();  // the grid of the null classification is freed when unused for three frames
    EXPECT_EQ(scene->auxiliaryTextureCount(), 3u) << "volume texture + premultiplied table + occupancy grid";
    node->settings.functions["Acceleration"] = "null";
    keyAfterFrame();
    keyAfterFrame();
    keyAfterFrame();
    EXPECT_EQ(scene->auxiliaryTextureCount(), 2u) << "no occupancy grid without skipping";
}

TEST_F(SceneAnalysis, TheSameSceneComposedTwiceReusesTheProgram)
{
    keyAfterFrame();
    keyAfterFrame();
    EXPECT_EQ(scene->compositor().programCount(), 1u);
    // A second volume with the same settings shares the program; a different one adds one.
    osg::ref_ptr<VolumeNode> twin = volumeNode(node->getVolume(), node->getTransferFunction());
    osg::ref_ptr<osg::MatrixTransform> moved = new osg::MatrixTransform(osg::Matrix::translate(20, 0, 0));
    moved->addChild(twin.get());
    scene->addChild(moved.get());
    renderOrthoFromPlusZ(scene.get(), 8, 8, 60.0);
    EXPECT_EQ(scene->compositor().programCount(), 1u);
    twin->settings.functions["RayTraversal"] = "mip";
    renderOrthoFromPlusZ(scene.get(), 8, 8, 60.0);
    EXPECT_EQ(scene->compositor().programCount(), 2u);
    EXPECT_EQ(scene->compositionKeys().size(), 2u);
}

}  // namespace
}  // namespace volren::test
