#include <volume_model/ParameterCatalog.h>
#include <volume_model/ParseNumber.h>
#include <volume_model/RenderSettings.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <variant>

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

/// A setting every volume has: declared as implementations' parameters are (no slot: no one
/// implementation reads it) and parsed by the same ParameterDecl, with the field it lives in.
struct Field
{
    ParameterDecl decl;
    std::variant<double RenderSettings::*, int RenderSettings::*, bool RenderSettings::*, std::string RenderSettings::*>
        member;
};

const std::vector<Field>& fields()
{
    static const std::vector<Field> list = [] {
        const RenderSettings d;  // the defaults are the struct's own
        using T = ParameterType;
        return std::vector<Field>{
            {{.key = "sampleFactor", .defaultValue = d.sampleDistanceFactor, .lo = 0.0, .hi = 1e6, .openLow = true,
              .help = "step as a factor of the smallest voxel spacing"},
             &RenderSettings::sampleDistanceFactor},
            {{.key = "sampleDistance", .defaultValue = d.sampleDistance, .lo = 0.0, .hi = 1e300,
              .help = "step in world units (0 = use sampleFactor)"},
             &RenderSettings::sampleDistance},
            {{.key = "earlyTermination", .defaultValue = d.earlyTerminationThreshold, .lo = 0.0, .hi = 1.0,
              .openLow = true, .help = "opacity at which front-to-back marching stops (1 = never; default 1 - 1/512)"},
             &RenderSettings::earlyTerminationThreshold},
            {{.key = "macrocellSize", .type = T::Integer, .defaultValue = d.macrocellSize, .lo = 1, .hi = 1024,
              .unit = "voxels", .help = "edge of the empty-space-skipping macrocells"},
             &RenderSettings::macrocellSize},
            {{.key = "lod", .type = T::Integer, .defaultValue = d.lod, .lo = 0, .hi = 16, .unit = "mip levels",
              .help = "level of detail: mip level the volume is sampled from, the step growing as 2^lod"},
             &RenderSettings::lod},
            {{.key = "lodByDistance", .type = T::Switch, .defaultValue = d.lodByDistance,
              .help = "level of detail by distance: the level rises where a pixel covers more than a voxel"},
             &RenderSettings::lodByDistance},
            {{.key = "memoryBudgetMB", .type = T::Integer, .defaultValue = d.memoryBudgetMB, .lo = 0, .hi = 1 << 24,
              .unit = "MiB",
              .help = "GPU memory for one volume's voxels (0 = auto: half of what the GPU reports, else 2048); "
                      "larger volumes are bricked"},
             &RenderSettings::memoryBudgetMB},
            {{.key = "brickSize", .type = T::Integer, .defaultValue = d.brickSize, .lo = 4, .hi = 512, .unit = "voxels",
              .help = "edge of the bricks of a bricked volume (each stored with a one-voxel border)"},
             &RenderSettings::brickSize},
            {{.key = "texturePrecision", .type = T::Choice, .defaultValue = d.texturePrecision,
              .choices = {"auto", "native", "16bit"},
              .help = "volume texture precision: auto (16bit on drivers that filter 8-bit textures coarsely)"},
             &RenderSettings::texturePrecision}};
    }();
    return list;
}

/// The setting every volume has under `key` (lower case), or null.
const Field* fieldFor(const std::string& key)
{
    for (const Field& f : fields())
        if (lowerKey(f.decl.key) == key) return &f;
    return nullptr;
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

std::string RenderSettings::keyForSlot(const std::string& slot)
{
    for (const auto& [key, s] : slotKeys())
        if (s == slot) return key;
    return {};
}

std::vector<std::pair<std::string, std::string>> RenderSettings::keys()
{
    std::vector<std::pair<std::string, std::string>> out = {
        {"samplerate", "samples per smallest voxel spacing (= 1 / sampleFactor)"}};
    for (const Field& f : fields()) out.push_back({f.decl.key, f.decl.help + " (" + f.decl.range() + ")"});
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
    if (const Field* f = fieldFor(k))
        return std::visit([&](auto member) { return f->decl.format(ParameterValue(this->*member)); }, f->member);
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
    if (k == "samplerate") {
        double v = 0.0;
        if (!parseFiniteNumber(value, v) || !(v > 0.0) || v < 1e-6)
            return error = "samplerate must be a number of samples per voxel > 0, got '" + value + "'", false;
        sampleDistanceFactor = 1.0 / v;
        return true;
    }
    if (const Field* f = fieldFor(k)) {
        ParameterValue v;
        if (!f->decl.parse(value, v, error)) return false;
        std::visit([&](auto member) { this->*member = std::get<std::remove_reference_t<decltype(this->*member)>>(v); },
                   f->member);
        return true;
    }
    std::string known;
    for (const auto& entry : keys()) known += (known.empty() ? "" : ", ") + entry.first;
    error = "unknown setting '" + key + "' (known: " + known + ")";
    return false;
}

}  // namespace volren
