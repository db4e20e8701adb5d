#include <volume_model/ParameterCatalog.h>
#include <volume_model/ParseNumber.h>
#include <volume_model/RenderSettings.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace volren {

namespace {

/// Setting keys that choose an implementation, and the slot each one chooses for.
const std::vector<std::pair<std::string, std::string>>& slotKeys()
{
    static const std::vector<std::pair<std::string, std::string>> keys = {
        {"raysetup", "RaySetup"},         {"clipray", "ClipRay"},
        {"jitter", "Jitter"},             {"traversal", "RayTraversal"},
        {"clipposition", "ClipPosition"}, {"reconstruction", "Reconstruction"},
        {"classification", "Classification"}, {"gradient", "Gradient"},
        {"gradientinput", "GradientInput"}, {"shading", "Shading"},
        {"illumination", "Illumination"}, {"shadowing", "Shadowing"},
        {"acceleration", "Acceleration"}, {"volumestorage", "VolumeStorage"},
        {"weighting", "Weighting"}};
    return keys;
}

/// Every slot has a null implementation: the usual words for "off" name it. Other names (and
/// aliases of implementations) are the renderer's to resolve (volren::applyNodeSetting).
std::string canonicalFunction(const std::string& value)
{
    if (value == "off" || value == "none" || value == "0" || value == "false") return "null";
    return value;
}

bool isIdentifier(const std::string& s)
{
    if (s.empty()) return false;
    for (char c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
    return true;
}

/// Whether every parameter set in `a` has the same value in `b` (set, or by default there).
bool sameParameters(const RenderSettings& a, const RenderSettings& b)
{
    for (const auto& [key, value] : a.parameters) {
        if (auto it = b.parameters.find(key); it != b.parameters.end()) {
            if (!sameValue(it->second, value)) return false;
            continue;
        }
        const ParameterDecl* decl = ParameterCatalog::instance().find(key);
        if (!decl || !sameValue(decl->defaultValue, value)) return false;
    }
    return true;
}

}  // namespace

bool RenderSettings::operator==(const RenderSettings& o) const
{
    auto same = [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); };
    return same(sampleDistanceFactor, o.sampleDistanceFactor) && same(sampleDistance, o.sampleDistance) &&
           same(earlyTerminationThreshold, o.earlyTerminationThreshold) && macrocellSize == o.macrocellSize &&
           lod == o.lod && memoryBudgetMB == o.memoryBudgetMB && brickSize == o.brickSize &&
           lodByDistance == o.lodByDistance && texturePrecision == o.texturePrecision && functions == o.functions &&
           forceNull == o.forceNull && sameParameters(*this, o) && sameParameters(o, *this);
}

template <typename T> T RenderSettings::parameter(const std::string& key) const
{
    const ParameterDecl* decl = ParameterCatalog::instance().find(key);
    if (!decl)
        throw std::logic_error("no implementation declares a parameter '" + key +
                               "' (the renderer's ShaderFunctionRegistry declares them: is it loaded?)");
    auto it = parameters.find(decl->key);
    const ParameterValue& value = it == parameters.end() ? decl->defaultValue : it->second;
    if (const T* v = std::get_if<T>(&value)) return *v;
    throw std::logic_error("parameter '" + key + "' of " + decl->owners() + " is not read as this type");
}

template double RenderSettings::parameter<double>(const std::string&) const;
template int RenderSettings::parameter<int>(const std::string&) const;
template bool RenderSettings::parameter<bool>(const std::string&) const;
template std::string RenderSettings::parameter<std::string>(const std::string&) const;
template WeightCurve RenderSettings::parameter<WeightCurve>(const std::string&) const;

std::string RenderSettings::slotForKey(const std::string& key)
{
    const std::string k = lowerKey(key);
    for (const auto& [name, slot] : slotKeys())
        if (name == k) return slot;
    return {};
}

std::vector<std::pair<std::string, std::string>> RenderSettings::keys()
{
    std::vector<std::pair<std::string, std::string>> out = {
        {"samplerate", "samples per smallest voxel spacing (= 1 / sampleFactor)"},
        {"sampleFactor", "step as a factor of the smallest voxel spacing"},
        {"sampleDistance", "step in world units (0 = use sampleFactor)"},
        {"earlyTermination", "opacity at which front-to-back marching stops (1 = never; default 1 - 1/512)"},
        {"macrocellSize", "edge of the empty-space-skipping macrocells in voxels (1-1024)"},
        {"lod", "level of detail: mip level the volume is sampled from, the step growing as 2^lod (0-16)"},
        {"lodByDistance", "level of detail by distance: the level rises where a pixel covers more than a voxel (on/off)"},
        {"memoryBudgetMB", "GPU memory for one volume's voxels in MiB (0 = auto: half of what the GPU reports, else 2048); larger volumes are bricked"},
        {"brickSize", "edge of the bricks of a bricked volume in voxels (4-512; each stored with a one-voxel border)"},
        {"texturePrecision", "volume texture precision: auto (16bit on drivers that filter 8-bit textures coarsely), native, 16bit"}};
    for (const ParameterDecl& d : ParameterCatalog::instance().all())
        out.push_back({d.key, d.help + " (" + d.range() + (d.emptyMeans.empty() ? "" : "; empty = " + d.emptyMeans) +
                                  "; " + d.owners() + ")"});
    out.push_back({"forceNull", "comma-separated slots forced to their null implementation"});
    for (const auto& [name, slot] : slotKeys()) out.push_back({name, "implementation of slot " + slot});
    return out;
}

