#include "CommandLine.h"
#include "Commands.h"

#include <volume_model/ReadVolume.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>

namespace volren::app {

int infoCommand(const std::vector<std::string>& args)
{
    if (args.size() != 1) throw UsageError("info takes exactly one volume file");
    osg::ref_ptr<Volume> v = readVolumeWithProgress(args[0]);
    const osg::Vec3i& d = v->dims();
    const osg::Vec3d& s = v->spacing();
    const auto [lo, hi] = v->valueRange();
    const Histogram h = v->histogram(256);
    std::cout << std::setprecision(6);
    std::cout << "file:        " << args[0] << "\n"
              << "dims:        " << d.x() << " x " << d.y() << " x " << d.z() << " (" << v->voxelCount() << " voxels)\n"
              << "voxel type:  " << voxelTypeName(v->type()) << "\n"
              << "blocks:      " << v->channels() << (v->channels() == 1 ? " channel" : " channels") << " x "
              << v->frames() << (v->frames() == 1 ? " time point" : " time points")
              << " (statistics over all; rendering shows channel 0, time point 0)\n"
              << "spacing:     " << s.x() << " x " << s.y() << " x " << s.z() << "\n"
              << "world size:  " << v->worldSize().x() << " x " << v->worldSize().y() << " x " << v->worldSize().z() << "\n"
              << "rescale:     value = stored * " << v->rescaleSlope() << " + " << v->rescaleIntercept() << "\n"
              << "value range: " << lo << " .. " << hi << "\n"
              << "non-finite:  " << v->nonFiniteCount() << " voxels\n"
              << "histogram:   p1 " << h.percentile(0.01) << ", p50 " << h.percentile(0.5) << ", p99 "
              << h.percentile(0.99) << ", Otsu threshold " << h.otsuThreshold() << "\n";
    // A 16-column sketch of the 256-bin histogram (log scale), low values on the left.
    static const char* levels = " .:-=+*#%@";
    std::vector<double> coarse(16, 0.0);
    for (std::size_t i = 0; i < h.counts.size(); ++i) coarse[i * 16 / h.counts.size()] += double(h.counts[i]);
    const double top = std::log1p(*std::max_element(coarse.begin(), coarse.end()));
    std::cout << "             [";
    for (double c : coarse) std::cout << levels[top > 0 ? int(std::log1p(c) / top * 9.0 + 0.5) : 0];
    std::cout << "]\n";
    return 0;
}

}  // namespace volren::app
