// Spatial weighting curves (volume_model/SpatialWeighting.h): values against the piecewise-linear
// closed form, exact text round trips, and refusals (their settings weightX/Y/Z: render tests).
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

}  // namespace
}  // namespace volren::test
