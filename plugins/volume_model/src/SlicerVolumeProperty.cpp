#include <volume_model/ParseNumber.h>
#include <volume_model/SlicerVolumeProperty.h>
#include "PiecewiseLinear.h"

#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

namespace volren {

namespace {

/// The line that holds each field, with its name for messages.
enum Line
{
    Interpolation = 1,
    Shade,
    Diffuse,
    Ambient,
    Specular,
    SpecularPower,
    ScalarOpacity,
    GradientOpacity,
    Colour,
    LineCount = Colour
};

const char* const lineNames[] = {"",
                                 "interpolation type",
                                 "shade flag",
                                 "diffuse reflection",
                                 "ambient reflection",
                                 "specular reflection",
                                 "specular power",
                                 "scalar opacity function",
                                 "gradient opacity function",
                                 "colour transfer function"};

class Parser
{
public:
    explicit Parser(const std::string& path) : _path(path) {}

    [[noreturn]] void fail(int line, const std::string& why) const
    {
        throw std::runtime_error(_path + ":" + std::to_string(line) + ": " + why);
    }

    /// The words of `text`.
    static std::vector<std::string> words(const std::string& text)
    {
        std::istringstream in(text);
        return {std::istream_iterator<std::string>(in), std::istream_iterator<std::string>()};
    }

    double number(int line, const std::string& word, const std::string& what) const
    {
        double v = 0.0;
        if (!parseFiniteNumber(word, v)) fail(line, what + ": '" + word + "' is not a finite number");
        return v;
    }

    /// A line of one number.
    double single(int line, const std::string& text) const
    {
        const std::vector<std::string> w = words(text);
        if (w.size() != 1)
            fail(line, std::string("expected one number (the ") + lineNames[line] + "), found " +
                           std::to_string(w.size()) + " words");
        return number(line, w[0], lineNames[line]);
    }

    int integer(int line, const std::string& text) const
    {
        const double v = single(line, text);
        if (v != std::floor(v) || std::fabs(v) > 1e9) fail(line, std::string("the ") + lineNames[line] + " must be an integer");
        return int(v);
    }

