#include <volume_model/TransferFunction.h>

#include <gtest/gtest.h>

namespace volren::test {
namespace {

TEST(TransferFunction, InterpolatesLinearlyAndClampsOutside)
{
    TransferFunction tf;
    tf.setPoint(100.0, osg::Vec4(0, 0, 0, 0));
    tf.setPoint(300.0, osg::Vec4(1, 0.5f, 0, 0.8f));
    EXPECT_EQ(tf.evaluate(50.0), osg::Vec4(0, 0, 0, 0));
    EXPECT_EQ(tf.evaluate(1000.0), osg::Vec4(1, 0.5f, 0, 0.8f));
    const osg::Vec4 mid = tf.evaluate(150.0);
    EXPECT_FLOAT_EQ(mid.r(), 0.25f);
    EXPECT_FLOAT_EQ(mid.g(), 0.125f);
    EXPECT_FLOAT_EQ(mid.a(), 0.2f);
}

TEST(TransferFunction, LookupTableSpansTheDomainEndToEnd)
{
    TransferFunction tf;
    tf.setPoint(0.0, osg::Vec4(0, 0, 0, 0));
    tf.setPoint(10.0, osg::Vec4(1, 1, 1, 1));
    tf.setResolution(11);
    std::vector<osg::Vec4> table = tf.lookupTable();
    ASSERT_EQ(table.size(), 11u);
    for (int i = 0; i <= 10; ++i) EXPECT_FLOAT_EQ(table[i].r(), i / 10.0f) << i;
    // An explicit window wider than the points: the ends hold the end colours.
    tf.setDomain(-10.0, 30.0);
    table = tf.lookupTable();
    EXPECT_EQ(table.front(), osg::Vec4(0, 0, 0, 0));
    EXPECT_FLOAT_EQ(table[4].r(), 0.6f);  // value 6
    EXPECT_EQ(table.back(), osg::Vec4(1, 1, 1, 1));
}

TEST(TransferFunction, RejectsBadInput)
{
    TransferFunction tf;
    EXPECT_THROW(tf.setPoint(1.0, osg::Vec4(1.5f, 0, 0, 0)), std::invalid_argument);
    EXPECT_THROW(tf.setPoint(1.0, osg::Vec4(0, 0, 0, -0.1f)), std::invalid_argument);
    EXPECT_THROW(tf.setPoint(std::nan(""), osg::Vec4(0, 0, 0, 0)), std::invalid_argument);
    EXPECT_THROW(tf.setDomain(5.0, 5.0), std::invalid_argument);
    EXPECT_THROW(tf.setResolution(1), std::invalid_argument);
    EXPECT_THROW(tf.setResolution(70000), std::invalid_argument);
}

TEST(TransferFunction, EveryEditBumpsTheModifiedCount)
{
    TransferFunction tf;
    unsigned last = tf.modifiedCount();
    auto bumped = [&] {
        const bool grew = tf.modifiedCount() > last;
        last = tf.modifiedCount();
        return grew;
    };
    tf.setPoint(1.0, osg::Vec4(1, 1, 1, 1));
    EXPECT_TRUE(bumped());
    tf.setDomain(0.0, 2.0);
    EXPECT_TRUE(bumped());
    tf.setResolution(64);
    EXPECT_TRUE(bumped());
    EXPECT_TRUE(tf.removePoint(1.0));
    EXPECT_TRUE(bumped());
    EXPECT_FALSE(tf.removePoint(1.0));
    EXPECT_FALSE(bumped());
}

TEST(TransferFunction, MonotoneCubicPassesThroughPointsNeverOvershootsAndIsSmooth)
{
    // A step (0, 0, 1, 1) and a peak: linear would be straight; the monotone cubic keeps every
    // point, stays between neighbouring points' values (no overshoot), is flat where the data
    // turns (0 at the peak's sides' extremes), and its slope is continuous at interior points.
    TransferFunction tf;
    tf.setPoint(0, osg::Vec4(0, 0, 0, 0));
    tf.setPoint(10, osg::Vec4(0, 0.2f, 0, 0.0f));
    tf.setPoint(20, osg::Vec4(1, 0.9f, 1, 1.0f));
    tf.setPoint(30, osg::Vec4(1, 0.3f, 0, 1.0f));
    tf.setInterpolation(TransferFunction::Interpolation::MonotoneCubic);
    for (const auto& [value, rgba] : tf.points()) EXPECT_EQ(tf.evaluate(value), rgba) << value;
    double previousAlpha = 0.0;
    for (double v = 0.0; v <= 30.0; v += 0.05) {
        const osg::Vec4 c = tf.evaluate(v);
        for (int k = 0; k < 4; ++k) {
            EXPECT_GE(c[k], 0.0f);
            EXPECT_LE(c[k], 1.0f);
        }
        EXPECT_GE(c.a() + 1e-7, previousAlpha) << "alpha rises monotonically like its points, at " << v;
        previousAlpha = c.a();
        if (v > 20.0) {
            EXPECT_LE(c.g(), 0.9f + 1e-6f) << "no overshoot above the peak's point";
        }
    }
    // Between 20 and 30 alpha is flat (1 to 1): exactly 1, not a bump.
    EXPECT_EQ(tf.evaluate(25).a(), 1.0f);
    // C1: one-sided slopes at the interior point 20 agree (green: 0.2 -> 0.9 -> 0.3 is a peak,
    // so its tangent is 0 there).
    const double h = 1e-4;
    EXPECT_NEAR((tf.evaluate(20).g() - tf.evaluate(20 - h).g()) / h, 0.0, 1e-2);
    EXPECT_NEAR((tf.evaluate(20 + h).g() - tf.evaluate(20).g()) / h, 0.0, 1e-2);
    // Red's 0 -> 0 -> 1 -> 1: smooth S between 10 and 20, its midpoint exactly halfway.
    EXPECT_NEAR(tf.evaluate(15).r(), 0.5f, 1e-6);
    EXPECT_LT(tf.evaluate(12).r(), 0.2f) << "a smooth start, below the straight line's 0.2";
    // Linear again: the straight line.
    tf.setInterpolation(TransferFunction::Interpolation::Linear);
    EXPECT_NEAR(tf.evaluate(12).r(), 0.2f, 1e-6);
}

}  // namespace
}  // namespace volren::test
