// The viewer's settings panel on its model operations: the spatial weighting's per-axis fade
// writes and reads back the ramp curve of the node's settings; the shadow sliders cover every
// shadowing parameter, each within what RenderSettings accepts.
#include <volume_gui/RenderSettingsPanel.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <set>
#include <sstream>

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

TEST(RenderSettingsPanel, TheShadowSlidersCoverEveryShadowingParameterWithinItsRange)
{
    // The parameters the shadowing methods read (issue #19: shadow rays' step factor and cutoff,
    // the light volume's resolution factor, the cones' angle, start offset, step growth and
    // filter sigma, the occlusion's reach) and the phase function's anisotropy.
    const std::set<std::string> wanted = {"shadowStepFactor", "shadowCutoff",    "lightVolumeScale",
                                          "coneAngle",        "coneStart",       "coneStepGrowth",
                                          "coneFilterSigma",  "aoDistance",      "anisotropy"};
    std::set<std::string> shown;
    for (const SettingSlider& s : RenderSettingsPanel::shadowSliders()) {
        shown.insert(s.key);
        ASSERT_LT(s.lo, s.hi) << s.key;
        RenderSettings settings;
        const double value = std::strtod(settings.get(s.key).c_str(), nullptr);
        EXPECT_GE(value, s.lo) << s.key << ": the default lies on the slider";
        EXPECT_LE(value, s.hi) << s.key << ": the default lies on the slider";
        for (const float end : {s.lo, s.hi}) {
            std::ostringstream text;
            text << end;
            std::string error;
            EXPECT_TRUE(settings.set(s.key, text.str(), error)) << s.key << " = " << end << ": " << error;
            EXPECT_NEAR(std::strtod(settings.get(s.key).c_str(), nullptr), end, 1e-6 * std::abs(end) + 1e-9) << s.key;
        }
    }
    EXPECT_EQ(shown, wanted);
}

}  // namespace
}  // namespace volren::test