std::string RenderSettings::get(const std::string& key) const
{
    const std::string k = lowerKey(key);
    if (const std::string slot = slotForKey(k); !slot.empty()) {
        if (forceNull.count(slot)) return "null (forced)";
        auto it = functions.find(slot);
        return it == functions.end() ? std::string() : it->second;
    }
    if (k == "samplerate") return shortestText(1.0 / sampleDistanceFactor);
    if (k == "samplefactor") return shortestText(sampleDistanceFactor);
    if (k == "sampledistance") return shortestText(sampleDistance);
    if (k == "earlytermination") return shortestText(earlyTerminationThreshold);
    if (k == "macrocellsize") return std::to_string(macrocellSize);
    if (k == "lod") return std::to_string(lod);
    if (k == "memorybudgetmb") return std::to_string(memoryBudgetMB);
    if (k == "bricksize") return std::to_string(brickSize);
    if (k == "lodbydistance") return lodByDistance ? "on" : "off";
    if (k == "textureprecision") return texturePrecision;
    if (k == "forcenull") {
        std::string list;
        for (const auto& s : forceNull) list += (list.empty() ? "" : ",") + s;
        return list;
    }
    if (const ParameterDecl* d = ParameterCatalog::instance().find(k)) {
        auto it = parameters.find(d->key);
        return d->format(it == parameters.end() ? d->defaultValue : it->second);
    }
    return {};
}

bool RenderSettings::set(const std::string& key, const std::string& value, std::string& error)
{
    const std::string k = lowerKey(key);
    if (const std::string slot = slotForKey(k); !slot.empty()) {
        const std::string name = canonicalFunction(lowerKey(value));
        if (!isIdentifier(name)) return error = key + " must name an implementation, got '" + value + "'", false;
        functions[slot] = name;
        return true;
    }
    if (k == "forcenull") {
        std::set<std::string> slots;
        std::stringstream list(value);
        std::string item;
        while (std::getline(list, item, ',')) {
            if (item.empty()) continue;
            bool known = false;
            for (const auto& entry : slotKeys()) known = known || entry.second == item;
            if (!known) return error = "forceNull: unknown slot '" + item + "'", false;
            slots.insert(item);
        }
        forceNull = slots;
        return true;
    }
    if (const ParameterDecl* d = ParameterCatalog::instance().find(k)) {
        ParameterValue v;
        if (!d->parse(value, v, error)) return false;
        parameters[d->key] = v;
        return true;
    }
    struct Numeric
    {
        const char* key;
        double* field;
        double lo, hi;
        bool openLow;
    };
    const Numeric numerics[] = {
        {"samplefactor", &sampleDistanceFactor, 0.0, 1e6, true},
        {"sampledistance", &sampleDistance, 0.0, 1e300, false},
        {"earlytermination", &earlyTerminationThreshold, 0.0, 1.0, true},
    };
    double v = 0.0;
    if (k == "samplerate") {
        if (!parseFiniteNumber(value, v) || !(v > 0.0) || v < 1e-6)
            return error = "samplerate must be a number of samples per voxel > 0, got '" + value + "'", false;
        sampleDistanceFactor = 1.0 / v;
        return true;
    }
    struct Whole
    {
        const char* key;
        int* field;
        int lo, hi;
        const char* unit;
    };
    const Whole wholes[] = {{"macrocellsize", &macrocellSize, 1, 1024, "voxels"},
                            {"lod", &lod, 0, 16, "mip levels"},
                            {"memorybudgetmb", &memoryBudgetMB, 0, 1 << 24, "MiB"},
                            {"bricksize", &brickSize, 4, 512, "voxels"}};
    for (const Whole& w : wholes) {
        if (k != w.key) continue;
        if (!parseFiniteNumber(value, v) || v != std::floor(v) || v < w.lo || v > w.hi)
            return error = key + " must be a whole number of " + w.unit + " in [" + std::to_string(w.lo) + ", " +
                           std::to_string(w.hi) + "], got '" + value + "'",
                   false;
        *w.field = int(v);
        return true;
    }
    if (k == "textureprecision") {
        const std::string p = lowerKey(value);
        if (p != "auto" && p != "native" && p != "16bit")
            return error = "texturePrecision must be auto, native or 16bit, got '" + value + "'", false;
        texturePrecision = p;
        return true;
    }
    if (k == "lodbydistance") {
        const std::string b = lowerKey(value);
        if (b == "on" || b == "true" || b == "1") return lodByDistance = true, true;
        if (b == "off" || b == "false" || b == "0") return lodByDistance = false, true;
        return error = "lodByDistance must be on or off, got '" + value + "'", false;
    }
    for (const Numeric& n : numerics) {
        if (k != n.key) continue;
        const bool ok = parseFiniteNumber(value, v) && (n.openLow ? v > n.lo : v >= n.lo) && v <= n.hi;
        if (!ok) {
            std::ostringstream why;
            why << key << " must be a number in " << (n.openLow ? "(" : "[") << n.lo << ", " << n.hi << "], got '"
                << value << "'";
            error = why.str();
            return false;
        }
        *n.field = v;
        return true;
    }
    std::string known;
    for (const auto& entry : keys()) known += (known.empty() ? "" : ", ") + entry.first;
    error = "unknown setting '" + key + "' (known: " + known + ")";
    return false;
}

}  // namespace volren
