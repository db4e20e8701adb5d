// Prefetching a time series: the time points ahead of the shown one are copied on a background
// thread within the budget, a step takes them instead of copying, and the copies never pass the
// budget.
#include <volume_model/ChannelDisplay.h>
#include <volume_model/TimePrefetcher.h>
#include <volume_model/TimeSeries.h>

#include <osg/Group>

#include <gtest/gtest.h>

namespace volren::test {
namespace {

constexpr int edge = 8, timePoints = 6;
constexpr std::size_t blockBytes = edge * edge * edge * 2;  // 16-bit

/// 3 channels x 6 time points; block (c, t) holds 100 c + t; channel 1 hidden.
osg::ref_ptr<VolumeNode> seriesNode()
{
    osg::ref_ptr<Volume> v = new Volume;
    v->allocate(VoxelType::UInt16, {edge, edge, edge}, 3, timePoints);
    for (int t = 0; t < timePoints; ++t)
        for (int c = 0; c < 3; ++c) {
            auto* voxels = reinterpret_cast<std::uint16_t*>(v->block(c, t));
            std::fill(voxels, voxels + edge * edge * edge, std::uint16_t(100 * c + t));
        }
    v->dirty();
    osg::ref_ptr<VolumeNode> node = new VolumeNode;
    node->setVolume(v.get());
    node->setTransferFunction(colourWindowTransferFunction({1, 1, 1}, 0, 300).get());
    node->channels.resize(3);
    node->channels[1].visible = false;
    return node;
}

TEST(TimePrefetcher, StepsTakeThePrefetchedBlocksAndTheCopiesStayWithinTheBudget)
{
    osg::ref_ptr<VolumeNode> node = seriesNode();
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(node.get());
    (void)node->drawnNodes();  // time point 0 shown: 2 blocks copied
    ASSERT_EQ(node->blockCopies(), 2u);
    // Room for the shown time point of the two shown channels (its blocks count until the cull
    // takes them), two time points ahead, and half of a third.
    const std::size_t budget = 7 * blockBytes;
    TimePrefetcher prefetcher(*root, budget);
    prefetcher.ahead(0);
    prefetcher.wait();
    EXPECT_EQ(prefetcher.heldBytes(), 4 * blockBytes) << "time points 1 and 2, channels 0 and 2";
    TimeSeries series(*root);
    for (int t = 1; t < 2 * timePoints; ++t) {
        // As the viewer steps: the time point set, the prefetcher told, then the next cull.
        series.show(t % timePoints);
        prefetcher.ahead(t % timePoints);
        prefetcher.wait();
        EXPECT_EQ(prefetcher.heldBytes(), 6 * blockBytes) << "the shown one, waiting for the cull, and the next two";
        EXPECT_LE(prefetcher.heldBytes(), budget);
        const std::size_t copies = node->blockCopies(), hits = node->prefetchHits();
        const std::vector<VolumeNode*> drawn = node->drawnNodes();
        ASSERT_EQ(drawn.size(), 2u);
        EXPECT_EQ(drawn[0]->getVolume()->value(0), double(t % timePoints)) << "channel 0 at " << t;
        EXPECT_EQ(drawn[1]->getVolume()->value(0), double(200 + t % timePoints)) << "channel 2 at " << t;
        EXPECT_EQ(node->blockCopies(), copies) << "nothing copied in the step to " << t;
        EXPECT_EQ(node->prefetchHits(), hits + 2);
        EXPECT_EQ(prefetcher.heldBytes(), 4 * blockBytes) << "the cull took the shown ones";
    }
}

TEST(TimePrefetcher, AnEditedVolumeIsCopiedAgainAndASmallBudgetPrefetchesNothing)
{
    osg::ref_ptr<VolumeNode> node = seriesNode();
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(node.get());
    {
        TimePrefetcher tiny(*root, blockBytes);  // not even one time point of two channels
        tiny.ahead(0);
        tiny.wait();
        EXPECT_EQ(tiny.heldBytes(), 0u);
    }
    TimePrefetcher prefetcher(*root, 100 * blockBytes);
    prefetcher.ahead(0);
    prefetcher.wait();
    EXPECT_EQ(prefetcher.heldBytes(), 2 * (timePoints - 1) * blockBytes) << "every other time point";
    reinterpret_cast<std::uint16_t*>(node->getVolume()->block(0, 1))[0] = 7;
    node->getVolume()->dirty();
    node->setTimePoint(1);
    const std::size_t copies = node->blockCopies();
    EXPECT_EQ(node->drawnNodes()[0]->getVolume()->value(0), 7.0) << "the edit, not the stale prefetched block";
    EXPECT_EQ(node->blockCopies(), copies + 2);
}

}  // namespace
}  // namespace volren::test
