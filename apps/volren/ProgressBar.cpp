// Reading a volume with a one-line progress bar on stderr for loads longer than half a second.
#include "Commands.h"

#include <volume_model/LoadProgress.h>
#include <volume_model/ReadVolume.h>

#include <osgDB/FileNameUtils>

#include <chrono>
#include <iostream>

namespace volren::app {

osg::ref_ptr<Volume> readVolumeWithProgress(const std::string& path)
{
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    int shown = -1;  // percent last drawn; -1 until the load has taken 0.5 s
    const LoadProgress progress = [&](double fraction) {
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        const int percent = int(fraction * 100.0);
        if (seconds < 0.5 || percent == shown) return true;
        constexpr int width = 40;
        const int filled = percent * width / 100;
        std::cerr << "\rloading " << osgDB::getSimpleFileName(path) << " [" << std::string(std::size_t(filled), '#')
                  << std::string(std::size_t(width - filled), ' ') << "] " << percent << "%" << std::flush;
        shown = percent;
        return true;
    };
    const auto clearLine = [&] {
        if (shown >= 0) std::cerr << "\r" << std::string(80, ' ') << "\r" << std::flush;
    };
    try {
        osg::ref_ptr<Volume> volume = readVolumeFile(path, withLoadProgress(nullptr, &progress).get());
        clearLine();
        return volume;
    } catch (...) {
        clearLine();
        throw;
    }
}

}  // namespace volren::app
