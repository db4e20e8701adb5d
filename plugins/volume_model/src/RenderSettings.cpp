#include <volume_model/ParseNumber.h>
#include <volume_model/RenderSettings.h>

#include <charconv>
#include <cmath>
#include <sstream>

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

std::string lower(std::string s)
{
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

const std::vector<std::string>& debugViewNames()
{
    static const std::vector<std::string> names = {"scalar", "position", "classification", "gradient",
                                                   "normal", "view", "light"};
    return names;
}

/// The shortest text that reads back as `v` (so settings survive a scene file unchanged).
std::string number(double v)
{
    char text[32];
    const auto [end, error] = std::to_chars(text, text + sizeof(text), v);
    return error == std::errc() ? std::string(text, end) : std::string("nan");
}

}  // namespace

bool RenderSettings::operator==(const RenderSettings& o) const
{
    auto same = [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); };
    return same(sampleDistanceFactor, o.sampleDistanceFactor) && same(sampleDistance, o.sampleDistance) &&
           same(earlyTerminationThreshold, o.earlyTerminationThreshold) && same(isoValue, o.isoValue) &&
           same(shadingThreshold, o.shadingThreshold) && same(ambient, o.ambient) && same(specular, o.specular) &&
           same(shininess, o.shininess) && same(roughness, o.roughness) && same(threshold, o.threshold) &&
           debugView == o.debugView && macrocellSize == o.macrocellSize &&
           same(adaptiveTolerance, o.adaptiveTolerance) && adaptiveSteps == o.adaptiveSteps && lod == o.lod &&
           same(shadowStepFactor, o.shadowStepFactor) && same(shadowCutoff, o.shadowCutoff) &&
           same(lightVolumeScale, o.lightVolumeScale) && same(coneAngle, o.coneAngle) && same(coneStart, o.coneStart) &&
           same(coneStepGrowth, o.coneStepGrowth) && same(coneFilterSigma, o.coneFilterSigma) &&
           same(aoDistance, o.aoDistance) &&
           same(anisotropy, o.anisotropy) &&
           memoryBudgetMB == o.memoryBudgetMB && brickSize == o.brickSize && lodByDistance == o.lodByDistance && texturePrecision == o.texturePrecision &&
           weighting == o.weighting && functions == o.functions && forceNull == o.forceNull;
}

