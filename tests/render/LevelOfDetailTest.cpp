// Level of detail: each mip level is the average of the voxels each coarse voxel covers, the GPU
// samples the level asked for (closed form), empty-space skipping stays exact at every level,
// and LOD by distance picks the level from how many voxels a pixel covers.
#include "AccelerationFixture.h"
#include "RenderFixture.h"
#include "TestData.h"

#include <volume_renderer/VolumeMipChain.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace volren::test {
namespace {

/// Values of a level's image (mipLevelImages) of a float volume.
std::vector<float> levelValues(const osg::Image& image)
{
    std::vector<float> out(std::size_t(image.s()) * image.t() * image.r());
    std::memcpy(out.data(), image.data(), out.size() * sizeof(float));
    return out;
}

TEST(VolumeMipChain, LevelsHalveAndRoundDownToOneVoxel)
{
    EXPECT_EQ(mipDims({5, 4, 3}, 1), osg::Vec3i(2, 2, 1));
    EXPECT_EQ(mipDims({5, 4, 3}, 2), osg::Vec3i(1, 1, 1));
    EXPECT_EQ(mipLevelCount({5, 4, 3}), 3);
    EXPECT_EQ(mipLevelCount({256, 256, 113}), 9);
    EXPECT_EQ(mipLevelCount({1, 1, 1}), 1);
    EXPECT_DOUBLE_EQ(mipVoxelSpan({5, 4, 3}, 1), 3.0);  // z: 3 voxels into 1
}

TEST(VolumeMipChain, EachVoxelIsTheOverlapWeightedAverageOfTheVoxelsItCovers)
{
    // Odd sizes: a level-1 voxel covers 2.5 level-0 voxels along x (5 -> 2) and 3 along z.
    const osg::Vec3i dims(5, 4, 3);
    osg::ref_ptr<Volume> volume = new Volume;
    volume->allocate(VoxelType::Float32, dims);
    std::mt19937 random(5);
    std::uniform_real_distribution<float> value(-10.0f, 10.0f);
    auto* v = reinterpret_cast<float*>(volume->data());
    for (std::size_t i = 0; i < volume->voxelCount(); ++i) v[i] = value(random);
    volume->dirty();
    const std::vector<osg::ref_ptr<osg::Image>> levels = mipLevelImages(*volume, 5);
    ASSERT_EQ(levels.size(), 2u) << "levels 1 and 2: clamped to the chain";
    ASSERT_EQ(osg::Vec3i(levels[0]->s(), levels[0]->t(), levels[0]->r()), mipDims(dims, 1));
    const std::vector<float> level1 = levelValues(*levels[0]);
    // Brute force in 3D: weight of level-0 voxel i under level-1 voxel j = product of overlaps.
    auto overlap = [](int i, int j, double r) {
        return std::max(0.0, std::min((j + 1) * r, i + 1.0) - std::max(j * r, double(i)));
    };
    const osg::Vec3i d1 = mipDims(dims, 1);
    for (int z = 0; z < d1.z(); ++z)
        for (int y = 0; y < d1.y(); ++y)
            for (int x = 0; x < d1.x(); ++x) {
                double sum = 0.0, weight = 0.0;
                for (int k = 0; k < dims.z(); ++k)
                    for (int j = 0; j < dims.y(); ++j)
                        for (int i = 0; i < dims.x(); ++i) {
                            const double w = overlap(i, x, 2.5) * overlap(j, y, 2.0) * overlap(k, z, 3.0);
                            sum += w * v[i + dims.x() * (j + dims.y() * k)];
                            weight += w;
                        }
                EXPECT_NEAR(level1[std::size_t(x + d1.x() * (y + d1.y() * z))], sum / weight, 1e-5) << x << " " << y << " " << z;
            }
    double mean = 0.0;
    for (std::size_t i = 0; i < volume->voxelCount(); ++i) mean += v[i];
    EXPECT_NEAR(levelValues(*levels[1])[0], mean / double(volume->voxelCount()), 1e-4) << "the last level: the mean";
}

TEST(VolumeMipChain, NaNVoxelsAreLeftOutAndIntegersStayWithinTheirVoxels)
{
    osg::ref_ptr<Volume> floats = new Volume;
    floats->allocate(VoxelType::Float32, {4, 2, 2});
    auto* f = reinterpret_cast<float*>(floats->data());
    for (int i = 0; i < 16; ++i) f[i] = std::numeric_limits<float>::quiet_NaN();
    f[2] = 3.0f;  // level-1 voxel x = 1 covers x = 2, 3: one finite value in its box
    floats->dirty();
    const std::vector<float> level1 = levelValues(*mipLevelImages(*floats, 1).at(0));
    EXPECT_TRUE(std::isnan(level1[0])) << "a box of NaN only";
    EXPECT_EQ(level1[1], 3.0f);

    osg::ref_ptr<Volume> bytes = new Volume;
    bytes->allocate(VoxelType::UInt8, {2, 2, 2});
    const std::uint8_t values[8] = {0, 1, 1, 1, 1, 1, 1, 1};  // mean 0.875 -> 1
    std::memcpy(bytes->data(), values, 8);
    bytes->dirty();
    EXPECT_EQ(mipLevelImages(*bytes, 1).at(0)->data()[0], 1);
}

class LevelOfDetail : public AccelerationFixture
{
};

TEST_F(LevelOfDetail, TheNextLevelSamplesTheAverageOfStripesAsItsClosedForm)
{
    // Stripes of 0 and 200 along x, one voxel wide: level 1 is 100 everywhere. Through 32 voxels
    // along z with a TF whose opacity rises linearly to 0.05 at 255 (per voxel), a level-1
    // pixel's opacity is 1 - (1 - 0.05 * 100/255)^32, whatever the step; level 0 shows stripes.
    osg::ref_ptr<Volume> volume = bytes([](int x, int, int) { return x % 2 ? 200 : 0; });
    osg::ref_ptr<TransferFunction> tf = transferFunction({{0, {1, 1, 1, 0}}, {255, {1, 1, 1, 0.05f}}}, 0, 255);
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get());
    std::string error;
    ASSERT_TRUE(node->settings.set("earlyTermination", "1", error)) << error;
    osg::ref_ptr<VolumeScene> scene = sceneOf(node.get());
    const double expected = 1.0 - std::pow(1.0 - 0.05 * 100.0 / 255.0, 32.0);
    for (const char* reconstruction : {"trilinear", "nearest", "tricubic"}) {
        node->settings.functions["Reconstruction"] = reconstruction;
        node->settings.lod = 1;
        const Pixels coarse = renderOrthoFromPlusZ(scene.get(), 32, 32, 32.0);
        for (int x = 4; x < 28; x += 3) EXPECT_NEAR(coarse.at(x, 16).a(), expected, 2e-3) << reconstruction << " x " << x;
        node->settings.lod = 0;
        const Pixels full = renderOrthoFromPlusZ(scene.get(), 32, 32, 32.0);
        EXPECT_GT(std::abs(full.at(15, 16).a() - full.at(16, 16).a()), 0.1) << reconstruction << ": stripes at level 0";
    }
}

