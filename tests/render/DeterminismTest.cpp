// The same input renders bit-identically twice, and no pixel is ever NaN, even for float
// volumes holding NaN and Inf voxels.
#include "RenderFixture.h"
#include "TestData.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace volren::test {
namespace {

class Determinism : public RenderFixture
{
};

osg::ref_ptr<Volume> noiseVolume(bool withNonFinite)
{
    osg::ref_ptr<Volume> v = new Volume;
    v->allocate(VoxelType::Float32, {24, 20, 16});
    v->setSpacing({1.0, 1.0, 2.0});
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> dist(0.0f, 1.0f);
    auto* f = reinterpret_cast<float*>(v->data());
    for (std::size_t i = 0; i < v->voxelCount(); ++i) f[i] = dist(rng);
    if (withNonFinite) {
        f[100] = std::numeric_limits<float>::quiet_NaN();
        f[2000] = std::numeric_limits<float>::infinity();
        f[3000] = -std::numeric_limits<float>::infinity();
        for (std::size_t i = 4000; i < 4400; ++i) f[i] = std::numeric_limits<float>::quiet_NaN();
    }
    v->dirty();
    return v;
}

Pixels renderNoise(bool withNonFinite)
{
    osg::ref_ptr<Volume> volume = noiseVolume(withNonFinite);
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    tf->setPoint(0.0, osg::Vec4(0, 0, 1, 0.0f));
    tf->setPoint(1.0, osg::Vec4(1, 0.5f, 0, 0.3f));
    osg::ref_ptr<VolumeNode> node = new VolumeNode;
    node->setVolume(volume.get());
    node->setTransferFunction(tf.get());
    node->settings.functions["Jitter"] = "hash";
    const osg::Matrixd view =
        osg::Matrixd::lookAt(osg::Vec3d(40, -50, 30), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 0, 1));
    return RenderFixture::render(node.get(), 64, 48, view, osg::Matrixd::perspective(40, 64.0 / 48, 1, 500),
                                 osg::Vec3(0.1f, 0.1f, 0.1f));
}

TEST_F(Determinism, SameInputRendersBitIdenticalImages)
{
    const Pixels a = renderNoise(false);
    const Pixels b = renderNoise(false);
    ASSERT_EQ(a.rgba.size(), b.rgba.size());
    EXPECT_EQ(0, std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(osg::Vec4)));
    int covered = 0;
    for (const osg::Vec4& p : a.rgba) covered += p.a() > 0.01f;
    EXPECT_GT(covered, 200) << "the volume should cover part of the image";
}

TEST_F(Determinism, NaNAndInfVoxelsNeverProduceNaNPixels)
{
    const Pixels img = renderNoise(true);
    int covered = 0;
    for (const osg::Vec4& p : img.rgba) {
        for (int c = 0; c < 4; ++c) ASSERT_TRUE(std::isfinite(p[c]));
        ASSERT_GE(p.a(), 0.0f);
        ASSERT_LE(p.a(), 1.0f);
        covered += p.a() > 0.01f;
    }
    EXPECT_GT(covered, 200);
}

}  // namespace
}  // namespace volren::test
