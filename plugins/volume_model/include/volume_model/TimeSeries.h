#pragma once
#include <volume_model/Volume.h>
#include <volume_model/VolumeNode.h>

#include <osg/Node>

#include <vector>

namespace volren {

/// Time point `t` (from 0) of `volume` as a volume of its own: every channel of that time
/// point, with the spacing, rescale and file name kept. Throws std::out_of_range naming the
/// file and the count when `t` is not a time point of it.
osg::ref_ptr<Volume> timePointOf(const Volume& volume, int t);

/// The time series shown below a scene root: every VolumeNode whose volume has several time
/// points, kept whole here while the nodes show one time point each (only it reaches the GPU).
class TimeSeries
{
public:
    /// Collects the nodes below `root` whose volumes have more than one time point.
    explicit TimeSeries(osg::Node& root);
    /// Most time points of any collected volume (1 when there is no time series).
    int timePoints() const;
    /// Makes every collected node show time point `t`; a volume with fewer time points shows
    /// its last. Throws std::out_of_range when `t` is not in [0, timePoints()).
    void show(int t);

private:
    struct Series
    {
        osg::ref_ptr<VolumeNode> node;
        osg::ref_ptr<Volume> whole;
    };
    std::vector<Series> _series;
};

}  // namespace volren
