// The viewer's settings panel on its model operations: a curve parameter's fade writes and reads
// back the ramp curve; the panel shows exactly the declared parameters of the implementations the
// node is drawn with, following the choice; every slider lies within its declared range.
#include <volume_gui/RenderSettingsPanel.h>

#include <volume_model/ParameterCatalog.h>
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>

namespace volren::test {
namespace {

std::set<std::string> shownKeys(const RenderSettingsPanel& panel)
{
    std::set<std::string> keys;
    for (const ParameterDecl* p : panel.shownParameters()) keys.insert(p->key);
    return keys;
}

TEST(RenderSettingsPanel, ACurveFadeIsTheRampCurveOfThatParameter)
{
    osg::ref_ptr<VolumeNode> node = new VolumeNode;
    RenderSettingsPanel panel(node.get(), {});
    EXPECT_EQ(panel.fade("weightZ"), 0.0);
    panel.setFade("weightZ", 0.1);
    EXPECT_TRUE(panel.error().empty()) << panel.error();
    EXPECT_EQ(node->settings.get("weightZ"), "0:0,0.1:1,0.9:1,1:0");
    EXPECT_DOUBLE_EQ(panel.fade("weightZ"), 0.1);
    EXPECT_EQ(panel.fade("weightX"), 0.0);
    EXPECT_TRUE(spatialWeighting(node->settings).axes[0].identity());
    panel.setFade("weightZ", 0.8);  // at most half the axis from each end
    EXPECT_EQ(node->settings.get("weightZ"), "0:0,0.5:1,1:0");
    EXPECT_DOUBLE_EQ(panel.fade("weightZ"), 0.5);
    std::string error;
    ASSERT_TRUE(node->settings.set("weightZ", "0:0.5,1:1", error)) << error;
    EXPECT_EQ(panel.fade("weightZ"), -1.0) << "another curve is not a fade";
    panel.setFade("weightZ", 0.0);
    EXPECT_TRUE(spatialWeighting(node->settings).identity());
}

TEST(RenderSettingsPanel, ShowsTheParametersOfTheChosenImplementationsOnly)
{
    ShaderFunctionRegistry::instance();
    osg::ref_ptr<VolumeNode> node = new VolumeNode;
    std::map<std::string, std::string> drawnWith;  // what the renderer reports
    RenderSettingsPanel panel(node.get(), {}, [&drawnWith] { return drawnWith; });
    EXPECT_EQ(shownKeys(panel), std::set<std::string>{}) << "nothing chosen, nothing shown";
    std::string error;
    ASSERT_TRUE(node->settings.set("shadowing", "cone", error)) << error;
    const std::set<std::string> cone = {"shadowStepFactor", "shadowCutoff", "coneAngle",
                                        "coneStart",        "coneStepGrowth", "coneFilterSigma"};
    EXPECT_EQ(shownKeys(panel), cone);
    ASSERT_TRUE(node->settings.set("shadowing", "cone_ao", error)) << error;
    std::set<std::string> coneAo = cone;
    coneAo.insert("aoDistance");
    EXPECT_EQ(shownKeys(panel), coneAo) << "the list follows the choice";
    ASSERT_TRUE(node->settings.set("shadowing", "light_volume", error)) << error;
    EXPECT_EQ(shownKeys(panel), (std::set<std::string>{"shadowStepFactor", "lightVolumeScale"}));
    ASSERT_TRUE(node->settings.set("shadowing", "null", error)) << error;
    drawnWith = {{"Shading", "lighting"}, {"Illumination", "henyey_greenstein"}, {"RayTraversal", "isosurface"}};
    EXPECT_EQ(shownKeys(panel), (std::set<std::string>{"ambient", "anisotropy", "isoValue"}))
        << "the renderer's choices where the node names none";
    ASSERT_TRUE(node->settings.set("illumination", "cook_torrance", error)) << error;
    EXPECT_EQ(shownKeys(panel), (std::set<std::string>{"ambient", "specular", "roughness", "isoValue"}))
        << "the node's own choice wins";
    ASSERT_TRUE(node->settings.set("forceNull", "Shading", error)) << error;
    EXPECT_EQ(shownKeys(panel), (std::set<std::string>{"specular", "roughness", "isoValue"}));
}

TEST(RenderSettingsPanel, EverySliderLiesWithinItsDeclaredRangeWithTheDefaultOnIt)
{
    ShaderFunctionRegistry::instance();
    int sliders = 0;
    for (const ParameterDecl& p : ParameterCatalog::instance().all()) {
        if (p.panel.kind != PanelHint::Slider && p.panel.kind != PanelHint::LogSlider) continue;
        ++sliders;
        const double lo = p.panel.lo != p.panel.hi ? p.panel.lo : p.lo;
        const double hi = p.panel.lo != p.panel.hi ? p.panel.hi : p.hi;
        ASSERT_LT(lo, hi) << p.key;
        RenderSettings settings;
        const double value = std::strtod(settings.get(p.key).c_str(), nullptr);
        EXPECT_GE(value, lo) << p.key << ": the default lies on the slider";
        EXPECT_LE(value, hi) << p.key << ": the default lies on the slider";
        for (const float end : {float(lo), float(hi)}) {
            std::ostringstream text;
            text << end;
            std::string error;
            EXPECT_TRUE(settings.set(p.key, text.str(), error)) << p.key << " = " << end << ": " << error;
            EXPECT_NEAR(std::strtod(settings.get(p.key).c_str(), nullptr), end, 1e-6 * std::abs(end) + 1e-9) << p.key;
        }
    }
    EXPECT_GE(sliders, 15) << "the shadowing, illumination, shading and adaptive parameters";
}

}  // namespace
}  // namespace volren::test
