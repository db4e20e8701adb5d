#include <volume_model/ImageJLut.h>
#include <volume_model/ParaViewPreset.h>
#include <volume_model/ParseNumber.h>
#include <volume_model/SlicerVolumeProperty.h>
#include <volume_model/TransferFunctionFile.h>

#include <osg/Notify>
#include <osgDB/FileNameUtils>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace volren {

namespace {

struct RawPoint
{
    double value;
    double rgba[4];
    int line;
};

}  // namespace

bool isParaViewPreset(const std::string& path)
{
    return osgDB::getLowerCaseFileExtension(path.substr(0, path.rfind('#'))) == "json";
}

bool transferFunctionFitsAnyRange(const std::string& path)
{
    return isParaViewPreset(path) || osgDB::getLowerCaseFileExtension(path) == "lut";
}

osg::ref_ptr<TransferFunction> readTransferFunctionFile(const std::string& path)
{
    if (isParaViewPreset(path)) {
        const std::size_t hash = path.rfind('#');
        return readParaViewPreset(path.substr(0, hash), hash == std::string::npos ? std::string() : path.substr(hash + 1));
    }
    const std::string extension = osgDB::getLowerCaseFileExtension(path);
    if (extension == "lut") return readImageJLut(path);
    if (extension != "vp") return readTfFile(path);
    const SlicerVolumeProperty vp = readSlicerVolumeProperty(path);
    if (vp.hasGradientOpacity())
        OSG_NOTICE << path << ": the gradient opacity is ignored (volren classifies by value only)" << std::endl;
    OSG_INFO << path << ": Slicer's interpolation, shading and lighting lines are ignored (volren's render settings apply)"
             << std::endl;
    osg::ref_ptr<TransferFunction> tf = vp.transferFunction();
    tf->setName(path);
    return tf;
}

osg::ref_ptr<TransferFunction> readTfFile(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open transfer-function file");

    double scale = 255.0;
    std::vector<RawPoint> raw;
    std::string line;
    int lineNo = 0;
    auto fail = [&](const std::string& why) { throw std::runtime_error(path + ":" + std::to_string(lineNo) + ": " + why); };
    auto number = [&](std::istringstream& words, const std::string& what) {
        std::string s;
        double v = 0.0;
        if (!(words >> s) || !parseFiniteNumber(s, v)) fail(what + " needs a number");
        return v;
    };
    bool hasDomain = false;
    double domain[2] = {0.0, 1.0};
    unsigned int resolution = 0;
    bool smooth = false;
    while (std::getline(in, line)) {
        ++lineNo;
        std::istringstream words(line);
        std::string first;
        if (!(words >> first)) continue;
        if (first == "#volren") {  // volren's settings, a comment to every other reader
            std::string key;
            words >> key;
            if (key == "domain") {
                domain[0] = number(words, "#volren domain");
                domain[1] = number(words, "#volren domain");
                if (!(domain[0] < domain[1])) fail("#volren domain needs MIN < MAX");
                hasDomain = true;
            } else if (key == "resolution") {
                const double n = number(words, "#volren resolution");
                if (n < 2 || n > 65536 || n != double(unsigned(n))) fail("#volren resolution must be an integer in 2..65536");
                resolution = unsigned(n);
            } else if (key == "interpolation") {
                std::string mode;
                words >> mode;
                if (mode != "linear" && mode != "monotone-cubic")
                    fail("#volren interpolation must be linear or monotone-cubic, got '" + mode + "'");
                smooth = mode == "monotone-cubic";
            } else {
                fail("unknown '#volren " + key + "' (known: domain, resolution, interpolation)");
            }
            continue;
        }
        if (first[0] == '#') continue;
        if (first == "colour-scale" || first == "color-scale") {
            std::string s;
            if (!(words >> s) || !parseFiniteNumber(s, scale) || !(scale > 0.0)) fail("colour-scale needs a positive number");
            continue;
        }
        RawPoint p{0.0, {0, 0, 0, 0}, lineNo};
        if (!parseFiniteNumber(first, p.value)) fail("expected 'value r g b a', '" + first + "' is not a number");
        for (int c = 0; c < 4; ++c) {
            std::string s;
            if (!(words >> s)) fail("expected 'value r g b a', found only " + std::to_string(c + 1) + " numbers");
            if (!parseFiniteNumber(s, p.rgba[c])) fail("component '" + s + "' is not a number");
        }
        raw.push_back(p);  // the rest of the line is a comment
    }
    if (in.bad()) throw std::runtime_error(path + ": read error");
    if (raw.empty()) throw std::runtime_error(path + ": no control points (expected lines 'value r g b a')");

    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    tf->setName(path);
    for (const RawPoint& p : raw) {
        osg::Vec4 rgba;
        for (int c = 0; c < 4; ++c) {
            const double v = p.rgba[c] / scale;
            if (v < 0.0 || v > 1.0) {
                lineNo = p.line;
                fail("component " + std::to_string(p.rgba[c]) + " is outside [0, " + std::to_string(scale) +
                     "] (colour-scale " + std::to_string(scale) + ")");
            }
            rgba[c] = float(v);
        }
        tf->setPoint(p.value, rgba);
    }
    if (hasDomain) tf->setDomain(domain[0], domain[1]);
    if (resolution) tf->setResolution(resolution);
    if (smooth) tf->setInterpolation(TransferFunction::Interpolation::MonotoneCubic);
    return tf;
}

void writeTransferFunctionFile(const TransferFunction& tf, const std::string& path)
{
    // A read-only file stays as it is, even where renaming over it would work (root, or a
    // writable folder): the user made it read-only.
    struct stat existing;
    if (::stat(path.c_str(), &existing) == 0 && !(existing.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)))
        throw std::runtime_error(path + ": file is read-only; not replaced");
    const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
    {
        std::ofstream out(temporary);
        if (!out) throw std::runtime_error(path + ": cannot write (" + temporary + ": " + std::strerror(errno) + ")");
        out << "# volren transfer function (OSG .tf format): value r g b a, alpha = opacity per smallest voxel spacing\n";
        out << std::setprecision(std::numeric_limits<double>::max_digits10);
        if (tf.hasExplicitDomain()) out << "#volren domain " << tf.domainMin() << ' ' << tf.domainMax() << '\n';
        out << "#volren resolution " << tf.resolution() << '\n';
        if (tf.interpolation() == TransferFunction::Interpolation::MonotoneCubic) out << "#volren interpolation monotone-cubic\n";
        out << "colour-scale 1\n";
        for (const auto& [value, c] : tf.points())
            out << value << ' ' << c.r() << ' ' << c.g() << ' ' << c.b() << ' ' << c.a() << '\n';
        out.flush();
        if (!out) {
            std::remove(temporary.c_str());
            throw std::runtime_error(path + ": write error (disk full?); the old file is unchanged");
        }
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        const std::string why = std::strerror(errno);
        std::remove(temporary.c_str());
        throw std::runtime_error(path + ": cannot replace the file (" + why + "); the old file is unchanged");
    }
}

}  // namespace volren
