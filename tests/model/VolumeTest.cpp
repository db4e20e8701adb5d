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

namespace volren::test {

TEST(Volume, KeepsChannelsAndTimePointsAsBlocksOfTheGrid)
{
    osg::ref_ptr<Volume> v = new Volume;
    v->allocate(VoxelType::UInt16, {4, 3, 2}, 2, 3);
    EXPECT_EQ(v->channels(), 2);
    EXPECT_EQ(v->frames(), 3);
    EXPECT_EQ(v->voxelCount(), 24u);
    EXPECT_EQ(v->totalVoxelCount(), 144u);
    EXPECT_EQ(v->byteSize(), 288u);
    EXPECT_EQ(v->block(0, 0), v->data());
    EXPECT_EQ(v->block(1, 0) - v->data(), 48);      // channel 1 follows channel 0
    EXPECT_EQ(v->block(1, 2) - v->data(), 5 * 48);  // time point 2, channel 1
    EXPECT_THROW(v->block(2, 0), std::out_of_range);
    EXPECT_THROW(v->block(0, 3), std::out_of_range);
    const std::uint16_t hot = 9000;
    std::memcpy(v->block(1, 2) + 2 * 23, &hot, 2);  // last voxel of the last block
    v->dirty();
    EXPECT_EQ(v->valueRange(), std::make_pair(0.0, 9000.0)) << "statistics cover every block";
    EXPECT_EQ(v->storedValue(143), 9000.0);

    std::vector<std::uint8_t> bytes(4 * 3 * 2 * 2 * 2);
    EXPECT_THROW(v->assign(VoxelType::UInt16, {4, 3, 2}, std::vector<std::uint8_t>(bytes), 2, 2), std::invalid_argument);
    v->assign(VoxelType::UInt16, {4, 3, 2}, std::move(bytes), 2, 1);
    EXPECT_EQ(v->channels(), 2);
    EXPECT_EQ(v->frames(), 1);
    EXPECT_THROW(v->allocate(VoxelType::UInt8, {4, 4, 4}, 0, 1), std::invalid_argument);
    EXPECT_THROW(v->allocate(VoxelType::UInt8, {4, 4, 4}, 1, -2), std::invalid_argument);
    // 2^31-1 cubed overflows 64 bits long before the 2^34-voxel limit is checked naively.
    EXPECT_THROW(Volume::checkedVoxelCount({2147483647, 2147483647, 2147483647}, 2147483647), std::invalid_argument);
    EXPECT_THROW(Volume::checkedVoxelCount({1024, 1024, 1024}, 17), std::invalid_argument);
    EXPECT_EQ(Volume::checkedVoxelCount({1024, 1024, 1024}, 16), std::uint64_t(1) << 34);
}

}  // namespace volren::test
