// Time series (VolumeNode::setTimePoint, `--set time=K`): the node keeps its whole volume and
// draws the blocks of the time point it shows, against closed forms.
#include "RenderFixture.h"
#include "TestData.h"

#include <volume_model/ChannelDisplay.h>
#include <volume_model/TimeSeries.h>
#include <volume_renderer/SceneSettings.h>

#include <cmath>
#include <cstring>

namespace volren::test {
namespace {

class TimeSeriesRender : public RenderFixture
{
protected:
    static constexpr int n = 16;          ///< voxels per axis (spacing 1), centred at the origin
    static constexpr double alpha = 0.1;  ///< TF opacity per voxel where the medium is

    /// 3 time points x `channels` channels: at time point t, channel c fills the slab
    /// 4 (t + c) <= x < 4 (t + c) + 4 (value 200), elsewhere 0.
    static osg::ref_ptr<Volume> movingSlabs(int channels)
    {
        osg::ref_ptr<Volume> v = new Volume;
        v->allocate(VoxelType::UInt8, {n, n, n}, channels, 3);
        for (int t = 0; t < 3; ++t)
            for (int c = 0; c < channels; ++c) {
                std::uint8_t* voxels = v->block(c, t);
                for (int i = 0; i < n * n * n; ++i) voxels[i] = (i % n) / 4 == t + c ? 200 : 0;
            }
        v->dirty();
        return v;
    }
    /// Pixels (two per voxel along x, from -8 to 8) over the slab starting at voxel 4 k: its middle.
    static void expectSlab(const Pixels& img, int k, const osg::Vec3& colour, const std::string& what)
    {
        const double a = 1.0 - std::pow(1.0 - alpha, n);
        for (int x = 0; x < 32; ++x) {
            const int voxel = x / 2;
            if (voxel % 4 == 0 || voxel % 4 == 3) continue;  // next to a slab's faces: interpolated
            const bool inside = voxel / 4 == k;
            for (int y = 4; y < 28; ++y) {
                ASSERT_NEAR(img.at(x, y).a(), inside ? a : 0.0, 2e-3) << what << " pixel " << x << "," << y;
                for (int c = 0; c < 3; ++c) ASSERT_NEAR(img.at(x, y)[c], inside ? colour[c] * a : 0.0, 2e-3) << what;
            }
        }
    }
};

TEST_F(TimeSeriesRender, EachTimePointShowsItsOwnVoxelsAndOnlyItsBlockIsDrawn)
{
    osg::ref_ptr<Volume> series = movingSlabs(1);
    osg::ref_ptr<VolumeNode> node = volumeNode(series.get(), colourWindowTransferFunction({1, 0.5f, 0.25f}, 0, 100, alpha).get());
    node->settings.earlyTerminationThreshold = 1.0;
    osg::ref_ptr<VolumeScene> scene = new VolumeScene;
    scene->addChild(node.get());
    for (int t : {0, 1, 2, 1}) {
        applySetting(*scene, "time", std::to_string(t));  // as `--set time=K`
        EXPECT_EQ(node->getVolume(), series.get()) << "the node keeps the whole series";
        const Pixels img = renderOrthoFromPlusZ(scene.get(), 32, 32, 16.0);
        expectSlab(img, t, {1, 0.5f, 0.25f}, "time point " + std::to_string(t));
        // What is drawn (and uploaded: the first block of the drawn volume) is that time point's block.
        const std::vector<VolumeNode*> drawn = node->drawnNodes();
        ASSERT_EQ(drawn.size(), 1u);
        EXPECT_EQ(std::memcmp(drawn[0]->getVolume()->data(), series->block(0, t), std::size_t(n * n * n)), 0);
        if (t > 0) {
            EXPECT_EQ(drawn[0]->getVolume()->totalVoxelCount(), std::size_t(n * n * n)) << "a copy of one block";
        }
    }
    try {
        applySetting(*scene, "time", "3");
        ADD_FAILURE() << "time point 3 of 3 was accepted";
    } catch (const SettingError& e) {
        EXPECT_NE(std::string(e.what()).find("time point 3 does not exist (the scene has 3, counted from 0)"), std::string::npos)
            << e.what();
    }
}

TEST_F(TimeSeriesRender, AChannelOfATimePointIsThatBlock)
{
    // Two channels and three time points: at time point 1 channel 0 fills slab 1 and channel 1
    // slab 2; channel 1 alone shows slab 2 in its colour.
    osg::ref_ptr<Volume> series = movingSlabs(2);
    osg::ref_ptr<VolumeNode> node = volumeNode(series.get(), colourWindowTransferFunction({1, 1, 1}, 0, 100, alpha).get());
    node->settings.earlyTerminationThreshold = 1.0;
    for (int c = 0; c < 2; ++c) node->channels.push_back({true, colourWindowTransferFunction(channelColour(c), 0, 100, alpha)});
    osg::ref_ptr<VolumeScene> scene = new VolumeScene;
    scene->addChild(node.get());
    // Stepping through time copies (and so uploads) the shown channels of each new time point once.
    for (int t : {0, 1, 2}) {
        const std::size_t before = node->blockCopies();
        TimeSeries(*scene).show(t);
        renderOrthoFromPlusZ(scene.get(), 8, 8, 16.0);
        renderOrthoFromPlusZ(scene.get(), 8, 8, 16.0);  // a second frame of the same time point copies nothing
        EXPECT_EQ(node->blockCopies() - before, 2u) << "time point " << t;
    }
    TimeSeries(*scene).show(1);
    applySetting(*scene, "channels", "1");
    expectSlab(renderOrthoFromPlusZ(scene.get(), 32, 32, 16.0), 2, channelColour(1), "channel 1 at time point 1");
    applySetting(*scene, "channels", "0");
    expectSlab(renderOrthoFromPlusZ(scene.get(), 32, 32, 16.0), 1, channelColour(0), "channel 0 at time point 1");
}

}  // namespace
}  // namespace volren::test
