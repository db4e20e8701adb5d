// The channel panel and the time player of the viewer, on their model operations: a channel's
// colour and window rewrite its transfer function exactly (one undo step of that channel's own
// editor, over that channel's histogram), and playback steps time points by the wall clock.
#include <volume_gui/ChannelPanel.h>
#include <volume_gui/TimePlayer.h>

#include <volume_model/ChannelDisplay.h>

#include <osg/Group>

#include <gtest/gtest.h>

namespace volren::test {
namespace {

/// 2 channels x 3 time points of 4^3 voxels: block (c, t) holds 10 * (c + 1) + t everywhere.
osg::ref_ptr<VolumeNode> seriesNode()
{
    osg::ref_ptr<Volume> v = new Volume;
    v->allocate(VoxelType::UInt8, {4, 4, 4}, 2, 3);
    for (int t = 0; t < 3; ++t)
        for (int c = 0; c < 2; ++c) std::fill(v->block(c, t), v->block(c, t) + 64, std::uint8_t(10 * (c + 1) + t));
    v->dirty();
    osg::ref_ptr<VolumeNode> node = new VolumeNode;
    node->setVolume(v.get());
    node->setTransferFunction(colourWindowTransferFunction({1, 1, 1}, 0, 50).get());
    node->channels = {{true, colourWindowTransferFunction({0, 1, 0}, 5, 25, 0.2)}, {true, nullptr}};
    return node;
}

TEST(ChannelPanel, AColourAndWindowRewriteTheChannelsTransferFunctionAsOneUndoStep)
{
    osg::ref_ptr<VolumeNode> node = seriesNode();
    ChannelPanel panel(node.get());
    EXPECT_EQ(panel.channels(), 2);
    const ChannelPanel::ColourWindow read = panel.colourWindow(0);
    EXPECT_EQ(read.colour, osg::Vec3(0, 1, 0));
    EXPECT_DOUBLE_EQ(read.low, 5.0);
    EXPECT_DOUBLE_EQ(read.high, 25.0);
    EXPECT_NEAR(read.opacity, 0.2, 1e-7);

    // Channel 1 has no TF of its own: the edit gives it a copy, the node's stays as it was.
    const TransferFunction::Points nodePoints = node->getTransferFunction()->points();
    panel.setColourWindow(1, {osg::Vec3(1, 0, 1), 12.0, 30.0, 0.5});
    ASSERT_TRUE(node->channels[1].transferFunction);
    EXPECT_EQ(node->getTransferFunction()->points(), nodePoints);
    const TransferFunction& tf = *node->channels[1].transferFunction;
    EXPECT_EQ(tf.points(), colourWindowTransferFunction({1, 0, 1}, 12.0, 30.0, 0.5)->points());
    EXPECT_NEAR(tf.evaluate(21.0).a(), 0.25, 1e-6) << "half way up the window";
    const ChannelPanel::ColourWindow back = panel.colourWindow(1);
    EXPECT_DOUBLE_EQ(back.low, 12.0);
    EXPECT_DOUBLE_EQ(back.high, 30.0);

    // One undo step of channel 1's own editor; channel 0's editor has none.
    panel.select(1);
    ASSERT_TRUE(panel.editor().history().undo());
    EXPECT_EQ(node->channels[1].transferFunction->points(), nodePoints) << "back to the node's copy";
    EXPECT_FALSE(panel.editor().history().canUndo());
    panel.select(0);
    EXPECT_FALSE(panel.editor().history().canUndo());

    EXPECT_THROW(panel.select(2), std::out_of_range);
    const unsigned int edits = node->channels[0].transferFunction->modifiedCount();
    panel.setColourWindow(0, {osg::Vec3(1, 1, 0), 6.0, 20.0, 0.3}, false);  // a drag going on
    panel.setColourWindow(0, {osg::Vec3(1, 1, 0), 7.0, 20.0, 0.3}, true);   // and its end
    EXPECT_GT(node->channels[0].transferFunction->modifiedCount(), edits);
    ASSERT_TRUE(panel.editor().history().undo()) << "one step for the drag";
    EXPECT_FALSE(panel.editor().history().canUndo());
    EXPECT_THROW(panel.setColourWindow(0, {osg::Vec3(1, 1, 1), 30.0, 12.0, 0.5}), std::invalid_argument);
    EXPECT_THROW(panel.setColourWindow(0, {osg::Vec3(1, 1, 1), 1.0, 2.0, 1.5}), std::invalid_argument);
}

TEST(ChannelPanel, EachChannelsEditorShowsThatChannelsHistogram)
{
    osg::ref_ptr<VolumeNode> node = seriesNode();
    ChannelPanel panel(node.get());
    for (int c = 0; c < 2; ++c) {
        panel.select(c);
        const Volume* shown = panel.editor().volume();
        ASSERT_TRUE(shown);
        EXPECT_EQ(shown->valueRange(), std::make_pair(10.0 * (c + 1), 10.0 * (c + 1))) << "channel " << c;
    }
}

TEST(TimePlayer, PlaybackStepsOneTimePointPerPeriodAndWraps)
{
    osg::ref_ptr<VolumeNode> node = seriesNode();
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(node.get());
    TimePlayer player(*root);
    EXPECT_EQ(player.timePoints(), 3);
    EXPECT_EQ(player.current(), 0);
    EXPECT_FALSE(player.advance(10.0)) << "paused";
    player.playing = true;
    player.framesPerSecond = 4.0;  // a step per 0.25 s
    EXPECT_FALSE(player.advance(0.2));
    EXPECT_TRUE(player.advance(0.1));  // 0.3 s in all
    EXPECT_EQ(player.current(), 1);
    EXPECT_EQ(node->shownTimePoint(), 1);
    EXPECT_TRUE(player.advance(0.45));  // 0.05 carried + 0.45 = two periods
    EXPECT_EQ(player.current(), 0) << "wraps after the last";
    player.show(2);
    EXPECT_EQ(node->shownTimePoint(), 2);
    const std::size_t copies = node->blockCopies();
    for (VolumeNode* drawn : node->drawnNodes()) EXPECT_EQ(drawn->getVolume()->value(0), double(10 * (drawn == node->channelNode(0) ? 1 : 2) + 2));
    EXPECT_EQ(node->blockCopies(), copies + 2) << "one copy per shown channel of the new time point";
    EXPECT_THROW(player.show(3), std::out_of_range);
}

}  // namespace
}  // namespace volren::test