std::string RenderSettings::slotForKey(const std::string& key)
{
    const std::string k = lower(key);
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
        {"adaptiveTolerance", "adaptive sampling: largest change of the classified RGBA in a homogeneous macrocell (0-1)"},
        {"adaptiveSteps", "adaptive sampling: most march steps one sample stands for in a homogeneous macrocell (1-64)"},
        {"anisotropy", "Henyey-Greenstein g of illumination=henyey_greenstein (-0.99..0.99; 0 isotropic, > 0 forward)"},
        {"shadowStepFactor", "shadow rays (shadowing=ray): their step as a factor of the view ray's (> 0)"},
        {"shadowCutoff", "shadow rays stop once the light's transmittance falls below this (0 = never; default 1/512)"},
        {"lightVolumeScale", "light volume (shadowing=light_volume): its resolution as a fraction of the volume's per axis (0-1]"},
        {"coneAngle", "cone tracing (shadowing=cone, cone_ao): the shadow cones' aperture in degrees (0-120]"},
        {"coneStart", "cone tracing: where cones start, in voxels from the sample (0-16)"},
        {"coneStepGrowth", "cone tracing: step as a fraction of the cone's diameter (0.05-4)"},
        {"coneFilterSigma", "cone tracing: Gaussian pre-filter of the opacity volume, sigma in voxels (0 = none, up to 4)"},
        {"aoDistance", "ambient occlusion (shadowing=cone_ao): reach of its cones in voxels (0-256]"},
        {"lod", "level of detail: mip level the volume is sampled from, the step growing as 2^lod (0-16)"},
        {"lodByDistance", "level of detail by distance: the level rises where a pixel covers more than a voxel (on/off)"},
        {"memoryBudgetMB", "GPU memory for one volume's voxels in MiB (0 = auto: half of what the GPU reports, else 2048); larger volumes are bricked"},
        {"brickSize", "edge of the bricks of a bricked volume in voxels (4-512; each stored with a one-voxel border)"},
        {"texturePrecision", "volume texture precision: auto (16bit on drivers that filter 8-bit textures coarsely), native, 16bit"},
        {"isoValue", "isosurface data value (empty = the TF's first opaque value)"},
        {"shadingThreshold", "opacity below which lighting_threshold shading leaves samples unlit"},
        {"ambient", "ambient light fraction"},
        {"specular", "specular strength"},
        {"shininess", "Blinn-Phong exponent"},
        {"roughness", "Cook-Torrance roughness (0..1]"},
        {"threshold", "threshold classification level, 0..1 of the value window"},
        {"debugView", "debug shading view: scalar, position, classification, gradient, normal, view, light"},
        {"weightX", "spatial weighting along x: 'u:w,u:w,...' (u in [0,1] of the volume's width, weights in [0,1]) or 'ramp:A'; scales opacity"},
        {"weightY", "spatial weighting along y (as weightX)"},
        {"weightZ", "spatial weighting along z (as weightX; 'ramp:0.05' fades the first and last 5% of the slices)"},
        {"forceNull", "comma-separated slots forced to their null implementation"}};
    for (const auto& [name, slot] : slotKeys()) out.push_back({name, "implementation of slot " + slot});
    return out;
}

std::string RenderSettings::get(const std::string& key) const
{
    const std::string k = lower(key);
    if (const std::string slot = slotForKey(k); !slot.empty()) {
        if (forceNull.count(slot)) return "null (forced)";
        auto it = functions.find(slot);
        return it == functions.end() ? std::string() : it->second;
    }
    if (k == "samplerate") return number(1.0 / sampleDistanceFactor);
    if (k == "samplefactor") return number(sampleDistanceFactor);
    if (k == "sampledistance") return number(sampleDistance);
    if (k == "earlytermination") return number(earlyTerminationThreshold);
    if (k == "macrocellsize") return std::to_string(macrocellSize);
    if (k == "adaptivetolerance") return number(adaptiveTolerance);
    if (k == "adaptivesteps") return std::to_string(adaptiveSteps);
    if (k == "anisotropy") return number(anisotropy);
    if (k == "shadowstepfactor") return number(shadowStepFactor);
    if (k == "shadowcutoff") return number(shadowCutoff);
    if (k == "lightvolumescale") return number(lightVolumeScale);
    if (k == "coneangle") return number(coneAngle);
    if (k == "conestart") return number(coneStart);
    if (k == "conestepgrowth") return number(coneStepGrowth);
    if (k == "conefiltersigma") return number(coneFilterSigma);
    if (k == "aodistance") return number(aoDistance);
    if (k == "lod") return std::to_string(lod);
    if (k == "memorybudgetmb") return std::to_string(memoryBudgetMB);
    if (k == "bricksize") return std::to_string(brickSize);
    if (k == "lodbydistance") return lodByDistance ? "on" : "off";
    if (k == "textureprecision") return texturePrecision;
    if (k == "isovalue") return std::isnan(isoValue) ? std::string() : number(isoValue);
    if (k == "shadingthreshold") return number(shadingThreshold);
    if (k == "ambient") return number(ambient);
    if (k == "specular") return number(specular);
    if (k == "shininess") return number(shininess);
    if (k == "roughness") return number(roughness);
    if (k == "threshold") return number(threshold);
    if (k == "debugview") return debugViewNames()[std::size_t(debugView)];
    if (k == "weightx") return weighting.axes[0].text();
    if (k == "weighty") return weighting.axes[1].text();
    if (k == "weightz") return weighting.axes[2].text();
    if (k == "forcenull") {
        std::string list;
        for (const auto& s : forceNull) list += (list.empty() ? "" : ",") + s;
        return list;
    }
    return {};
}

