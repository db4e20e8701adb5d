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

TEST(BrickPlan, ABudgetFillsWholeLevelsFromTheCoarsestAndConstantBricksTakeNoSlot)
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
    // Room for every level but 0: level 1 is the finest whole one, level 0 left out.
    const BrickPlan plan = planBricks(layout, ranges, 0, coarse + slotsOf(0) - 1, true);
    EXPECT_EQ(plan.finest, 1);
    EXPECT_EQ(plan.slotted.size(), coarse);
    for (const BrickId& id : plan.slotted) EXPECT_GE(id.level, 1);
    // Coarsest level first, so loaders fill the levels a ray falls back to before finer ones.
    EXPECT_EQ(plan.slotted.front().level, int(layout.levels.size()) - 1);
    EXPECT_EQ(plan.slotted.back().level, 1);
    // The constant brick (1, 1, 0) of level 1 takes no slot: its page entry holds its value.
    bool found = false;
    for (const auto& [id, value] : plan.constant)
        if (id == BrickId{1, {1, 1, 0}}) found = value == 0.25f;
    EXPECT_TRUE(found);
    // One more slot holds level 0 too.
    EXPECT_EQ(planBricks(layout, ranges, 0, coarse + slotsOf(0), true).finest, 0);
    // Asked for level 2 only: levels 0 and 1 stay out however large the pool.
    EXPECT_EQ(planBricks(layout, ranges, 2, 512, true).finest, 2);
    EXPECT_THROW(planBricks(layout, ranges, 0, 0, true), std::invalid_argument);
    // Unknown ranges (a lazy file's level not read yet): every brick needs a slot.
    std::vector<MacrocellGrid> unknown = ranges;
    unknown[1] = MacrocellGrid{};
    EXPECT_EQ(planBricks(layout, unknown, 0, coarse + slotsOf(0), true).finest, 1);
}

TEST(BrickPlan, BricksOutOfViewAreLeftOutSoAFinerLevelFits)
{
    // Seeing only bricks with x == 0, the pool holds level 0's visible bricks where it could not
    // hold all of them; the coarsest level stays whole.
    const BrickLayout layout = brickLayout({40, 24, 16}, 8);
    const std::vector<MacrocellGrid> ranges = syntheticRanges(layout);
    const std::size_t all = planBricks(layout, ranges, 0, 100000, true).slotted.size();
    auto leftColumn = [](int, const osg::Vec3i& b) { return b.x() == 0; };
    const BrickPlan seen = planBricks(layout, ranges, 0, 100000, true, leftColumn);
    EXPECT_EQ(seen.finest, 0);
    EXPECT_LT(seen.slotted.size(), all);
    for (const BrickId& id : seen.slotted)
        EXPECT_TRUE(id.brick.x() == 0 || id.level == int(layout.levels.size()) - 1) << id.level;
    EXPECT_EQ(planBricks(layout, ranges, 0, seen.slotted.size(), true, leftColumn).finest, 0);
    EXPECT_GT(planBricks(layout, ranges, 0, seen.slotted.size(), true).finest, 0);
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
            node->settings.parameters["isoValue"] = 150.0;
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

TEST_F(BrickedVolume, StreamedFramesAreCompleteAtSomeLevelAndConvergeToTheWaitingFrame)
{
    // Streaming (volren view): a frame draws what is in the pool, at most uploadBudgetMB of
    // bricks more per frame, with the coarsest levels there from the first frame, so no frame has
    // a hole; the frames converge to the image of a frame that waits for its bricks.
    osg::ref_ptr<Volume> volume = field();
    osg::ref_ptr<TransferFunction> tf = transferFunction(
        {{0, {0, 0, 0, 0}}, {60, {0.2f, 0.3f, 0.8f, 0.05f}}, {160, {1.0f, 0.8f, 0.5f, 0.4f}}, {255, {1, 1, 1, 0.8f}}}, 0, 255);
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get());
    node->settings.brickSize = 4;  // 10^3 bricks at level 0, 6^3 bytes each
    node->settings.functions["VolumeStorage"] = "bricked";
    const Pixels waited = oblique(sceneOf(node.get()).get());

    osg::ref_ptr<VolumeScene> scene = sceneOf(node.get());
    scene->pass.streamBricks = true;
    const std::size_t perFrame = 25;
    scene->pass.uploadBudgetMB = perFrame * 216 / 1048576.0;
    const Pixels first = oblique(scene.get());
    ASSERT_EQ(scene->brickStatistics().size(), 1u);
    const BrickStatistics atFirst = scene->brickStatistics().front();
    EXPECT_GT(scene->pendingBricks(), 100u) << "the first frame cannot hold level 0";
    EXPECT_GT(maxDifference(first, waited), 1e-3);
    EXPECT_EQ(covered(first), covered(waited)) << "no holes: every pixel the volume covers has a value";
    std::size_t uploaded = atFirst.uploaded;
    int frames = 1;
    Pixels last = first;
    for (; scene->pendingBricks() > 0 && frames < 2000; ++frames) {
        scene->waitForBricks(1.0);
        last = oblique(scene.get());
        const BrickStatistics now = scene->brickStatistics().front();
        EXPECT_LE(now.uploaded - uploaded, perFrame + 1) << "frame " << frames;
        uploaded = now.uploaded;
        EXPECT_EQ(covered(last), covered(waited)) << "frame " << frames;
    }
    EXPECT_EQ(scene->pendingBricks(), 0u);
    EXPECT_GT(frames, 10) << "at most " << perFrame << " bricks a frame";
    EXPECT_LE(maxDifference(last, waited), 1e-5) << "converged after " << frames << " frames";
}

