#include <volume_model/ParseNumber.h>
#include <volume_model/TransferFunctionFile.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
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

osg::ref_ptr<TransferFunction> readTransferFunctionFile(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open transfer-function file");

    double scale = 255.0;
    std::vector<RawPoint> raw;
    std::string line;
    int lineNo = 0;
    auto fail = [&](const std::string& why) { throw std::runtime_error(path + ":" + std::to_string(lineNo) + ": " + why); };
    while (std::getline(in, line)) {
        ++lineNo;
        std::istringstream words(line);
        std::string first;
        if (!(words >> first) || first[0] == '#') continue;
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
    return tf;
}

void writeTransferFunctionFile(const TransferFunction& tf, const std::string& path)
{
    std::ofstream out(path);
    if (!out) throw std::runtime_error(path + ": cannot open for writing");
    out << "# volren transfer function: value r g b a (alpha = opacity per smallest voxel spacing)\n";
    out << "colour-scale 1\n";
    out << std::setprecision(std::numeric_limits<double>::max_digits10);
    for (const auto& [value, c] : tf.points())
        out << value << ' ' << c.r() << ' ' << c.g() << ' ' << c.b() << ' ' << c.a() << '\n';
    out.flush();
    if (!out) throw std::runtime_error(path + ": write error");
}

}  // namespace volren