bool RenderSettings::set(const std::string& key, const std::string& value, std::string& error)
{
    const std::string k = lower(key);
    if (const std::string slot = slotForKey(k); !slot.empty()) {
        const std::string name = canonicalFunction(lower(value));
        if (!isIdentifier(name)) return error = key + " must name an implementation, got '" + value + "'", false;
        functions[slot] = name;
        return true;
    }
    if (k == "weightx" || k == "weighty" || k == "weightz") {
        WeightCurve curve;
        if (!WeightCurve::parse(value, curve, error)) return error = key + ": " + error, false;
        weighting.axes[std::size_t(k[6] - 'x')] = curve;
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
        {"shadingthreshold", &shadingThreshold, 0.0, 1.0, false},
        {"ambient", &ambient, 0.0, 1.0, false},
        {"specular", &specular, 0.0, 10.0, false},
        {"shininess", &shininess, 1.0, 1e4, false},
        {"roughness", &roughness, 0.0, 1.0, true},
        {"threshold", &threshold, 0.0, 1.0, false},
        {"adaptivetolerance", &adaptiveTolerance, 0.0, 1.0, false},
        {"shadowstepfactor", &shadowStepFactor, 0.0, 1e3, true},
        {"anisotropy", &anisotropy, -0.99, 0.99, false},
        {"shadowcutoff", &shadowCutoff, 0.0, 1.0, false},
        {"lightvolumescale", &lightVolumeScale, 0.0, 1.0, true},
        {"coneangle", &coneAngle, 0.0, 120.0, true},
        {"conestart", &coneStart, 0.0, 16.0, false},
        {"conestepgrowth", &coneStepGrowth, 0.05, 4.0, false},
        {"conefiltersigma", &coneFilterSigma, 0.0, 4.0, false},
        {"aodistance", &aoDistance, 0.0, 256.0, true},
    };
    double v = 0.0;
    if (k == "samplerate") {
        if (!parseFiniteNumber(value, v) || !(v > 0.0) || v < 1e-6)
            return error = "samplerate must be a number of samples per voxel > 0, got '" + value + "'", false;
        sampleDistanceFactor = 1.0 / v;
        return true;
    }
    if (k == "debugview") {
        const auto& names = debugViewNames();
        for (std::size_t i = 0; i < names.size(); ++i)
            if (lower(value) == names[i] || value == std::to_string(i)) return debugView = int(i), true;
        return error = "debugView must be one of scalar, position, classification, gradient, normal, view, light; got '" +
                       value + "'",
               false;
    }
    struct Whole
    {
        const char* key;
        int* field;
        int lo, hi;
        const char* unit;
    };
    const Whole wholes[] = {{"macrocellsize", &macrocellSize, 1, 1024, "voxels"},
                            {"adaptivesteps", &adaptiveSteps, 1, 64, "steps"},
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
        const std::string p = lower(value);
        if (p != "auto" && p != "native" && p != "16bit")
            return error = "texturePrecision must be auto, native or 16bit, got '" + value + "'", false;
        texturePrecision = p;
        return true;
    }
    if (k == "lodbydistance") {
        const std::string b = lower(value);
        if (b == "on" || b == "true" || b == "1") return lodByDistance = true, true;
        if (b == "off" || b == "false" || b == "0") return lodByDistance = false, true;
        return error = "lodByDistance must be on or off, got '" + value + "'", false;
    }
    if (k == "isovalue") {
        if (value.empty()) return isoValue = std::numeric_limits<double>::quiet_NaN(), true;
        if (!parseFiniteNumber(value, v)) return error = "isoValue must be a number, got '" + value + "'", false;
        isoValue = v;
        return true;
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
