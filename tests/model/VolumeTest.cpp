#include "TestData.h"

#include <volume_model/Volume.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace volren::test {
namespace {

TEST(Volume, AllocatesEveryVoxelTypeWithItsSize)
{
    for (auto [type, bytes] : {std::pair{VoxelType::UInt8, 1}, {VoxelType::Int8, 1}, {VoxelType::UInt16, 2},
                               {VoxelType::Int16, 2}, {VoxelType::Float32, 4}}) {
        Volume v;
        v.allocate(type, {3, 4, 5});
        EXPECT_EQ(v.voxelCount(), 60u);
        EXPECT_EQ(v.byteSize(), 60u * bytes) << voxelTypeName(type);
        VoxelType parsed;
        ASSERT_TRUE(parseVoxelType(voxelTypeName(type), parsed));
        EXPECT_EQ(parsed, type);
    }
}

TEST(Volume, RejectsZeroNegativeAndOverflowingDims)
{
    Volume v;
    EXPECT_THROW(v.allocate(VoxelType::UInt8, {0, 4, 4}), std::invalid_argument);
    EXPECT_THROW(v.allocate(VoxelType::UInt8, {4, -1, 4}), std::invalid_argument);
    // 2^31-1 cubed overflows any 64-bit byte count: refused before allocating anything.
    EXPECT_THROW(v.allocate(VoxelType::Float32, {2147483647, 2147483647, 2147483647}), std::invalid_argument);
    EXPECT_THROW(v.assign(VoxelType::UInt16, {2, 2, 2}, std::vector<std::uint8_t>(15)), std::invalid_argument);
}

TEST(Volume, SpacingMustBePositiveAndFinite)
{
    Volume v;
    EXPECT_THROW(v.setSpacing({1, 0, 1}), std::invalid_argument);
    EXPECT_THROW(v.setSpacing({1, -2, 1}), std::invalid_argument);
    EXPECT_THROW(v.setSpacing({1, std::nan(""), 1}), std::invalid_argument);
    v.allocate(VoxelType::UInt8, {10, 20, 30});
    v.setSpacing({0.5, 0.25, 3.0});
    EXPECT_DOUBLE_EQ(v.minSpacing(), 0.25);
    EXPECT_EQ(v.worldSize(), osg::Vec3d(5.0, 5.0, 90.0));
}

TEST(Volume, ValueRangeAppliesRescaleAndIgnoresNonFiniteVoxels)
{
    osg::ref_ptr<Volume> v = constantVolume(VoxelType::Int16, {4, 4, 4}, 10);
    std::int16_t lo = -300, hi = 1200;
    std::memcpy(v->data() + 2 * 5, &lo, 2);
    std::memcpy(v->data() + 2 * 9, &hi, 2);
    v->dirty();
    auto [a, b] = v->valueRange();
    EXPECT_DOUBLE_EQ(a, -300);
    EXPECT_DOUBLE_EQ(b, 1200);
    v->setRescale(-0.5, 7.0);  // a negative slope swaps the ends
    std::tie(a, b) = v->valueRange();
    EXPECT_DOUBLE_EQ(a, -593.0);
    EXPECT_DOUBLE_EQ(b, 157.0);
    EXPECT_DOUBLE_EQ(v->value(5), 157.0);

    osg::ref_ptr<Volume> f = constantVolume(VoxelType::Float32, {4, 1, 1}, 2.0);
    const float bad[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()};
    std::memcpy(f->data(), bad, sizeof(bad));
    f->dirty();
    std::tie(a, b) = f->valueRange();
    EXPECT_EQ(a, 2.0);
    EXPECT_EQ(b, 2.0);
    EXPECT_EQ(f->nonFiniteCount(), 2u);
    EXPECT_EQ(f->histogram(8).ignored, 2u);
    EXPECT_EQ(f->histogram(8).total(), 2u);
}

TEST(Volume, SignedEightBitValuesAreSigned)
{
    osg::ref_ptr<Volume> v = constantVolume(VoxelType::Int8, {2, 1, 1}, -128);
    EXPECT_DOUBLE_EQ(v->value(0), -128.0);
    EXPECT_DOUBLE_EQ(v->value(1, 0, 0), -128.0);
}

TEST(Volume, ModifiedCountGrowsWithEveryChange)
{
    Volume v;
    const unsigned a = v.modifiedCount();
    v.allocate(VoxelType::UInt8, {2, 2, 2});
    const unsigned b = v.modifiedCount();
    v.setSpacing({2, 2, 2});
    const unsigned c = v.modifiedCount();
    EXPECT_LT(a, b);
    EXPECT_LT(b, c);
}

}  // namespace
}  // namespace volren::test
