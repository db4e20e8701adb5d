#include <volume_renderer/PassSettings.h>

#include <volume_model/ParseNumber.h>
#include <volume_model/RenderSettings.h>

#include <charconv>

namespace volren {

std::vector<std::pair<std::string, std::string>> PassSettings::keys()
{
    return {{"lighting", "on/off: off ignores the scene's lights, so the lighting slots become null"},
            {"forceNullAll", "comma-separated slots forced to null for every volume"},
            {"streamBricks", "on/off: bricked volumes draw what is loaded while loader threads read the rest (off: "
                             "every frame waits for its bricks)"},
            {"uploadBudgetMB", "megabytes of bricks a streaming frame uploads at most (> 0)"},
            {"countSamples", "on/off: on writes each pixel's number of reconstructed samples into red (alpha 1) "
                             "instead of its colour, a debug output of what skipping saves"}};
}

bool PassSettings::isKey(const std::string& key)
{
    for (const auto& entry : keys())
        if (entry.first == key) return true;
    return false;
}

bool PassSettings::isSaved(const std::string& key) const
{
    return isKey(key) && (key != "countSamples" || countSamples);
}

std::string PassSettings::get(const std::string& key) const
{
    if (key == "lighting") return lighting ? "on" : "off";
    if (key == "streamBricks") return streamBricks ? "on" : "off";
    if (key == "countSamples") return countSamples ? "on" : "off";
    if (key == "uploadBudgetMB") {
        char text[32];  // the shortest text that reads back as the value
        return std::string(text, std::to_chars(text, text + sizeof(text), uploadBudgetMB).ptr);
    }
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
    if (key == "streamBricks") {
        if (value == "on" || value == "1" || value == "true") return streamBricks = true, true;
        if (value == "off" || value == "0" || value == "false") return streamBricks = false, true;
        return error = "streamBricks must be on or off, got '" + value + "'", false;
    }
    if (key == "countSamples") {
        if (value == "on" || value == "1" || value == "true") return countSamples = true, true;
        if (value == "off" || value == "0" || value == "false") return countSamples = false, true;
        return error = "countSamples must be on or off, got '" + value + "'", false;
    }
    if (key == "uploadBudgetMB") {
        double v = 0.0;
        if (!parseFiniteNumber(value, v) || !(v > 0.0) || v > 1e6)
            return error = "uploadBudgetMB must be a number of megabytes above 0, got '" + value + "'", false;
        uploadBudgetMB = v;
        return true;
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
