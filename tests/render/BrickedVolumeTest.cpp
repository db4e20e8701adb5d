// Bricked volumes (VolumeStorage bricked, BrickPool.h): the layout of every level's bricks, which
// bricks a budget holds, and images equal to the single-texture storage's: at the node's level
// when the budget holds it, at the finest level that fits otherwise.
#include "AccelerationFixture.h"

#include <volume_renderer/BrickPool.h>
#include <volume_renderer/VolumeMipChain.h>

#include <cmath>
#include <string>

namespace volren::test {
namespace {

TEST(BrickLayout, EveryLevelIsCutIntoBricksAndStackedInThePageTable)
{
    const BrickLayout layout = brickLayout({37, 20, 9}, 8);
    ASSERT_EQ(int(layout.levels.size()), mipLevelCount({37, 20, 9}));
    EXPECT_EQ(layout.levels[0].dims, osg::Vec3i(37, 20, 9));
    EXPECT_EQ(layout.levels[0].bricks, osg::Vec3i(5, 3, 2));  // ceil(37/8), ceil(20/8), ceil(9/8)
    EXPECT_EQ(layout.levels[1].dims, osg::Vec3i(18, 10, 4));
    EXPECT_EQ(layout.levels[1].bricks, osg::Vec3i(3, 2, 1));
    EXPECT_EQ(layout.levels[1].tableZ, 2);
    EXPECT_EQ(layout.levels[2].tableZ, 3);
    int z = 0;
    for (const BrickLevel& l : layout.levels) z += l.bricks.z();
    EXPECT_EQ(layout.tableSize, osg::Vec3i(5, 3, z));
    EXPECT_EQ(layout.brickCount(0), 30u);
    EXPECT_THROW(brickLayout({4, 4, 4}, 1), std::invalid_argument);
}

/// Ranges of a layout's levels: brick (x, y, z) of level L holds [L + x, L + x + 1], except bricks
/// with y == 1, which hold the one value 0.25.
std::vector<MacrocellGrid> syntheticRanges(const BrickLayout& layout)
{
    std::vector<MacrocellGrid> out;
    for (std::size_t level = 0; level < layout.levels.size(); ++level) {
        MacrocellGrid g;
        g.cellSize = layout.brickSize;
        g.cells = layout.levels[level].bricks;
        for (int z = 0; z < g.cells.z(); ++z)
            for (int y = 0; y < g.cells.y(); ++y)
                for (int x = 0; x < g.cells.x(); ++x) {
                    g.lo.push_back(y == 1 ? 0.25f : float(level + x));
                    g.hi.push_back(y == 1 ? 0.25f : float(level + x + 1));
                }
        out.push_back(g);
    }
    return out;
}

TEST(BrickResidency, ABudgetFillsWholeLevelsFromTheCoarsestAndConstantBricksTakeNoSlot)
{
    const BrickLayout layout = brickLayout({40, 24, 16}, 8);  // levels: 5x3x2, 3x2x1, 2x1x1, 1x1x1, ...
    const std::vector<MacrocellGrid> ranges = syntheticRanges(layout);
    auto slotsOf = [&](int level) {
        std::size_t n = 0;
        for (std::size_t i = 0; i < ranges[std::size_t(level)].size(); ++i) n += ranges[std::size_t(level)].lo[i] != 0.25f;
        return n;
    };
    std::size_t coarse = 0;
    for (int level = 1; level < int(layout.levels.size()); ++level) coarse += slotsOf(level);
    // Room for every level but 0: level 1 is the finest complete one, level 0 all missing.
    const BrickResidency r = chooseResidency(layout, ranges, 0, {4, 4, 4}, coarse + slotsOf(0) - 1);
    EXPECT_EQ(r.finestComplete, 1);
    EXPECT_EQ(r.resident.size(), coarse);
    const osg::Vec3i& t = layout.tableSize;
    auto entry = [&](int level, int x, int y, int z) {
        const int tz = z + layout.levels[std::size_t(level)].tableZ;
        return &r.pageTable[((std::size_t(tz) * t.y() + y) * t.x() + x) * 4];
    };
    for (int x = 0; x < 5; ++x) EXPECT_EQ(entry(0, x, 0, 0)[3], float(PageEntry::Missing));
    EXPECT_EQ(entry(1, 1, 1, 0)[3], float(PageEntry::Constant));
    EXPECT_EQ(entry(1, 1, 1, 0)[0], 0.25f);
    // Slots are handed out in order, x fastest over the pool's 4 x 4 x 4 slots.
    const float* last = entry(1, 2, 0, 0);
    EXPECT_EQ(last[3], float(PageEntry::Resident));
    const std::size_t slot = std::size_t(last[0] + 4 * last[1] + 16 * last[2]);
    ASSERT_LT(slot, r.resident.size());
    EXPECT_EQ(r.resident[slot].first, 1);
    EXPECT_EQ(r.resident[slot].second, osg::Vec3i(2, 0, 0));
    // One more slot holds level 0 too.
    EXPECT_EQ(chooseResidency(layout, ranges, 0, {4, 4, 4}, coarse + slotsOf(0)).finestComplete, 0);
    // Asked for level 2 only: levels 0 and 1 stay missing however large the pool.
    EXPECT_EQ(chooseResidency(layout, ranges, 2, {8, 8, 8}, 512).finestComplete, 2);
    EXPECT_THROW(chooseResidency(layout, ranges, 0, {1, 1, 1}, 0), std::invalid_argument);
}

TEST(BrickResidency, PoolSlotsStayWithinTheLargestTexture)
{
    const osg::Vec3i s = poolSlotsFor(1000, 34, 2048);
    EXPECT_GE(std::size_t(s.x()) * s.y() * s.z(), 1000u);
    EXPECT_LE(s.x() * 34, 2048);
    const osg::Vec3i capped = poolSlotsFor(1000000, 34, 340);  // at most 10 slots per axis
    EXPECT_EQ(capped, osg::Vec3i(10, 10, 10));
    EXPECT_THROW(poolSlotsFor(1, 34, 16), std::invalid_argument);
}

class BrickedVolume : public AccelerationFixture
{
protected:
    /// A smooth field with a constant slab (constant bricks) and odd sizes.
    static osg::ref_ptr<Volume> field(int n = 37)
    {
        return bytes(
            [](int x, int y, int z) {
                if (z < 9) return 40;  // constant bricks of 8 voxels with their borders below z = 8
                return int(128 + 100 * std::sin(0.3 * x) * std::cos(0.23 * y + 0.1 * z));
            },
            n);
    }
    static std::string storageOf(VolumeScene* scene)
    {
        const std::vector<std::string> keys = scene->compositionKeys();
        if (keys.empty()) return {};
        const std::size_t at = keys.front().find("VolumeStorage=");
        return at == std::string::npos ? std::string() : keys.front().substr(at + 14, keys.front().find(';', at) - at - 14);
    }
};

TEST_F(BrickedVolume, EveryReconstructionAndTraversalSeesTheSingleTexturesVoxels)
{
    // Bricks of 8 voxels with their one-voxel border: linear filtering, the tricubic's eight
    // fetches and the gradients' neighbours read across brick edges as in one texture.
    osg::ref_ptr<Volume> volume = field();
    osg::ref_ptr<TransferFunction> tf = transferFunction(
        {{0, {0, 0, 0, 0}}, {60, {0.2f, 0.3f, 0.8f, 0.05f}}, {160, {1.0f, 0.8f, 0.5f, 0.4f}}, {255, {1, 1, 1, 0.8f}}}, 0, 255);
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get());
    osg::ref_ptr<VolumeScene> scene = sceneOf(node.get(), true);
    node->settings.brickSize = 8;
    for (const char* traversal : {"dvr_front_to_back", "mip", "isosurface"})
        for (const char* reconstruction : {"nearest", "trilinear", "tricubic"}) {
            node->settings.functions["RayTraversal"] = traversal;
            node->settings.functions["Reconstruction"] = reconstruction;
            node->settings.isoValue = 150;
            node->settings.functions["VolumeStorage"] = "texture";
            const Pixels single = oblique(scene.get());
            EXPECT_EQ(storageOf(scene.get()), "texture");
            node->settings.functions["VolumeStorage"] = "bricked";
            const Pixels bricked = oblique(scene.get());
            EXPECT_EQ(storageOf(scene.get()), "bricked");
            // Only the filter weights' coordinate rounding differs (pool texels against the volume's).
            EXPECT_LE(maxDifference(single, bricked), 1e-4) << traversal << " " << reconstruction;
            EXPECT_GT(covered(single), 300) << traversal;
        }
}

TEST_F(BrickedVolume, AVolumeOverItsBudgetIsBrickedAtTheFinestLevelThatFits)
{
    // 64^3 bytes in 16-bit texels (512 KiB) fit a budget of 1 MiB as one texture. With a budget
    // the bricks of 4 voxels (6^3 texels, 432 bytes) of level 0 do not fit (16^3 = 4096 bricks,
    // 2427 slots per MiB) but those of level 1 do: the policy bricks the volume by itself and
    // the image is the single texture's at lod 1.
    osg::ref_ptr<Volume> volume = bytes([](int x, int y, int z) { return (x * 37 + y * 91 + z * 53) % 200 + 30; }, 64);
    osg::ref_ptr<TransferFunction> tf =
        transferFunction({{0, {0, 0, 0, 0}}, {100, {0.3f, 0.5f, 0.9f, 0.02f}}, {255, {1, 0.9f, 0.6f, 0.2f}}}, 0, 255);
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get());
    osg::ref_ptr<VolumeScene> scene = sceneOf(node.get());
    node->settings.texturePrecision = "16bit";
    node->settings.memoryBudgetMB = 1;
    node->settings.brickSize = 4;
    const Pixels fits = oblique(scene.get());
    EXPECT_EQ(storageOf(scene.get()), "texture") << "512 KiB fit in 1 MiB";

