#include <volume_renderer/PassSettings.h>

#include <volume_model/RenderSettings.h>

namespace volren {

std::vector<std::pair<std::string, std::string>> PassSettings::keys()
{
    return {{"lighting", "on/off: off ignores the scene's lights, so the lighting slots become null"},
            {"forceNullAll", "comma-separated slots forced to null for every volume"}};
}

bool PassSettings::isKey(const std::string& key)
{
    for (const auto& entry : keys())
        if (entry.first == key) return true;
    return false;
}

std::string PassSettings::get(const std::string& key) const
{
    if (key == "lighting") return lighting ? "on" : "off";
    if (key == "forceNullAll") {
        std::string list;
        for (const auto& s : forceNull) list += (list.empty() ? "" : ",") + s;
        return list;
    }
    return {};
}

bool PassSettings::set(const std::string& key, const std::string& value, std::string& error)
{
    if (key == "lighting") {
        if (value == "on" || value == "1" || value == "true") return lighting = true, true;
        if (value == "off" || value == "0" || value == "false") return lighting = false, true;
        return error = "lighting must be on or off, got '" + value + "'", false;
    }
    if (key == "forceNullAll") {
        RenderSettings probe;  // same slot list and validation as the per-node key
        if (!probe.set("forceNull", value, error)) return false;
        forceNull = probe.forceNull;
        return true;
    }
    error = "'" + key + "' is not a pass setting";
    return false;
}

}  // namespace volren