    /// A function line "N v1 v2 ... vN" of points of `stride` numbers; positions non-decreasing,
    /// repeated ones moved up to the next double (Slicer's rule); every other number in [0,1].
    std::vector<std::vector<double>> function(int line, const std::string& text, std::size_t stride) const
    {
        const std::string name = lineNames[line];
        const std::vector<std::string> w = words(text);
        if (w.empty()) fail(line, "expected the " + name + " (N, then N numbers)");
        const double n = number(line, w[0], name + " count");
        if (n < 0 || n != std::floor(n) || n > 1e9) fail(line, name + ": count " + w[0] + " is not a whole number");
        const std::size_t count = std::size_t(n);
        if (count % stride != 0)
            fail(line, name + ": count " + std::to_string(count) + " is not a multiple of " + std::to_string(stride) +
                           " (numbers per point)");
        if (w.size() - 1 != count)
            fail(line, name + ": count says " + std::to_string(count) + " numbers, the line has " +
                           std::to_string(w.size() - 1));
        std::vector<std::vector<double>> points;
        double previous = -std::numeric_limits<double>::infinity();
        for (std::size_t i = 1; i < w.size(); i += stride) {
            std::vector<double> p;
            for (std::size_t c = 0; c < stride; ++c) p.push_back(number(line, w[i + c], name));
            for (std::size_t c = 1; c < stride; ++c)
                if (p[c] < 0.0 || p[c] > 1.0)
                    fail(line, name + ": " + w[i + c] + " at " + w[i] + " is outside [0,1]");
            if (p[0] < previous)
                fail(line, name + ": positions must not decrease (" + w[i] + " after " + std::to_string(previous) + ")");
            if (p[0] == previous)  // a step: Slicer moves the later point up by the least amount
                p[0] = previous == 0.0 ? std::numeric_limits<double>::min()
                                       : std::nextafter(previous, std::numeric_limits<double>::infinity());
            previous = p[0];
            points.push_back(std::move(p));
        }
        return points;
    }

private:
    std::string _path;
};
}  // namespace

bool SlicerVolumeProperty::hasGradientOpacity() const
{
    for (const auto& point : gradientOpacity)
        if (point.second != 1.0) return true;
    return false;
}

osg::ref_ptr<TransferFunction> SlicerVolumeProperty::transferFunction() const
{
    if (scalarOpacity.empty() || colour.empty()) throw std::invalid_argument("SlicerVolumeProperty without opacity or colour points");
    std::map<double, double> channel[4];
    for (const auto& [x, rgb] : colour)
        for (int c = 0; c < 3; ++c) channel[c][x] = rgb[c];
    for (const auto& [x, a] : scalarOpacity) channel[3][x] = a;
    return transferFunctionFromCurves(channel);
}

SlicerVolumeProperty readSlicerVolumeProperty(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open Slicer volume property file");
    std::vector<std::string> lines;
    std::string text;
    while (std::getline(in, text)) {
        if (!text.empty() && text.back() == '\r') text.pop_back();  // written on Windows
        lines.push_back(text);
    }
    if (in.bad()) throw std::runtime_error(path + ": read error");
    const Parser parse(path);
    auto blank = [](const std::string& s) { return s.find_first_not_of(" \t\r\f\v") == std::string::npos; };
    bool empty = true;
    for (const std::string& s : lines) empty = empty && blank(s);
    if (empty) throw std::runtime_error(path + ": empty file (expected the 9 lines of a Slicer volume property)");
    if (lines.size() < LineCount)
        parse.fail(int(lines.size()), "the file ends after line " + std::to_string(lines.size()) + "; a Slicer volume property has " +
                                          std::to_string(int(LineCount)) + " lines (the " + lineNames[lines.size() + 1] +
                                          " is missing)");
    for (std::size_t i = LineCount; i < lines.size(); ++i)
        if (!blank(lines[i]))
            parse.fail(int(i + 1), "unexpected text after the " + std::to_string(int(LineCount)) +
                                       " lines of a Slicer volume property");

    SlicerVolumeProperty vp;
    auto line = [&](Line l) -> const std::string& { return lines[l - 1]; };
    if (!blank(line(Interpolation))) vp.interpolationType = parse.integer(Interpolation, line(Interpolation));
    if (!blank(line(Shade))) {
        const int shade = parse.integer(Shade, line(Shade));
        if (shade != 0 && shade != 1) parse.fail(Shade, "the shade flag must be 0 or 1");
        vp.shade = shade == 1;
    }
    if (!blank(line(Diffuse))) vp.diffuse = parse.single(Diffuse, line(Diffuse));
    if (!blank(line(Ambient))) vp.ambient = parse.single(Ambient, line(Ambient));
    if (!blank(line(Specular))) vp.specular = parse.single(Specular, line(Specular));
    if (!blank(line(SpecularPower))) vp.specularPower = parse.single(SpecularPower, line(SpecularPower));
    for (const auto& p : parse.function(ScalarOpacity, line(ScalarOpacity), 2)) vp.scalarOpacity.emplace_back(p[0], p[1]);
    if (!blank(line(GradientOpacity)))
        for (const auto& p : parse.function(GradientOpacity, line(GradientOpacity), 2))
            vp.gradientOpacity.emplace_back(p[0], p[1]);
    for (const auto& p : parse.function(Colour, line(Colour), 4)) vp.colour.emplace_back(p[0], osg::Vec3d(p[1], p[2], p[3]));
    if (vp.scalarOpacity.empty()) parse.fail(ScalarOpacity, "the scalar opacity function has no points");
    if (vp.colour.empty()) parse.fail(Colour, "the colour transfer function has no points");
    return vp;
}

}  // namespace volren
