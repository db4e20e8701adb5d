// Adaptive sampling (Acceleration adaptive) stays within its bound: one sample stands for a run
// of steps only in macrocells where the classification varies by at most adaptiveTolerance over
// every value the cell's samples can read, so thin features are never stepped over; the
// Classifications' variation mirrors bound what the GPU's lookups can return.
#include "AccelerationFixture.h"
#include "RenderFixture.h"
#include "TestData.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

#include <osg/LightSource>

#include <random>

namespace volren::test {
namespace {

class AdaptiveSampling : public AccelerationFixture
{
protected:
    /// The images of `scene` with its node's Acceleration adaptive and occupancy (exact).
    template <typename Render>
    static std::pair<Pixels, Pixels> adaptiveAndExact(VolumeNode* node, VolumeScene* scene, Render draw)
    {
        node->settings.functions["Acceleration"] = "adaptive";
        Pixels adaptive = draw();
        EXPECT_EQ(chosenAcceleration(scene), "adaptive");
        node->settings.functions["Acceleration"] = "occupancy";
        Pixels exact = draw();
        node->settings.functions.erase("Acceleration");
        return {adaptive, exact};
    }
};

TEST(ClassificationVariation, BoundsEveryDifferenceTheLookupCanReturnAndIsZeroOnPlateaus)
{
    // Brute force over fine value steps in random ranges: the largest difference of opacity and
    // opacity-weighted colour between any two values must not exceed the mirror's bound; on the
    // TF's plateau (values 120..200 with one colour and opacity) the bound is 0.
    osg::ref_ptr<Volume> volume = constantVolume(VoxelType::UInt8, {4, 4, 4}, 0.0);
    osg::ref_ptr<TransferFunction> tf = transferFunction({{0, {0, 0, 0, 0}},
                                                         {60, {0.2f, 0.9f, 0.1f, 0.05f}},
                                                         {110, {0.9f, 0.3f, 0.2f, 0.4f}},
                                                         {120, {1, 0.5f, 0.25f, 0.6f}},
                                                         {200, {1, 0.5f, 0.25f, 0.6f}},
                                                         {255, {0, 0, 1, 1}}},
                                                        0, 255);
    osg::ref_ptr<VolumeNode> node = makeVolumeNode(volume.get(), tf.get());
    osg::ref_ptr<osg::StateSet> state = new osg::StateSet;
    const std::map<std::string, int> units;
    const BindContext context{.node = *node, .volume = *volume, .transfer = *tf, .settings = node->settings,
                              .stateSet = *state, .textureUnits = units};
    const std::vector<osg::Vec4> table = tf->lookupTable();
    auto lookup = [&](double texel) {  // the GPU's tf1d: linear between table entries
        const double u = std::clamp(texel, 0.0, 1.0) * double(table.size() - 1);
        const std::size_t i = std::min(std::size_t(u), table.size() - 2);
        const double f = u - double(i);
        osg::Vec4 c;
        for (int k = 0; k < 4; ++k) c[k] = float((1.0 - f) * table[i][k] + f * table[i + 1][k]);
        return c;
    };
    for (const char* name : {"tf1d", "premultiplied", "null"}) {
        const ShaderFunction* f = ShaderFunctionRegistry::instance().find("Classification", name);
        ASSERT_TRUE(f && f->variation) << name;
        const auto variation = f->variation(context);
        std::mt19937 random(11);
        std::uniform_real_distribution<double> texel(-0.1, 1.1);
        for (int trial = 0; trial < 300; ++trial) {
            double lo = texel(random), hi = texel(random);
            if (lo > hi) std::swap(lo, hi);
            double aMin = 1e9, aMax = -1e9, cMin[3] = {1e9, 1e9, 1e9}, cMax[3] = {-1e9, -1e9, -1e9};
            for (int k = 0; k <= 400; ++k) {
                const double v = lo + (hi - lo) * k / 400.0;
                const double u = std::clamp(v, 0.0, 1.0);
                const osg::Vec4 c = std::string(name) == "null" ? osg::Vec4(u, u, u, u) : lookup(v);
                aMin = std::min(aMin, double(c.a()));
                aMax = std::max(aMax, double(c.a()));
                for (int j = 0; j < 3; ++j) {
                    cMin[j] = std::min(cMin[j], double(c[j] * c.a()));
                    cMax[j] = std::max(cMax[j], double(c[j] * c.a()));
                }
            }
            double worst = aMax - aMin;
            for (int j = 0; j < 3; ++j) worst = std::max(worst, cMax[j] - cMin[j]);
            ASSERT_GE(variation(lo, hi) + 1e-6, worst) << name << " over [" << lo << ", " << hi << "]";
        }
        if (std::string(name) != "null") {
            EXPECT_EQ(variation(130.0 / 255.0, 190.0 / 255.0), 0.0) << name << ": the plateau";
            EXPECT_GT(variation(100.0 / 255.0, 130.0 / 255.0), 0.1) << name << ": across the ramp";
        }
    }
    EXPECT_FALSE(ShaderFunctionRegistry::instance().find("Classification", "threshold")->variation)
        << "no mirror: never homogeneous";
}

TEST_F(AdaptiveSampling, AHomogeneousBlockMatchesItsClosedFormAndTheExactMarch)
{
    // A block of one value under a TF constant over it: its inner macrocells are homogeneous,
    // so one sample stands for up to 8 steps there; optical depth is exact for any step, so the
    // block's opacity is still 1 - 0.9^16 along z, and the image is the exact march's to float
    // rounding. A point light close by makes the lit colour vary with position (not linearly),
    // so merged samples show: the images are not identical.
    osg::ref_ptr<Volume> volume = bytes([](int x, int y, int z) {
        return x >= 4 && x < 28 && y >= 4 && y < 28 && z >= 8 && z < 24 ? 200 : 0;
    });
    osg::ref_ptr<TransferFunction> tf = transferFunction(
        {{0, {0, 0, 0, 0}}, {100, {0, 0, 0, 0}}, {101, {1.0f, 0.6f, 0.2f, 0.1f}}, {255, {1.0f, 0.6f, 0.2f, 0.1f}}}, 0, 255);
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get());
    node->settings.functions["Reconstruction"] = "nearest";
    node->settings.macrocellSize = 4;
    node->settings.parameters["adaptiveSteps"] = 8;
    {
        // (A scene of its own: the fixture makes a new context for another image size.)
        osg::ref_ptr<VolumeScene> alongZ = sceneOf(node.get());
        const auto [adaptive, exact] =
            adaptiveAndExact(node.get(), alongZ.get(), [&] { return renderOrthoFromPlusZ(alongZ.get(), 32, 32, 32.0); });
        EXPECT_NEAR(adaptive.at(15, 16).a(), 1.0 - std::pow(0.9, 16.0), 2e-3);
        EXPECT_LT(maxDifference(adaptive, exact), 1e-5);
        // With fewer samples (the pass's countSamples debug output): the exact march samples
        // every half-voxel step of the occupied cells, the adaptive one a sample per run of up
        // to 8 steps in the cells whose apron stays inside the block (measured: 36 of 48 on the
        // centre ray, 46,080 of 49,152 over the image).
        alongZ->pass.countSamples = true;
        const auto [merged, every] =
            adaptiveAndExact(node.get(), alongZ.get(), [&] { return renderOrthoFromPlusZ(alongZ.get(), 32, 32, 32.0); });
        alongZ->pass.countSamples = false;
        EXPECT_LE(merged.at(15, 16).r(), every.at(15, 16).r() - 8.0f);
        EXPECT_LT(samples(merged), 0.97 * samples(every));
    }
    osg::ref_ptr<VolumeScene> scene = sceneOf(node.get());
    osg::ref_ptr<osg::LightSource> light = new osg::LightSource;
    light->getLight()->setPosition(osg::Vec4(2.0f, -3.0f, 20.0f, 1.0f));
    scene->addChild(light.get());
    for (const char* traversal : {"dvr_front_to_back", "dvr_back_to_front"}) {
        node->settings.functions["RayTraversal"] = traversal;
        const auto [adaptive, exact] = adaptiveAndExact(node.get(), scene.get(), [&] { return oblique(scene.get()); });
        const double difference = maxDifference(adaptive, exact);
        EXPECT_GT(difference, 0.0) << traversal << ": merged samples are taken elsewhere";
        EXPECT_LT(difference, 0.02) << traversal;
        EXPECT_GT(covered(adaptive), 400);
    }
}

TEST_F(AdaptiveSampling, AOneVoxelPlaneInHomogeneousMaterialIsNeverSteppedOver)
{
    // Material of one value (a TF plateau) with a one-voxel plane of another value (opaque red) at
    // z = 17: the plane's cells are not homogeneous at any cell size, so no run of steps crosses
    // it, even with runs of 64 steps. The image stays within the tolerance's reach of the exact
    // march; a run over the plane would lose most of its red (checked against the plateau alone).
    osg::ref_ptr<Volume> volume = bytes([](int, int, int z) { return z == 17 ? 250 : 100; });
    osg::ref_ptr<Volume> plateauOnly = bytes([](int, int, int) { return 100; });
    osg::ref_ptr<TransferFunction> tf = transferFunction({{0, {0, 0, 0, 0}},
                                                         {80, {0.3f, 0.5f, 0.9f, 0.02f}},
                                                         {120, {0.3f, 0.5f, 0.9f, 0.02f}},
                                                         {200, {1.0f, 0.1f, 0.1f, 0.9f}},
                                                         {255, {1.0f, 0.1f, 0.1f, 0.9f}}},
                                                        0, 255);
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get());
    node->settings.parameters["adaptiveSteps"] = 64;
    osg::ref_ptr<VolumeScene> scene = sceneOf(node.get());
    osg::ref_ptr<VolumeNode> plain = volumeNode(plateauOnly.get(), tf.get());
    osg::ref_ptr<VolumeScene> plainScene = sceneOf(plain.get());
    const Pixels withoutPlane = oblique(plainScene.get());
    for (int size : {2, 4, 8, 16}) {
        node->settings.macrocellSize = size;
        for (const char* traversal : {"dvr_front_to_back", "dvr_back_to_front"}) {
            node->settings.functions["RayTraversal"] = traversal;
            const auto [adaptive, exact] = adaptiveAndExact(node.get(), scene.get(), [&] { return oblique(scene.get()); });
            EXPECT_LT(maxDifference(adaptive, exact), 0.01) << "cells of " << size << ", " << traversal;
            EXPECT_GT(maxDifference(exact, withoutPlane), 0.3) << "the plane shows";
        }
    }
}

}  // namespace
}  // namespace volren::test