TEST_F(LevelOfDetail, EmptySpaceSkippingStaysExactAtEveryLevel)
{
    // The grids of a coarser level have larger cells and an apron over everything its samples
    // read (MacrocellGrid.h's gridShapeFor): images with skipping equal those without, bit for
    // bit, for a one-voxel plane (DVR both ways) and a soft shell (every reconstruction, MIP).
    osg::ref_ptr<Volume> plane = bytes([](int, int, int z) { return z == 17 ? 255 : 0; });
    osg::ref_ptr<TransferFunction> sharp =
        transferFunction({{0, {0, 0, 0, 0}}, {20, {0, 0, 0, 0}}, {255, {0.9f, 0.9f, 1.0f, 0.8f}}}, 0, 255);
    osg::ref_ptr<VolumeNode> node = volumeNode(plane.get(), sharp.get());
    osg::ref_ptr<VolumeScene> scene = sceneOf(node.get());
    for (int lod : {1, 2, 3})
        for (int size : {1, 2, 4, 8}) {
            node->settings.lod = lod;
            node->settings.macrocellSize = size;
            for (const char* traversal : {"dvr_front_to_back", "dvr_back_to_front"}) {
                node->settings.functions["RayTraversal"] = traversal;
                const auto [skipping, full] = withAndWithout(node.get(), scene.get(), [&] { return oblique(scene.get()); });
                EXPECT_TRUE(identical(skipping, full)) << "level " << lod << ", cells of " << size << ", " << traversal
                                                       << ": max difference " << maxDifference(skipping, full);
                EXPECT_GT(covered(skipping), 200) << "the plane shows at level " << lod;
            }
        }
    osg::ref_ptr<Volume> shell = bytes([](int x, int y, int z) {
        const double r = std::sqrt((x - 15.5) * (x - 15.5) + (y - 14.0) * (y - 14.0) + (z - 17.0) * (z - 17.0));
        return r < 11.0 ? int(255.0 * std::max(0.0, 1.0 - std::abs(r - 8.0) / 3.0)) : 0;
    });
    osg::ref_ptr<TransferFunction> soft =
        transferFunction({{0, {0, 0, 0, 0}}, {150, {0.2f, 0.4f, 0.9f, 0.0f}}, {255, {1.0f, 0.8f, 0.3f, 0.6f}}}, 0, 255);
    osg::ref_ptr<VolumeNode> shellNode = volumeNode(shell.get(), soft.get(), true);
    osg::ref_ptr<VolumeScene> shellScene = sceneOf(shellNode.get(), true);
    shellNode->settings.macrocellSize = 4;
    for (int lod : {1, 2})
        for (const char* reconstruction : {"nearest", "trilinear", "tricubic"}) {
            shellNode->settings.lod = lod;
            shellNode->settings.functions["Reconstruction"] = reconstruction;
            shellNode->settings.functions.erase("RayTraversal");
            auto [skipping, full] = withAndWithout(shellNode.get(), shellScene.get(), [&] { return oblique(shellScene.get()); });
            EXPECT_TRUE(identical(skipping, full)) << "level " << lod << ", " << reconstruction << ": max difference "
                                                   << maxDifference(skipping, full);
            shellNode->settings.functions["RayTraversal"] = "mip";
            shellNode->settings.functions["Acceleration"] = "range";  // MIP leaps only when asked
            std::tie(skipping, full) = withAndWithout(shellNode.get(), shellScene.get(), [&] { return oblique(shellScene.get()); },
                                                      "range");
            EXPECT_TRUE(identical(skipping, full)) << "MIP at level " << lod << ", " << reconstruction;
            shellNode->settings.functions.erase("Acceleration");
        }
}

