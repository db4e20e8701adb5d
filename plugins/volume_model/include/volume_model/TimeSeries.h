#pragma once
#include <volume_model/Volume.h>
#include <volume_model/VolumeNode.h>

#include <osg/Node>

#include <vector>

namespace volren {

/// The time series shown below a scene root: every VolumeNode whose volume has several time
/// points. Each node keeps its whole volume and shows one time point (VolumeNode::setTimePoint;
/// only that time point's blocks reach the GPU).
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
    std::vector<osg::ref_ptr<VolumeNode>> _nodes;
};

}  // namespace volren
