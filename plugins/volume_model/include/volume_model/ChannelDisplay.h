#pragma once
#include <volume_model/TransferFunction.h>
#include <volume_model/Volume.h>

#include <osg/Vec3>

#include <utility>
#include <vector>

namespace volren {

/// How one channel of a multi-channel volume is shown (VolumeNode::channels).
struct ChannelDisplay
{
    bool visible = true;                              ///< drawn at all
    osg::ref_ptr<TransferFunction> transferFunction;  ///< its classification (null: the node's)
    /// Scales the opacity of every control point of its transfer function (each clamped to 1):
    /// how strongly the channel shows against the others (in MIP, how bright it is).
    double opacity = 1.0;
};

/// Channel `c` at time point `t` of `volume` as a volume of its own (a copy of that block, with
/// the spacing, rescale, file name and channel hint kept). Throws std::out_of_range naming the
/// file when the block does not exist, std::runtime_error for a volume opened lazily with more
/// blocks (its source holds one).
osg::ref_ptr<Volume> channelOf(const Volume& volume, int c, int t = 0);

/// A copy of `tf` with every control point's opacity multiplied by `scale` (clamped to [0, 1]).
osg::ref_ptr<TransferFunction> scaledOpacity(const TransferFunction& tf, double scale);

/// The default fluorescence colour of channel `c`: green, magenta, cyan, yellow, red, blue, then
/// the same again.
osg::Vec3 channelColour(int c);

/// The microscopy way to show a channel: `colour` at every value, opacity 0 up to `low` rising
/// linearly to `opacity` at `high` (data values) and staying there above it.
osg::ref_ptr<TransferFunction> colourWindowTransferFunction(const osg::Vec3& colour, double low, double high,
                                                            double opacity = 1.0);

/// A channel through its colour table `colours` (dark to bright, spread evenly over [low, high]),
/// opacity rising linearly from 0 at `low` to `opacity` at `high`; one colour: as
/// colourWindowTransferFunction.
osg::ref_ptr<TransferFunction> colourTableTransferFunction(const std::vector<osg::Vec3f>& colours, double low, double high,
                                                           double opacity = 1.0);

/// The display window of channel `c` of `volume`: the `low` and `high` percentiles (0..100) of
/// its finite values (widened to a non-empty interval when the channel is constant).
std::pair<double, double> channelWindow(const Volume& volume, int c, double low = 0.5, double high = 99.5);

/// The opacity per voxel a default channel display reaches at the top of its window: dense
/// bright structures stay see-through over tens of voxels, as fluorescence stacks want.
constexpr double defaultChannelOpacity = 0.2;

/// Every channel of `volume` as its file shows it (Volume::channelHints: colour table, display
/// range, visibility), the rest by default: colour channelColour(c), window from the channel's
/// background (Otsu's threshold, when above the 0.5th percentile) to its 99.5th percentile (also
/// where the file's range is the whole range of the voxel type, ImageJ's when none was set);
/// opacity reaching defaultChannelOpacity at the window's top: the fluorescence default.
std::vector<ChannelDisplay> defaultChannelDisplays(const Volume& volume);

}  // namespace volren
