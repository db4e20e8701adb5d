#include "CommandLine.h"
#include "Commands.h"

#include <volume_model/ParseNumber.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cstdio>
#include <iostream>
#include <stdexcept>

namespace volren::app {

namespace {

OIIO::ImageBuf readImage(const std::string& path)
{
    OIIO::ImageBuf image(path);
    if (!image.read(0, 0, true, OIIO::TypeDesc::FLOAT))
        throw std::runtime_error(path + ": cannot read image: " + image.geterror());
    return image;
}

}  // namespace

int compareCommand(const std::vector<std::string>& args)
{
    std::vector<std::string> files;
    double threshold = 0.01;
    std::string diffFile;
    for (std::size_t i = 0; i < args.size(); ++i) {
        auto value = [&](const char* what) -> const std::string& {
            if (i + 1 >= args.size()) throw UsageError(std::string(what) + " needs a value");
            return args[++i];
        };
        if (args[i] == "--threshold") {
            const std::string& text = value("--threshold");
            if (!parseFiniteNumber(text, threshold)) throw UsageError("--threshold: '" + text + "' is not a number");
        }
        else if (args[i] == "--diff") diffFile = value("--diff");
        else if (!args[i].empty() && args[i][0] == '-') throw UsageError("compare: unknown option '" + args[i] + "'");
        else files.push_back(args[i]);
    }
    if (files.size() != 2) throw UsageError("compare takes two images: A B");
    if (!(threshold >= 0.0)) throw UsageError("--threshold must be a number >= 0");
    const OIIO::ImageBuf a = readImage(files[0]), b = readImage(files[1]);
    const OIIO::ImageSpec &sa = a.spec(), &sb = b.spec();
    if (sa.width != sb.width || sa.height != sb.height)
        throw std::runtime_error(files[1] + ": " + std::to_string(sb.width) + "x" + std::to_string(sb.height) +
                                 " differs from " + files[0] + ": " + std::to_string(sa.width) + "x" + std::to_string(sa.height));
    // Channels both have: RGB, and alpha when both carry it.
    const int channels = std::min(sa.nchannels, sb.nchannels) >= 4 ? 4 : std::min({3, sa.nchannels, sb.nchannels});
    const OIIO::ROI roi(0, sa.width, 0, sa.height, 0, 1, 0, channels);
    const auto result = OIIO::ImageBufAlgo::compare(a, b, float(threshold), float(threshold), roi);
    if (a.has_error() || b.has_error()) throw std::runtime_error("compare failed: " + a.geterror() + b.geterror());
    const double pixels = double(sa.width) * sa.height;
    std::printf("channels compared: %d (%s)\n", channels, channels == 4 ? "RGBA" : "RGB");
    std::printf("RMSE:           %.6g\n", result.rms_error);
    std::printf("PSNR:           %.2f dB (peak 1)\n", result.PSNR);
    std::printf("max abs error:  %.6g at pixel %d,%d (row 0 at the top)\n", result.maxerror, result.maxx, result.maxy);
    std::printf("mean abs error: %.6g\n", result.meanerror);
    std::printf("pixels over %g: %.3f%% (%llu of %.0f)\n", threshold, 100.0 * double(result.nfail) / pixels,
                static_cast<unsigned long long>(result.nfail), pixels);
    if (!diffFile.empty()) {
        OIIO::ImageBuf diff = OIIO::ImageBufAlgo::absdiff(a, b, roi);
        if (diff.has_error() || !diff.write(diffFile)) throw std::runtime_error(diffFile + ": cannot write the difference image: " + diff.geterror());
        std::printf("difference image: %s (|A - B| per channel)\n", diffFile.c_str());
    }
    return 0;
}

}  // namespace volren::app
