#include <volume_model/ParaViewPreset.h>
#include "PiecewiseLinear.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <stdexcept>

namespace volren {

namespace {

using Json = nlohmann::json;

/// The numbers of `preset[key]`, `stride` per point; empty when the key is absent.
std::vector<double> pointList(const Json& preset, const char* key, std::size_t stride, const std::string& where)
{
    if (!preset.contains(key)) return {};
    const Json& list = preset[key];
    if (!list.is_array()) throw std::runtime_error(where + ": \"" + key + "\" is not a list");
    if (list.size() % stride != 0)
        throw std::runtime_error(where + ": \"" + key + "\" has " + std::to_string(list.size()) +
                                 " numbers, not a multiple of " + std::to_string(stride));
    std::vector<double> numbers;
    for (const Json& n : list) {
        if (!n.is_number() || !std::isfinite(n.get<double>()))
            throw std::runtime_error(where + ": \"" + key + "\" holds " + n.dump() + ", not a finite number");
        numbers.push_back(n.get<double>());
    }
    return numbers;
}
}  // namespace

osg::ref_ptr<TransferFunction> readParaViewPreset(const std::string& path, const std::string& name)
{
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open ParaView preset file");
    Json document;
    try {
        document = Json::parse(in);
    } catch (const Json::exception& e) {
        throw std::runtime_error(path + ": not valid JSON: " + e.what());
    }
    const Json* preset = nullptr;
    std::string names;
    auto consider = [&](const Json& candidate) {
        if (!candidate.is_object()) return;
        const std::string candidateName = candidate.value("Name", std::string());
        names += (names.empty() ? "" : ", ") + ("'" + candidateName + "'");
        if (!preset && (name.empty() || candidateName == name)) preset = &candidate;
    };
    if (document.is_array())
        for (const Json& candidate : document) consider(candidate);
    else
        consider(document);
    if (!preset) {
        if (names.empty()) throw std::runtime_error(path + ": no preset objects (expected ParaView's preset JSON)");
        throw std::runtime_error(path + ": no preset named '" + name + "' (presets: " + names + ")");
    }
    const std::string where = path + " preset '" + preset->value("Name", std::string()) + "'";
    if (!preset->contains("RGBPoints")) {
        if (preset->contains("IndexedColors"))
            throw std::runtime_error(where + ": categorical presets (\"IndexedColors\") are not transfer functions");
        throw std::runtime_error(where + ": no \"RGBPoints\"");
    }

    std::map<double, double> channel[4];
    const std::vector<double> rgb = pointList(*preset, "RGBPoints", 4, where);
    if (rgb.empty()) throw std::runtime_error(where + ": \"RGBPoints\" is empty");
    for (std::size_t i = 0; i < rgb.size(); i += 4)
        for (int c = 0; c < 3; ++c) {
            if (rgb[i + 1 + c] < 0.0 || rgb[i + 1 + c] > 1.0)
                throw std::runtime_error(where + ": colour component " + std::to_string(rgb[i + 1 + c]) + " at " +
                                         std::to_string(rgb[i]) + " is outside [0,1]");
            channel[c][rgb[i]] = rgb[i + 1 + c];
        }
    const std::vector<double> opacity = pointList(*preset, "Points", 4, where);
    for (std::size_t i = 0; i < opacity.size(); i += 4) {
        const double x = opacity[i], a = opacity[i + 1], midpoint = opacity[i + 2], sharpness = opacity[i + 3];
        if (a < 0.0 || a > 1.0)
            throw std::runtime_error(where + ": opacity " + std::to_string(a) + " at " + std::to_string(x) + " is outside [0,1]");
        if (midpoint != 0.5 || sharpness != 0.0)
            throw std::runtime_error(where + ": opacity point at " + std::to_string(x) + " has midpoint " +
                                     std::to_string(midpoint) + " and sharpness " + std::to_string(sharpness) +
                                     "; only linear segments (midpoint 0.5, sharpness 0) are supported");
        channel[3][x] = a;
    }
    if (channel[3].empty()) {  // ParaView's starting opacity: a ramp over the colour range
        channel[3][channel[0].begin()->first] = 0.0;
        channel[3][channel[0].rbegin()->first] = 1.0;
    }

    osg::ref_ptr<TransferFunction> tf = transferFunctionFromCurves(channel);
    tf->setName(preset->value("Name", path));
    return tf;
}

}  // namespace volren
