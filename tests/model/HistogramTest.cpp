#include "TestData.h"

#include <volume_model/Histogram.h>

#include <gtest/gtest.h>

namespace volren::test {
namespace {

TEST(Histogram, CountsEveryVoxelInItsBin)
{
    osg::ref_ptr<Volume> v = new Volume;
    v->allocate(VoxelType::UInt8, {256, 1, 1});
    for (int i = 0; i < 256; ++i) v->data()[i] = std::uint8_t(i);
    v->dirty();
    const Histogram h = v->histogram(16);
    ASSERT_EQ(h.counts.size(), 16u);
    EXPECT_EQ(h.total(), 256u);
    EXPECT_DOUBLE_EQ(h.minValue, 0.0);
    EXPECT_DOUBLE_EQ(h.maxValue, 255.0);
    // Bins of width 255/16 = 15.9375: value i belongs to bin floor(i / 15.9375), 255 to the last.
    std::vector<std::uint64_t> expected(16, 0);
    for (int i = 0; i < 256; ++i) expected[std::min(15, int(i / 15.9375))]++;
    for (int b = 0; b < 16; ++b) EXPECT_EQ(h.counts[b], expected[b]) << "bin " << b;
    EXPECT_NEAR(h.percentile(0.5), 127.5, 1.0);
}

TEST(Histogram, OtsuSeparatesTwoPopulations)
{
    Histogram h;
    h.minValue = 0;
    h.maxValue = 100;
    h.counts.assign(100, 0);
    for (int i = 10; i < 20; ++i) h.counts[i] = 1000;  // background around 15
    for (int i = 70; i < 80; ++i) h.counts[i] = 300;   // object around 75
    const double t = h.otsuThreshold();
    EXPECT_GE(t, 20.0);
    EXPECT_LE(t, 70.0);
}

TEST(Histogram, PercentileOfEmptyHistogramIsTheMinimum)
{
    Histogram h;
    h.minValue = 3;
    h.maxValue = 5;
    h.counts.assign(4, 0);
    EXPECT_EQ(h.percentile(0.7), 3.0);
}

}  // namespace
}  // namespace volren::test