    node->settings.lod = 1;
    const Pixels level1 = oblique(scene.get());
    node->settings.lod = 0;
    node->settings.functions["VolumeStorage"] = "bricked";
    const Pixels bricked = oblique(scene.get());
    EXPECT_GT(maxDifference(fits, level1), 1e-3) << "levels 0 and 1 must differ for this test to mean anything";
    EXPECT_LE(maxDifference(bricked, level1), 1e-4) << "sampled at level 1, the finest that fits";
    node->settings.functions.erase("VolumeStorage");

    // A volume larger than the budget is bricked without being asked, its pool within the budget.
    osg::ref_ptr<Volume> large = bytes([](int x, int y, int z) { return (x * 37 + y * 91 + z * 53) % 200 + 30; }, 160);
    osg::ref_ptr<VolumeNode> largeNode = volumeNode(large.get(), tf.get());
    largeNode->settings = node->settings;
    largeNode->settings.brickSize = 16;  // page entries of 16 bytes per brick: few with bricks of 16
    osg::ref_ptr<VolumeScene> largeScene = sceneOf(largeNode.get());
    const Pixels over = oblique(largeScene.get());  // 160^3 16-bit texels: 7.8 MiB
    EXPECT_EQ(storageOf(largeScene.get()), "bricked");
    EXPECT_GT(covered(over), 300);
    EXPECT_LE(largeScene->textureBytes(), (std::size_t(5) << 20) / 4) << "a pool of at most 1 MiB, tables and grids";
}

}  // namespace
}  // namespace volren::test
