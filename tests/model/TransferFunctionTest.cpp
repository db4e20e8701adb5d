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

}  // namespace
}  // namespace volren::test
