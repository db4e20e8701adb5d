#include "ZarrJson.h"

#include <volume_model/OmeZarrAttributes.h>

#include <osg/Notify>

#include <cmath>
#include <set>

namespace volren {

namespace {

using zarrjson::Json;
using zarrjson::shortText;

std::string inferredType(const std::string& name)
{
    if (name == "x" || name == "y" || name == "z") return "space";
    if (name == "t") return "time";
    if (name == "c") return "channel";
    return "";
}

/// Ranks of the axis types in the order OME-Zarr 0.4 requires: time, channel or custom, space.
int typeRank(const std::string& type)
{
    if (type == "time") return 0;
    if (type == "space") return 2;
    return 1;
}

std::vector<OmeZarrAxis> parseAxes(const Json& list, const std::string& name)
{
    if (!list.is_array()) throw std::runtime_error(name + ": multiscales axes is " + shortText(list) + ", not a list");
    if (list.size() < 2 || list.size() > 5)
        throw std::runtime_error(name + ": multiscales has " + std::to_string(list.size()) + " axes (OME-Zarr allows 2 to 5)");
    std::vector<OmeZarrAxis> axes;
    std::set<std::string> names;
    int spaces = 0, times = 0, others = 0, lastRank = -1;
    for (const Json& a : list) {
        OmeZarrAxis axis;
        if (a.is_string()) {  // OME-Zarr 0.3: axes are names
            axis.name = a.get<std::string>();
            axis.type = inferredType(axis.name);
        } else if (a.is_object() && a.contains("name") && a["name"].is_string()) {
            axis.name = a["name"].get<std::string>();
            if (a.contains("type") && !a["type"].is_null()) {
                if (!a["type"].is_string()) throw std::runtime_error(name + ": axis \"" + axis.name + "\" type is " + shortText(a["type"]) + ", not a string");
                axis.type = a["type"].get<std::string>();
            } else {
                axis.type = inferredType(axis.name);
            }
            if (a.contains("unit") && !a["unit"].is_null()) {
                if (!a["unit"].is_string()) throw std::runtime_error(name + ": axis \"" + axis.name + "\" unit is " + shortText(a["unit"]) + ", not a string");
                axis.unit = a["unit"].get<std::string>();
            }
        } else {
            throw std::runtime_error(name + ": axis " + shortText(a) + " is not an object with a \"name\"");
        }
        if (!names.insert(axis.name).second) throw std::runtime_error(name + ": axis name \"" + axis.name + "\" appears twice");
        const int rank = typeRank(axis.type);
        if (rank < lastRank)
            throw std::runtime_error(name + ": axis \"" + axis.name + "\" (" + (axis.type.empty() ? "custom" : axis.type) +
                                     ") is out of order (OME-Zarr orders time, then channel, then space axes)");
        lastRank = rank;
        (rank == 0 ? times : rank == 2 ? spaces : others) += 1;
        axes.push_back(axis);
    }
    if (spaces < 2 || spaces > 3)
        throw std::runtime_error(name + ": " + std::to_string(spaces) + " space axes (OME-Zarr images have 2 or 3)");
    if (times > 1) throw std::runtime_error(name + ": " + std::to_string(times) + " time axes (at most 1)");
    if (others > 1) throw std::runtime_error(name + ": " + std::to_string(others) + " channel or custom axes (at most 1)");
    return axes;
}

std::vector<double> numberList(const Json& list, std::size_t count, const std::string& what, const std::string& name)
{
    if (!list.is_array()) throw std::runtime_error(name + ": " + what + " is " + shortText(list) + ", not a list");
    if (list.size() != count)
        throw std::runtime_error(name + ": " + what + " has " + std::to_string(list.size()) + " values for " + std::to_string(count) + " axes");
    std::vector<double> values;
    for (const Json& v : list) {
        if (!v.is_number() || !std::isfinite(v.get<double>()))
            throw std::runtime_error(name + ": " + what + " holds " + shortText(v) + ", not a finite number");
        values.push_back(v.get<double>());
    }
    return values;
}

/// Applies a coordinateTransformations list (scale, then optional translation) to `level`.
void applyTransforms(const Json& list, OmeZarrLevel& level, std::size_t axes, const std::string& what, const std::string& name)
{
    if (!list.is_array()) throw std::runtime_error(name + ": " + what + " coordinateTransformations is " + shortText(list) + ", not a list");
    std::vector<double> scale(axes, 1.0), translation(axes, 0.0);
    bool scaled = false, translated = false;
    for (const Json& t : list) {
        const Json type = t.is_object() && t.contains("type") ? t["type"] : Json();
        if (type == "scale" && !scaled && !translated) {
            if (!t.contains("scale")) throw std::runtime_error(name + ": " + what + " scale transformation has no \"scale\" list (a \"path\" is not supported)");
            scale = numberList(t["scale"], axes, what + " scale", name);
            for (double s : scale)
                if (!(s > 0.0)) throw std::runtime_error(name + ": " + what + " scale holds " + std::to_string(s) + ", not a positive number");
            scaled = true;
        } else if (type == "translation" && scaled && !translated) {
            if (!t.contains("translation")) throw std::runtime_error(name + ": " + what + " translation transformation has no \"translation\" list");
            translation = numberList(t["translation"], axes, what + " translation", name);
            translated = true;
        } else if (type == "identity") {
        } else {
            throw std::runtime_error(name + ": " + what + " coordinate transformation " + shortText(t) +
                                     " is not supported (OME-Zarr 0.4: one scale, then at most one translation)");
        }
    }
    if (!scaled && !list.empty()) throw std::runtime_error(name + ": " + what + " coordinateTransformations has no scale");
    // x' = s * x + t applied after the level's own: scale multiplies, translation scales and adds.
    for (std::size_t i = 0; i < axes; ++i) {
        level.translation[i] = level.translation[i] * scale[i] + translation[i];
        level.scale[i] *= scale[i];
    }
}

void checkPath(const std::string& path, const std::string& name)
{
    if (path.empty() || path.front() == '/' || path.find("..") != std::string::npos || path.find('\\') != std::string::npos)
        throw std::runtime_error(name + ": dataset path \"" + path + "\" is not a folder inside the image");
}

float hexComponent(const std::string& hex, std::size_t at)
{
    return float(std::stoi(hex.substr(at, 2), nullptr, 16)) / 255.f;
}

std::vector<OmeroChannel> parseOmero(const Json& omero, const std::string& name)
{
    std::vector<OmeroChannel> channels;
    if (!omero.is_object()) throw std::runtime_error(name + ": omero is " + shortText(omero) + ", not an object");
    if (!omero.contains("channels")) return channels;
    const Json& list = omero["channels"];
    if (!list.is_array()) throw std::runtime_error(name + ": omero channels is " + shortText(list) + ", not a list");
    for (std::size_t i = 0; i < list.size(); ++i) {
        const Json& c = list[i];
        const std::string what = "omero channel " + std::to_string(i);
        if (!c.is_object()) throw std::runtime_error(name + ": " + what + " is " + shortText(c) + ", not an object");
        OmeroChannel ch;
        if (c.contains("label") && c["label"].is_string()) ch.label = c["label"].get<std::string>();
        if (c.contains("active") && c["active"].is_boolean()) ch.active = c["active"].get<bool>();
        if (c.contains("color") && !c["color"].is_null()) {
            const Json& color = c["color"];
            const std::string hex = color.is_string() ? color.get<std::string>() : std::string();
            if (hex.size() != 6 || hex.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
                throw std::runtime_error(name + ": " + what + " color " + shortText(color) + " is not RRGGBB hex");
            ch.color = hex;
            ch.red = hexComponent(hex, 0);
            ch.green = hexComponent(hex, 2);
            ch.blue = hexComponent(hex, 4);
        }
        if (c.contains("window") && !c["window"].is_null()) {
            const Json& w = c["window"];
            if (!w.is_object()) throw std::runtime_error(name + ": " + what + " window is " + shortText(w) + ", not an object");
            const auto number = [&](const char* key, double fallback) {
                if (!w.contains(key)) return fallback;
                if (!w[key].is_number() || !std::isfinite(w[key].get<double>()))
                    throw std::runtime_error(name + ": " + what + " window " + key + " is " + shortText(w[key]) + ", not a finite number");
                return w[key].get<double>();
            };
            ch.windowMin = number("min", 0.0);
            ch.windowMax = number("max", 0.0);
            ch.windowStart = number("start", ch.windowMin);
            ch.windowEnd = number("end", ch.windowMax);
            ch.hasWindow = true;
        }
        channels.push_back(ch);
    }
    return channels;
}

}  // namespace

int OmeZarrAttributes::axisOfType(const std::string& type) const
{
    for (std::size_t i = 0; i < axes.size(); ++i)
        if (axes[i].type == type) return int(i);
    return -1;
}

int OmeZarrAttributes::channelAxis() const
{
    for (std::size_t i = 0; i < axes.size(); ++i)
        if (axes[i].type != "time" && axes[i].type != "space") return int(i);
    return -1;
}

OmeZarrAttributes parseOmeZarrAttributes(const std::string& text, const std::string& name)
{
    const Json j = zarrjson::parse(text, name);
    if (!j.is_object()) throw std::runtime_error(name + ": not a JSON object");
    if (!j.contains("multiscales")) throw std::runtime_error(name + ": no \"multiscales\" (not an OME-Zarr image)");
    const Json& list = j["multiscales"];
    if (!list.is_array() || list.empty()) throw std::runtime_error(name + ": multiscales is " + shortText(list) + ", not a list of images");
    if (list.size() > 1) OSG_INFO << name << ": " << list.size() << " multiscales entries; volren reads the first" << std::endl;
    const Json& m = list.front();
    if (!m.is_object()) throw std::runtime_error(name + ": multiscales entry is " + shortText(m) + ", not an object");

    OmeZarrAttributes a;
    a.version = "0.4";
    if (m.contains("version") && !m["version"].is_null()) {
        if (!m["version"].is_string()) throw std::runtime_error(name + ": multiscales version is " + shortText(m["version"]) + ", not a string");
        a.version = m["version"].get<std::string>();
    }
    const bool older = a.version == "0.1" || a.version == "0.2" || a.version == "0.3";
    if (!older && a.version != "0.4")
        throw std::runtime_error(name + ": OME-Zarr version " + a.version + " is not supported (volren reads 0.4, zarr v2)");
    if (m.contains("name") && m["name"].is_string()) a.name = m["name"].get<std::string>();
    if (m.contains("axes")) a.axes = parseAxes(m["axes"], name);
    else if (older) a.axes = parseAxes(Json{"t", "c", "z", "y", "x"}, name);  // 0.1/0.2: always 5-D tczyx
    else throw std::runtime_error(name + ": multiscales has no axes");

    if (!m.contains("datasets") || !m["datasets"].is_array() || m["datasets"].empty())
        throw std::runtime_error(name + ": multiscales has no datasets (resolution levels)");
    const std::size_t n = a.axes.size();
    std::set<std::string> paths;
    for (std::size_t i = 0; i < m["datasets"].size(); ++i) {
        const Json& d = m["datasets"][i];
        const std::string what = "dataset " + std::to_string(i);
        if (!d.is_object() || !d.contains("path") || !d["path"].is_string())
            throw std::runtime_error(name + ": " + what + " has no \"path\" string");
        OmeZarrLevel level;
        level.path = d["path"].get<std::string>();
        checkPath(level.path, name);
        if (!paths.insert(level.path).second) throw std::runtime_error(name + ": dataset path \"" + level.path + "\" appears twice");
        level.scale.assign(n, 1.0);
        level.translation.assign(n, 0.0);
        if (d.contains("coordinateTransformations")) {
            applyTransforms(d["coordinateTransformations"], level, n, what, name);
        } else if (older) {
            for (std::size_t k = 0; k < n; ++k)
                if (a.axes[k].type == "space") level.scale[k] = std::ldexp(1.0, int(i));
        } else {
            throw std::runtime_error(name + ": " + what + " has no coordinateTransformations (OME-Zarr 0.4 requires a scale)");
        }
        a.levels.push_back(level);
    }
    if (m.contains("coordinateTransformations"))
        for (OmeZarrLevel& level : a.levels) applyTransforms(m["coordinateTransformations"], level, n, "multiscales", name);
    if (j.contains("omero")) a.channels = parseOmero(j["omero"], name);
    if (j.contains("volren") && j["volren"].is_object() && j["volren"].contains("rescale")) {
        const std::vector<double> r = numberList(j["volren"]["rescale"], 2, "volren rescale", name);
        if (r[0] == 0.0) throw std::runtime_error(name + ": volren rescale slope is 0");
        a.rescaleSlope = r[0];
        a.rescaleIntercept = r[1];
    }
    return a;
}

}  // namespace volren
