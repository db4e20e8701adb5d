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
    std::string file, readerOptions;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "-O" || args[i] == "--option") {
            if (i + 1 >= args.size()) throw UsageError(args[i] + " needs a value");
            readerOptions += (readerOptions.empty() ? "" : " ") + args[++i];
        } else if (!file.empty() || (!args[i].empty() && args[i][0] == '-')) {
            throw UsageError("info takes one volume file and -O OPTION, got '" + args[i] + "'");
        } else {
            file = args[i];
        }
    }
    if (file.empty()) throw UsageError("info takes exactly one volume file");
    osg::ref_ptr<Volume> v = readVolumeWithProgress(file, readerOptions);
    const osg::Vec3i& d = v->dims();
    const osg::Vec3d& s = v->spacing();
    const auto [lo, hi] = v->valueRange();
    const Histogram h = v->histogram(256);
    std::cout << std::setprecision(6);
    std::cout << "file:        " << file << "\n"
              << "dims:        " << d.x() << " x " << d.y() << " x " << d.z() << " (" << v->voxelCount() << " voxels)\n"
              << "voxel type:  " << voxelTypeName(v->type()) << "\n"
              << "blocks:      " << v->channels() << (v->channels() == 1 ? " channel" : " channels") << " x "
              << v->frames() << (v->frames() == 1 ? " time point" : " time points")
              << (v->channels() > 1 && !v->fullResolution()
                      ? " (statistics over all; rendering shows every channel in its colour, time point 0 or --time)\n"
                      : " (statistics over all; rendering shows channel 0, time point 0 or --time)\n")
              << "spacing:     " << s.x() << " x " << s.y() << " x " << s.z() << "\n"
              << "world size:  " << v->worldSize().x() << " x " << v->worldSize().y() << " x " << v->worldSize().z() << "\n"
              << "rescale:     value = stored * " << v->rescaleSlope() << " + " << v->rescaleIntercept() << "\n"
              << "value range: " << lo << " .. " << hi << "\n"
              << "non-finite:  " << v->nonFiniteCount() << " voxels\n"
              << "histogram:   p1 " << h.percentile(0.01) << ", p50 " << h.percentile(0.5) << ", p99 "
              << h.percentile(0.99) << ", Otsu threshold " << h.otsuThreshold() << "\n";
    if (const BrickSource* lazy = v->fullResolution()) {  // the figures above are of the preview level
        const osg::Vec3i f = lazy->levelDims(0);
        std::cout << "opened lazily: " << f.x() << " x " << f.y() << " x " << f.z() << " voxels in the file, "
                  << lazy->levelCount() << " levels; the figures above are of level " << v->fullResolutionLevel()
                  << " in memory (" << lazy->residentBytes() / 1048576.0 << " MiB held)\n";
    }
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
