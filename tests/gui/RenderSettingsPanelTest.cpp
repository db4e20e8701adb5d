// The viewer's settings panel on its model operations: the spatial weighting's per-axis fade
// writes and reads back the ramp curve of the node's settings.
#include <volume_gui/RenderSettingsPanel.h>

#include <gtest/gtest.h>

namespace volren::test {
namespace {

TEST(RenderSettingsPanel, AnAxisFadeIsTheRampCurveOfThatAxis)
{
    osg::ref_ptr<VolumeNode> node = new VolumeNode;
    RenderSettingsPanel panel(node.get(), {});
    EXPECT_EQ(panel.fade(2), 0.0);
    panel.setFade(2, 0.1);
    EXPECT_TRUE(panel.error().empty()) << panel.error();
    EXPECT_EQ(node->settings.get("weightZ"), "0:0,0.1:1,0.9:1,1:0");
    EXPECT_DOUBLE_EQ(panel.fade(2), 0.1);
    EXPECT_EQ(panel.fade(0), 0.0);
    EXPECT_TRUE(node->settings.weighting.axes[0].identity());
    panel.setFade(2, 0.8);  // at most half the axis from each end
    EXPECT_EQ(node->settings.get("weightZ"), "0:0,0.5:1,1:0");
    EXPECT_DOUBLE_EQ(panel.fade(2), 0.5);
    std::string error;
    ASSERT_TRUE(node->settings.set("weightZ", "0:0.5,1:1", error)) << error;
    EXPECT_EQ(panel.fade(2), -1.0) << "another curve is not a fade";
    panel.setFade(2, 0.0);
    EXPECT_TRUE(node->settings.weighting.identity());
}

}  // namespace
}  // namespace volren::test
