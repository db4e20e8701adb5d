// Re-quantising a volume to another voxel type (the bench's texture-precision rows).
#include "TestData.h"

#include <volume_model/Requantise.h>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace volren::test {
namespace {

osg::ref_ptr<Volume> floatRamp()
{
    osg::ref_ptr<Volume> v = new Volume;
    v->allocate(VoxelType::Float32, {7, 3, 2});
    auto* f = reinterpret_cast<float*>(v->data());
    for (std::size_t i = 0; i < v->voxelCount(); ++i) f[i] = float(-20.0 + 3.7 * double(i));
    v->setSpacing({0.5, 1.0, 2.0});
    v->setName("ramp");
    v->dirty();
    return v;
}

TEST(Requantise, IntegerTypesSpanTheValueRangeWithinHalfAStep)
{
    const osg::ref_ptr<Volume> ramp = floatRamp();
    const auto [lo, hi] = ramp->valueRange();
    for (auto [type, top] : {std::pair{VoxelType::UInt8, 255.0}, {VoxelType::UInt16, 65535.0}}) {
        const osg::ref_ptr<Volume> q = requantise(*ramp, type);
        ASSERT_EQ(q->type(), type);
        EXPECT_EQ(q->dims(), ramp->dims());
        EXPECT_EQ(q->spacing(), ramp->spacing());
        EXPECT_EQ(q->getName(), "ramp");
        const double step = (hi - lo) / top;
        EXPECT_DOUBLE_EQ(q->rescaleSlope(), step);
        EXPECT_DOUBLE_EQ(q->rescaleIntercept(), lo);
        for (std::size_t i = 0; i < ramp->voxelCount(); ++i) EXPECT_NEAR(q->value(i), ramp->value(i), step / 2 + 1e-9) << i;
        EXPECT_DOUBLE_EQ(q->value(0), lo);
        EXPECT_NEAR(q->value(ramp->voxelCount() - 1), hi, 1e-9);
    }
}

TEST(Requantise, FloatKeepsValuesAndNonFiniteVoxelsBecomeTheLowest)
{
    osg::ref_ptr<Volume> ramp = floatRamp();
    const osg::ref_ptr<Volume> same = requantise(*ramp, VoxelType::Float32);
    for (std::size_t i = 0; i < ramp->voxelCount(); ++i) EXPECT_EQ(same->value(i), ramp->value(i));
    reinterpret_cast<float*>(ramp->data())[3] = std::nanf("");
    ramp->dirty();
    const osg::ref_ptr<Volume> q = requantise(*ramp, VoxelType::UInt8);
    EXPECT_EQ(q->data()[3], 0);
    EXPECT_THROW(requantise(*ramp, VoxelType::Int16), std::invalid_argument);
}

}  // namespace
}  // namespace volren::test