TEST_F(BrickedVolume, ABudgetTooSmallForTheVolumeHoldsTheFinestLevelOfWhatTheViewSees)
{
    // Close to one corner the view sees a few level-0 bricks: a pool that cannot hold level 0
    // whole holds those, and the image is the single texture's; seen whole, the same budget
    // falls back to a coarser level.
    osg::ref_ptr<Volume> volume = bytes([](int x, int y, int z) { return (x * 37 + y * 91 + z * 53) % 200 + 30; }, 96);
    osg::ref_ptr<TransferFunction> tf =
        transferFunction({{0, {0, 0, 0, 0}}, {100, {0.3f, 0.5f, 0.9f, 0.02f}}, {255, {1, 0.9f, 0.6f, 0.2f}}}, 0, 255);
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get());
    osg::ref_ptr<VolumeScene> scene = sceneOf(node.get());
    node->settings.brickSize = 4;
    node->settings.texturePrecision = "16bit";
    const osg::Vec3d eye(80, -80, 65);
    auto corner = [&] {
        const osg::Matrixd v = osg::Matrixd::lookAt(eye, osg::Vec3d(45, -45, 45), osg::Vec3d(0, 0, 1));
        return render(scene.get(), 48, 40, v, osg::Matrixd::perspective(8, 1.2, 0.05, 300), osg::Vec3(0.1f, 0.2f, 0.3f));
    };
    node->settings.functions["VolumeStorage"] = "texture";
    const Pixels single = corner();
    node->settings.functions["VolumeStorage"] = "bricked";
    node->settings.memoryBudgetMB = 1;  // 6^3 16-bit texels a slot: 2427 slots for level 0's 13824 bricks
    const Pixels bricked = corner();
    ASSERT_EQ(scene->brickStatistics().size(), 1u);
    EXPECT_EQ(scene->brickStatistics().front().levelSampled, 0);
    EXPECT_GT(covered(single), 300);
    EXPECT_LE(maxDifference(single, bricked), 1e-4);
    // Seen whole, the pool evicts corner bricks of level 0 for the coarser level it now holds,
    // and the image is the single texture's at that level.
    const Pixels whole = oblique(scene.get());
    const BrickStatistics stats = scene->brickStatistics().front();
    EXPECT_GT(stats.levelSampled, 0) << "the whole volume does not fit at level 0";
    EXPECT_GT(stats.evicted, 0u);
    node->settings.functions["VolumeStorage"] = "texture";
    node->settings.lod = stats.levelSampled;
    EXPECT_LE(maxDifference(oblique(scene.get()), whole), 1e-4);
}

