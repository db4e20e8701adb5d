#include <volume_renderer/SampleDistance.h>

#include <volume_model/VolumeNode.h>

#include <osg/Notify>

namespace volren {

double effectiveSampleDistance(const VolumeNode& node)
{
    const Volume& volume = *node.getVolume();
    const RenderSettings& s = node.settings;
    double step = s.sampleDistance > 0.0 ? s.sampleDistance : s.sampleDistanceFactor * volume.minSpacing();
    const double diagonal = volume.worldSize().length();
    if (!(step > 0.0) || diagonal / step > maxStepsPerRay) {
        const double coarser = diagonal / maxStepsPerRay;
        OSG_WARN << "volren: sample distance " << step << " would take more than " << maxStepsPerRay
                 << " samples per ray; using " << coarser << std::endl;
        step = coarser;
    }
    return step;
}

}  // namespace volren
