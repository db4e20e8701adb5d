#include <volume_model/DefaultScene.h>
#include <volume_model/TimeSeries.h>

#include <algorithm>
#include <stdexcept>

namespace volren {

TimeSeries::TimeSeries(osg::Node& root)
{
    for (VolumeNode* node : findVolumeNodes(root))
        if (Volume* volume = node->getVolume(); volume && volume->frames() > 1) _nodes.push_back(node);
}

int TimeSeries::timePoints() const
{
    int most = 1;
    for (const osg::ref_ptr<VolumeNode>& node : _nodes) most = std::max(most, node->getVolume()->frames());
    return most;
}

void TimeSeries::show(int t)
{
    if (t < 0 || t >= timePoints())
        throw std::out_of_range("time point " + std::to_string(t) + " does not exist (the scene has " +
                                std::to_string(timePoints()) + ", counted from 0)");
    for (const osg::ref_ptr<VolumeNode>& node : _nodes) node->setTimePoint(t);  // each within its own
}

}  // namespace volren
