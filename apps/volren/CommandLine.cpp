#include "CommandLine.h"

#include <volume_model/ParseNumber.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace volren::app {

namespace {

double parseNumber(const std::string& text, const std::string& what)
{
    double v = 0.0;
    if (!parseFiniteNumber(text, v)) throw UsageError(what + ": '" + text + "' is not a number");
    return v;
}

int parseInt(const std::string& text, const std::string& what, int lo, int hi)
{
    char* end = nullptr;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || !end || *end != '\0' || v < lo || v > hi)
        throw UsageError(what + ": '" + text + "' must be a whole number in " + std::to_string(lo) + ".." +
                         std::to_string(hi));
    return int(v);
}

}  // namespace

osg::Vec3d parseVec3(const std::string& text, const std::string& what)
{
    std::stringstream in(text);
    std::string part;
    std::vector<double> values;
    while (std::getline(in, part, ',')) values.push_back(parseNumber(part, what));
    if (values.size() != 3) throw UsageError(what + ": expected x,y,z, got '" + text + "'");
    return osg::Vec3d(values[0], values[1], values[2]);
}

std::pair<std::size_t, Placement> parsePlaceOption(const std::string& text)
{
    const std::size_t colon = text.find(':');
    if (colon == std::string::npos) throw UsageError("--place: expected N:tx,ty,tz[:scale][:axis,angle], got '" + text + "'");
    const int n = parseInt(text.substr(0, colon), "--place input number", 1, 100000);
    try {
        return {std::size_t(n - 1), parsePlacement(text.substr(colon + 1))};
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--place ") + e.what());
    }
}

void checkPlacedInput(std::size_t index, std::size_t inputs)
{
    if (index >= inputs)
        throw UsageError("--place " + std::to_string(index + 1) + ": there " + (inputs == 1 ? "is " : "are ") +
                         std::to_string(inputs) + " input" + (inputs == 1 ? "" : "s"));
}

RenderOptions parseRenderOptions(const std::vector<std::string>& args, bool requireOutput)
{
    RenderOptions o;
    auto value = [&](std::size_t& i) -> const std::string& {
        if (i + 1 >= args.size()) throw UsageError(args[i] + " needs a value");
        return args[++i];
    };
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "-o" || a == "--output") o.output = value(i);
        else if (a == "--size") {
            const std::string& s = value(i);
            const std::size_t x = s.find('x');
            if (x == std::string::npos) throw UsageError("--size: expected WxH, got '" + s + "'");
            o.width = parseInt(s.substr(0, x), "--size width", 1, 16384);
            o.height = parseInt(s.substr(x + 1), "--size height", 1, 16384);
            o.sizeGiven = true;
        } else if (a == "--eye") o.eye = parseVec3(value(i), "--eye");
        else if (a == "--center") o.center = parseVec3(value(i), "--center");
        else if (a == "--up") o.up = parseVec3(value(i), "--up");
        else if (a == "--fov") {
            o.fov = parseNumber(value(i), "--fov");
            if (!(*o.fov > 0.0 && *o.fov < 180.0)) throw UsageError("--fov: must be in (0, 180) degrees");
        } else if (a == "--ortho") {
            o.ortho = true;
            if (const std::string& v = value(i); v != "fit") {
                o.orthoHeight = parseNumber(v, "--ortho");
                if (!(*o.orthoHeight > 0.0)) throw UsageError("--ortho: height must be positive (or 'fit')");
            }
        } else if (a == "--place") {
            const auto [n, placement] = parsePlaceOption(value(i));
            o.placements[n] = placement;
        } else if (a == "--time") {
            const std::string& v = value(i);
            if (v == "all") o.everyTime = true;
            else o.time = parseInt(v, "--time", 0, 1000000);
        } else if (a == "--turntable") o.turntable = parseInt(value(i), "--turntable", 1, 100000);
        else if (a == "--axis") {
            const std::string& v = value(i);
            if (v == "x") o.turntableAxis.set(1, 0, 0);
            else if (v == "y") o.turntableAxis.set(0, 1, 0);
            else if (v == "z") o.turntableAxis.set(0, 0, 1);
            else o.turntableAxis = parseVec3(v, "--axis");
            if (o.turntableAxis.length() == 0.0) throw UsageError("--axis: must not be zero");
        } else if (a == "--tf") o.tfFile = value(i);
        else if (a == "--tf-keep-range") o.tfKeepRange = true;
        else if (a == "--background") {
            o.background = parseVec3(value(i), "--background");
            for (int c = 0; c < 3; ++c)
                if (o.background[c] < 0.0 || o.background[c] > 1.0)
                    throw UsageError("--background: components must be in [0,1]");
        } else if (a == "--set") {
            const std::string& kv = value(i);
            const std::size_t eq = kv.find('=');
            if (eq == std::string::npos || eq == 0) throw UsageError("--set: expected KEY=VALUE, got '" + kv + "'");
            o.settings.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
        } else if (a == "--frames") o.frames = parseInt(value(i), "--frames", 1, 100000);
        else if (a == "--samples") o.samples = parseInt(value(i), "--samples", 1, 64);
        else if (a == "--screenshot") o.screenshot = value(i);
        else if (a == "--scale-bar" || a == "--no-scale-bar") o.scaleBar = a == "--scale-bar";
        else if (a == "--axes" || a == "--no-axes") o.axes = a == "--axes";
        else if (a == "--stats") o.statsFile = value(i);
        else if (a == "-O" || a == "--option") o.readerOptions += (o.readerOptions.empty() ? "" : " ") + value(i);
        else if (!a.empty() && a[0] == '-') throw UsageError("unknown option '" + a + "'");
        else o.inputs.push_back(a);
    }
    if (o.fov && o.ortho) throw UsageError("--fov and --ortho exclude each other");
    if (o.everyTime && o.time) throw UsageError("--time: give one time point or 'all'");
    for (const auto& [n, placement] : o.placements) checkPlacedInput(n, o.inputs.size());
    if (requireOutput && o.output.empty()) throw UsageError("missing -o OUT (e.g. -o image.png)");
    return o;
}

}  // namespace volren::app
