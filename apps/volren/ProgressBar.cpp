// A one-line progress bar on stderr for loads and writes longer than half a second.
#include "ProgressBar.h"

#include "Commands.h"

#include <volume_model/ReadVolume.h>

#include <osgDB/FileNameUtils>

#include <iostream>

namespace volren::app {

ProgressBar::ProgressBar(const std::string& verb, const std::string& name) : _start(std::chrono::steady_clock::now())
{
    _callback = [this, label = verb + " " + name](double fraction) {
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - _start).count();
        const int percent = int(fraction * 100.0);
        if (seconds < 0.5 || percent == _shown) return true;
        constexpr int width = 40;
        const int filled = percent * width / 100;
        std::cerr << "\r" << label << " [" << std::string(std::size_t(filled), '#') << std::string(std::size_t(width - filled), ' ')
                  << "] " << percent << "%" << std::flush;
        _shown = percent;
        return true;
    };
}

ProgressBar::~ProgressBar()
{
    if (_shown >= 0) std::cerr << "\r" << std::string(80, ' ') << "\r" << std::flush;
}

osg::ref_ptr<Volume> readVolumeWithProgress(const std::string& path, const std::string& readerOptions)
{
    const ProgressBar bar("loading", osgDB::getSimpleFileName(path));
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options(readerOptions);
    return readVolumeFile(path, withLoadProgress(options.get(), &bar.callback()).get());
}

}  // namespace volren::app
