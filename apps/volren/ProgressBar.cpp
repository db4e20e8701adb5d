// Progress of loads and writes longer than half a second on stderr: a redrawn bar on a terminal,
// a start line, tens of percent and an end line in a log.
#include "ProgressBar.h"

#include "Commands.h"

#include <volume_model/ReadVolume.h>

#include <osgDB/FileNameUtils>

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <iomanip>
#include <iostream>

namespace volren::app {

namespace {

/// Seconds a task runs before progress shows (VOLREN_PROGRESS_DELAY overrides 0.5, for tests).
double progressDelay()
{
    const char* text = std::getenv("VOLREN_PROGRESS_DELAY");
    char* end = nullptr;
    const double v = text ? std::strtod(text, &end) : 0.0;
    return text && end != text && v >= 0.0 ? v : 0.5;
}

}  // namespace

ProgressBar::ProgressBar(const std::string& verb, const std::string& name)
    : _start(std::chrono::steady_clock::now()), _label(verb + " " + name), _terminal(isatty(STDERR_FILENO) == 1),
      _delay(progressDelay())
{
    _callback = [this](double fraction) {
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - _start).count();
        const int percent = std::clamp(int(fraction * 100.0), 0, 100);
        if (seconds < _delay || percent == _shown) return true;
        if (_terminal) {  // one line, redrawn
            constexpr int width = 40;
            const int filled = percent * width / 100;
            std::cerr << "\r" << _label << " [" << std::string(std::size_t(filled), '#')
                      << std::string(std::size_t(width - filled), ' ') << "] " << percent << "%" << std::flush;
        } else if (_shown < 0) {  // a log: a start line, then a line per 10 % once it takes seconds
            std::cerr << _label << " ..." << std::endl;
        } else if (seconds >= 3.0 && percent / 10 > _shown / 10) {
            std::cerr << _label << ": " << percent / 10 * 10 << "% (" << std::fixed << std::setprecision(1) << seconds << " s)"
                      << std::defaultfloat << std::endl;
        }
        _shown = percent;
        return true;
    };
}

ProgressBar::~ProgressBar()
{
    if (_shown < 0) return;
    if (_terminal) {
        std::cerr << "\r" << std::string(80, ' ') << "\r" << std::flush;
    } else {
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - _start).count();
        std::cerr << _label << ": done in " << std::fixed << std::setprecision(1) << seconds << " s" << std::defaultfloat
                  << std::endl;
    }
}

osg::ref_ptr<Volume> readVolumeWithProgress(const std::string& path, const std::string& readerOptions)
{
    const ProgressBar bar("loading", osgDB::getSimpleFileName(path));
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options(readerOptions);
    return readVolumeFile(path, withLoadProgress(options.get(), &bar.callback()).get());
}

}  // namespace volren::app
