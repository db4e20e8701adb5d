#include <volume_model/ParseNumber.h>
#include <volume_model/RenderSettings.h>


namespace volren {

namespace {

bool parseBool(const std::string& text, bool& out)
{
    if (text == "1" || text == "true" || text == "on" || text == "yes") return out = true, true;
    if (text == "0" || text == "false" || text == "off" || text == "no") return out = false, true;
    return false;
}

}  // namespace

bool RenderSettings::operator==(const RenderSettings& o) const
{
    return sampleDistanceFactor == o.sampleDistanceFactor && sampleDistance == o.sampleDistance &&
           earlyTerminationThreshold == o.earlyTerminationThreshold && jitter == o.jitter;
}

std::vector<std::string> RenderSettings::keys()
{
    return {"sampleFactor", "sampleDistance", "earlyTermination", "jitter"};
}

bool RenderSettings::set(const std::string& key, const std::string& value, std::string& error)
{
    double number = 0.0;
    if (key == "sampleFactor") {
        if (!parseFiniteNumber(value, number) || !(number > 0.0) || number > 1e6)
            return error = "sampleFactor must be a number in (0, 1e6], got '" + value + "'", false;
        sampleDistanceFactor = number;
        return true;
    }
    if (key == "sampleDistance") {
        if (!parseFiniteNumber(value, number) || number < 0.0)
            return error = "sampleDistance must be a number >= 0 (0 = use sampleFactor), got '" + value + "'", false;
        sampleDistance = number;
        return true;
    }
    if (key == "earlyTermination") {
        if (!parseFiniteNumber(value, number) || !(number > 0.0) || number > 1.0)
            return error = "earlyTermination must be a number in (0, 1], got '" + value + "'", false;
        earlyTerminationThreshold = number;
        return true;
    }
    if (key == "jitter") {
        if (!parseBool(value, jitter)) return error = "jitter must be on/off (1/0, true/false), got '" + value + "'", false;
        return true;
    }
    std::string known;
    for (const auto& k : keys()) known += (known.empty() ? "" : ", ") + k;
    error = "unknown setting '" + key + "' (known: " + known + ")";
    return false;
}

}  // namespace volren