TEST_F(LevelOfDetail, ByDistanceTheLevelFollowsTheVoxelsOnePixelCovers)
{
    // 32 voxels seen 16 pixels high over 72 units: a pixel covers 4.5 voxels, so level
    // floor(log2 4.5) = 2: the same image as lod = 2, not as level 0; with lod = 1 on top, level 3.
    osg::ref_ptr<Volume> volume = bytes([](int x, int y, int z) { return (x * 37 + y * 11 + z * 5) % 200 + 40; });
    osg::ref_ptr<TransferFunction> tf =
        transferFunction({{0, {0, 0, 0, 0}}, {40, {0.3f, 0.6f, 0.9f, 0.02f}}, {255, {1.0f, 0.7f, 0.2f, 0.2f}}}, 0, 255);
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get());
    osg::ref_ptr<VolumeScene> scene = sceneOf(node.get());
    auto image = [&](int lod, bool byDistance) {
        node->settings.lod = lod;
        node->settings.lodByDistance = byDistance;
        return renderOrthoFromPlusZ(scene.get(), 16, 16, 72.0);
    };
    const Pixels byDistance = image(0, true);
    EXPECT_TRUE(identical(byDistance, image(2, false))) << "max difference " << maxDifference(byDistance, image(2, false));
    EXPECT_GT(maxDifference(byDistance, image(0, false)), 1e-3);
    EXPECT_TRUE(identical(image(1, true), image(3, false)));
}

}  // namespace
}  // namespace volren::test
