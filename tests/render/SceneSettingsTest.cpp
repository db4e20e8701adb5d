// The one router of settings (`volren render --set`, bench configurations, scene files):
// pass settings to the pass, the others to every volume, implementation names resolved and
// checked against the registry.
#include "TestData.h"

#include <volume_renderer/SceneSettings.h>

#include <gtest/gtest.h>

namespace volren::test {
namespace {

TEST(SceneSettings, RoutesPassAndNodeSettingsAndResolvesAliases)
{
    osg::ref_ptr<VolumeScene> scene = asVolumeScene(nullptr);
    osg::ref_ptr<VolumeNode> a = makeVolumeNode(constantVolume(VoxelType::UInt8, {2, 2, 2}, 1).get(),
                                                constantTransferFunction(osg::Vec4(1, 1, 1, 1)).get());
    osg::ref_ptr<VolumeNode> b = makeVolumeNode(a->getVolume(), a->getTransferFunction());
    scene->addChild(a.get());
    scene->addChild(b.get());
    applySetting(*scene, "lighting", "off");
    EXPECT_FALSE(scene->pass.lighting);
    applySetting(*scene, "traversal", "dvr");
    applySetting(*scene, "illumination", "CookTorrance");
    applySetting(*scene, "jitter", "on");
    applySetting(*scene, "samplerate", "4");
    for (VolumeNode* n : {a.get(), b.get()}) {
        EXPECT_EQ(n->settings.functions.at("RayTraversal"), "dvr_front_to_back");
        EXPECT_EQ(n->settings.functions.at("Illumination"), "cook_torrance");
        EXPECT_EQ(n->settings.functions.at("Jitter"), "hash");
        EXPECT_DOUBLE_EQ(n->settings.sampleDistanceFactor, 0.25);
    }
    EXPECT_EQ(asVolumeScene(scene.get()).get(), scene.get()) << "a VolumeScene is not wrapped again";
}

TEST(SceneSettings, BadSettingsNameTheKeyTheValueAndTheChoices)
{
    osg::ref_ptr<VolumeScene> scene = new VolumeScene;  // no volume: still checked
    try {
        applySetting(*scene, "traversal", "sparkle");
        FAIL() << "accepted an unknown implementation";
    } catch (const SettingError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("traversal=sparkle"), std::string::npos) << what;
        EXPECT_NE(what.find("known: dvr_front_to_back"), std::string::npos) << what;
        EXPECT_NE(what.find("additive"), std::string::npos) << "set traversals a volume may name are offered";
    }
    EXPECT_THROW(applySetting(*scene, "lighting", "dim"), SettingError);
    EXPECT_THROW(applySetting(*scene, "sampelrate", "2"), SettingError);
    EXPECT_THROW(applySetting(*scene, "earlyTermination", "2"), SettingError);
    EXPECT_TRUE(scene->pass.lighting) << "failed settings change nothing";
}

TEST(SceneSettings, HelpListsEverySlotWithThePolicysDefaultFirst)
{
    const std::string help = settingsHelp(CompositionPolicy());
    EXPECT_NE(help.find("RayTraversal    (traversal): dvr_front_to_back, "), std::string::npos) << help;
    EXPECT_NE(help.find("Jitter          (jitter): hash, "), std::string::npos) << help;
    EXPECT_NE(help.find("[blinn_phong when the scene needs it]"), std::string::npos) << help;
    EXPECT_NE(help.find("forceNullAll"), std::string::npos);
    EXPECT_NE(help.find("combine: additive (images), mip_additive (maxima), sum_of_media (media)"), std::string::npos)
        << help;
}

}  // namespace
}  // namespace volren::test
