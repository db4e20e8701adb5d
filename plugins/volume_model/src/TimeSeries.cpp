#include <volume_model/DefaultScene.h>
#include <volume_model/TimeSeries.h>

#include <algorithm>
#include <map>
#include <stdexcept>

namespace volren {

osg::ref_ptr<Volume> timePointOf(const Volume& volume, int t)
{
    const std::string name = volume.sourceFile.empty() ? std::string("volume") : volume.sourceFile;
    if (t < 0 || t >= volume.frames())
        throw std::out_of_range(name + ": time point " + std::to_string(t) + " does not exist (it has " +
                                std::to_string(volume.frames()) + ", counted from 0)");
    if (volume.fullResolution() && volume.frames() > 1)
        throw std::out_of_range(name + ": time points of a volume opened lazily cannot be shown (read it whole)");
    const std::size_t blockBytes = volume.voxelCount() * voxelSize(volume.type());
    const std::uint8_t* first = volume.block(0, t);
    std::vector<std::uint8_t> bytes(first, first + blockBytes * std::size_t(volume.channels()));
    osg::ref_ptr<Volume> one = new Volume;
    one->assign(volume.type(), volume.dims(), std::move(bytes), volume.channels(), 1);
    one->setSpacing(volume.spacing());
    one->setRescale(volume.rescaleSlope(), volume.rescaleIntercept());
    one->sourceFile = volume.sourceFile;
    return one;
}

TimeSeries::TimeSeries(osg::Node& root)
{
    for (VolumeNode* node : findVolumeNodes(root))
        if (Volume* volume = node->getVolume(); volume && volume->frames() > 1) _series.push_back({node, volume});
}

int TimeSeries::timePoints() const
{
    int most = 1;
    for (const Series& s : _series) most = std::max(most, s.whole->frames());
    return most;
}

void TimeSeries::show(int t)
{
    if (t < 0 || t >= timePoints())
        throw std::out_of_range("time point " + std::to_string(t) + " does not exist (the scene has " +
                                std::to_string(timePoints()) + ", counted from 0)");
    std::map<const Volume*, osg::ref_ptr<Volume>> shown;  // nodes sharing a volume share its time point
    for (Series& s : _series) {
        osg::ref_ptr<Volume>& one = shown[s.whole.get()];
        if (!one) one = timePointOf(*s.whole, std::min(t, s.whole->frames() - 1));
        s.node->setVolume(one.get());
    }
}

}  // namespace volren