TEST_F(BrickedVolume, BricksTheTransferFunctionHidesAreNeverLoadedAndTheImageStaysTheSame)
{
    // Values below 60 vary but the TF shows nothing there: their bricks (with the footprint and
    // the gradient's voxel around them) take no slot and read as their lowest value, and the lit
    // image is the single texture's, edges of the visible part included. A TF that shows them
    // loads them, and the image follows.
    osg::ref_ptr<Volume> volume = bytes(
        [](int x, int y, int z) {
            const int noise = (x * 7 + y * 13 + z * 29) % 40;
            return x < 20 ? noise : int(128 + 100 * std::sin(0.3 * x) * std::cos(0.23 * y + 0.1 * z));
        },
        48);
    osg::ref_ptr<TransferFunction> tf = transferFunction(
        {{0, {0, 0, 0, 0}}, {60, {0, 0, 0, 0}}, {61, {0.2f, 0.3f, 0.8f, 0.05f}}, {160, {1.0f, 0.8f, 0.5f, 0.4f}}, {255, {1, 1, 1, 0.8f}}},
        0, 255);
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get());
    osg::ref_ptr<VolumeScene> scene = sceneOf(node.get(), true);
    node->settings.brickSize = 4;
    node->settings.functions["VolumeStorage"] = "texture";
    const Pixels single = oblique(scene.get());
    node->settings.functions["VolumeStorage"] = "bricked";
    const Pixels bricked = oblique(scene.get());
    ASSERT_EQ(scene->brickStatistics().size(), 1u);
    const BrickStatistics hiding = scene->brickStatistics().front();
    EXPECT_GT(hiding.hidden, 12u * 12 * 3) << "level 0's bricks at x < 16 hold only hidden values";
    EXPECT_LE(maxDifference(single, bricked), 1e-4);
    EXPECT_GT(covered(single), 300);

    tf->assign(*transferFunction({{0, {0, 0, 0, 0}}, {10, {0.9f, 0.1f, 0.1f, 0.3f}}, {60, {0.9f, 0.1f, 0.1f, 0.3f}},
                                  {160, {1.0f, 0.8f, 0.5f, 0.4f}}, {255, {1, 1, 1, 0.8f}}},
                                 0, 255));
    node->settings.functions["VolumeStorage"] = "texture";
    const Pixels singleShown = oblique(scene.get());
    node->settings.functions["VolumeStorage"] = "bricked";
    const Pixels shown = oblique(scene.get());
    EXPECT_GT(maxDifference(single, singleShown), 1e-2) << "the second TF must show what the first hid";
    // Nothing stale from the first TF: the same as a scene that never hid those bricks, and as the
    // single texture, within the filter's coordinate rounding (the bricks sit in other slots; the
    // noise this TF shows is high-contrast: llvmpipe's 8-bit filter weights move it by ~1e-4).
    EXPECT_LE(maxDifference(oblique(sceneOf(node.get(), true).get()), shown), 2e-4);
    EXPECT_LE(maxDifference(singleShown, shown), 2e-4);
    EXPECT_LT(scene->brickStatistics().front().hidden, hiding.hidden);
    EXPECT_GT(scene->brickStatistics().front().resident, hiding.resident);
}

TEST_F(BrickedVolume, BudgetsOfOneFewAndEveryBrickSampleTheFinestLevelTheyHoldWhole)
{
    // Bricks of 64 voxels (66^3 16-bit texels, 575 KB a slot) of a 64^3 volume: every level is
    // one brick, the coarsest (one voxel) constant, so it takes no slot. 1 MiB holds one slot:
    // level 5 (2^3 voxels); 2 MiB three: levels 5, 4 and 3; 8 MiB all six others. Each image is
    // the single texture's at that level.
    osg::ref_ptr<Volume> volume = bytes([](int x, int y, int z) { return 40 + (x * 3 + y * 5 + z * 7) % 180; }, 64);
    osg::ref_ptr<TransferFunction> tf =
        transferFunction({{0, {0, 0, 0, 0}}, {100, {0.3f, 0.5f, 0.9f, 0.05f}}, {255, {1, 0.9f, 0.6f, 0.3f}}}, 0, 255);
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get());
    node->settings.brickSize = 64;
    node->settings.texturePrecision = "16bit";
    for (const auto& [budgetMB, level] : std::vector<std::pair<int, int>>{{1, 5}, {2, 3}, {8, 0}}) {
        osg::ref_ptr<VolumeScene> scene = sceneOf(node.get());
        node->settings.memoryBudgetMB = budgetMB;
        node->settings.functions["VolumeStorage"] = "bricked";
        node->settings.lod = 0;
        const Pixels bricked = oblique(scene.get());
        ASSERT_EQ(scene->brickStatistics().size(), 1u);
        EXPECT_EQ(scene->brickStatistics().front().levelSampled, level) << budgetMB << " MiB";
        EXPECT_EQ(scene->brickStatistics().front().resident, std::size_t(6 - level)) << budgetMB << " MiB";
        EXPECT_EQ(scene->brickStatistics().front().constant, 1u) << budgetMB << " MiB";
        node->settings.memoryBudgetMB = 0;
        node->settings.functions["VolumeStorage"] = "texture";
        node->settings.lod = level;
        const Pixels single = oblique(scene.get());
        EXPECT_LE(maxDifference(single, bricked), 1e-4) << budgetMB << " MiB";
        EXPECT_GT(covered(single), 300) << budgetMB << " MiB";
    }
}

}  // namespace
}  // namespace volren::test
