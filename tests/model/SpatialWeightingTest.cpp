// Spatial weighting curves (volume_model/SpatialWeighting.h) and their settings (weightX/Y/Z):
// values against the piecewise-linear closed form, exact text round trips, and refusals.
#include <volume_model/RenderSettings.h>
#include <volume_model/SpatialWeighting.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace volren::test {
namespace {

WeightCurve parsed(const std::string& text)
{
    WeightCurve curve;
    std::string error;
    EXPECT_TRUE(WeightCurve::parse(text, curve, error)) << text << ": " << error;
    return curve;
}

TEST(SpatialWeighting, ACurveIsPiecewiseLinearAndConstantBeyondItsEnds)
{
    const WeightCurve curve = parsed("0.2:0, 0.4:1, 0.9:0.5");
    EXPECT_EQ(curve.knots.size(), 3u);
    EXPECT_EQ(curve(0.0), 0.0);
    EXPECT_EQ(curve(0.2), 0.0);
    EXPECT_DOUBLE_EQ(curve(0.3), 0.5);
    EXPECT_EQ(curve(0.4), 1.0);
    EXPECT_DOUBLE_EQ(curve(0.65), 0.75);
    EXPECT_EQ(curve(0.9), 0.5);
    EXPECT_EQ(curve(1.0), 0.5);
    EXPECT_EQ(curve(std::numeric_limits<double>::quiet_NaN()), 0.0) << "NaN reads the first weight";
    EXPECT_FALSE(curve.identity());
    EXPECT_TRUE(WeightCurve{}.identity());
    EXPECT_EQ(WeightCurve{}(0.37), 1.0);
    EXPECT_TRUE(parsed("0:1,1:1").identity());
}

TEST(SpatialWeighting, ARampFadesBothEndsOverItsFraction)
{
    const WeightCurve ramp = parsed("ramp:0.1");
    EXPECT_EQ(ramp.text(), "0:0,0.1:1,0.9:1,1:0");
    EXPECT_DOUBLE_EQ(ramp(0.05), 0.5);
    EXPECT_EQ(ramp(0.5), 1.0);
    EXPECT_NEAR(ramp(0.975), 0.25, 1e-12);
    EXPECT_EQ(parsed("ramp:0.5").text(), "0:0,0.5:1,1:0");
}

TEST(SpatialWeighting, TheProductOfTheAxesScalesASample)
{
    SpatialWeighting w;
    w.axes[0] = parsed("0:0,1:1");
    w.axes[2] = parsed("0:1,1:0.5");
    EXPECT_DOUBLE_EQ(w(0.25, 0.9, 0.5), 0.25 * 1.0 * 0.75);
    EXPECT_FALSE(w.identity());
    EXPECT_TRUE(SpatialWeighting{}.identity());
}

TEST(SpatialWeighting, SettingsReadBackExactlyAndRefuseBadCurves)
{
    RenderSettings s;
    std::string error;
    ASSERT_TRUE(s.set("weightZ", "0:0,0.123456789012345:1,1:0.3", error)) << error;
    EXPECT_EQ(s.weighting.axes[2].knots.size(), 3u);
    EXPECT_EQ(s.weighting.axes[2].knots[1].first, 0.123456789012345);
    EXPECT_TRUE(s.weighting.axes[0].identity());
    RenderSettings copy;
    ASSERT_TRUE(copy.set("weightz", s.get("weightZ"), error)) << error;
    EXPECT_EQ(copy, s);
    ASSERT_TRUE(s.set("weightX", "ramp:0.05", error)) << error;
    EXPECT_EQ(s.get("weightX"), "0:0,0.05:1,0.95:1,1:0");
    ASSERT_TRUE(s.set("weightX", "none", error)) << error;
    EXPECT_TRUE(s.weighting.axes[0].knots.empty());
    EXPECT_EQ(s.get("weightX"), "");
    EXPECT_EQ(RenderSettings::slotForKey("weighting"), "Weighting");

    std::string many;
    for (int i = 0; i <= int(WeightCurve::maxKnots); ++i) many += (i ? "," : "") + std::to_string(i / 20.0) + ":1";
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"0.5", "is not u:w"},          {"0:1,x:1", "is not u:w"},     {"0:1.5", "weight must be in [0, 1]"},
        {"0:-0.1", "weight must be in [0, 1]"}, {"1.2:1", "u must be in [0, 1]"}, {"0.5:1,0.5:0", "u must increase"},
        {"0.6:1,0.5:0", "u must increase"},     {"ramp:0", "0 < A <= 0.5"},  {"ramp:0.7", "0 < A <= 0.5"},
        {"0:nan", "is not u:w"},        {many, "at most 16 knots"}};
    for (const auto& [value, why] : bad) {
        RenderSettings r;
        EXPECT_FALSE(r.set("weightY", value, error)) << value;
        EXPECT_NE(error.find("weightY: "), std::string::npos) << error;
        EXPECT_NE(error.find(why), std::string::npos) << value << ": " << error;
        EXPECT_EQ(r, RenderSettings{}) << "a refused curve changes nothing: " << value;
    }
}

}  // namespace
}  // namespace volren::test
