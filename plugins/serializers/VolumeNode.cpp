// volren::VolumeNode: its (shareable) Volume and TransferFunction, its RenderSettings and, for
// a multi-channel volume, how each channel is shown (Channels: visible, transfer function, opacity scale),
// and the time point a time series shows (TimePoint, written when not 0).
// Name, node mask, state set and callbacks come from the osg::Node wrapper.
//
// Settings are written as `key "value"` pairs under the names of `volren render --set` and read
// back through volren::applyNodeSetting (RenderSettings::set, implementation names checked
// against the renderer's registry, parameters against their declarations): every key
// RenderSettings::keys() lists is written, so a new setting or an implementation's new
// parameter is saved without touching this file. Numbers are written at full precision
// (exactNumber), `samplerate` is skipped (an alias of sampleFactor), and slot keys write the
// chosen implementation itself (get() reports a forced slot as "null (forced)").
#include "StreamFields.h"

#include <volume_renderer/SceneSettings.h>

#include <volume_model/ParameterCatalog.h>
#include <volume_model/VolumeNode.h>

#include <osgDB/ObjectWrapper>

#include <algorithm>
#include <cmath>

namespace {

using namespace volren::serializers;
using volren::RenderSettings;
using volren::VolumeNode;

/// The order release 0.1 wrote its settings in, so that the files it wrote read and write back
/// byte for byte. Frozen: keys that came later follow it in RenderSettings::keys() order.
const std::vector<std::string>& release01Order()
{
    static const std::vector<std::string> keys = {
        "sampleFactor", "sampleDistance", "earlyTermination", "macrocellSize", "adaptiveTolerance", "adaptiveSteps",
        "anisotropy", "shadowStepFactor", "shadowCutoff", "lightVolumeScale", "coneAngle", "coneStart",
        "coneStepGrowth", "coneFilterSigma", "aoDistance", "lod", "lodByDistance", "memoryBudgetMB", "brickSize",
        "texturePrecision", "isoValue", "shadingThreshold", "ambient", "specular", "shininess", "roughness",
        "threshold", "debugView", "weightX", "weightY", "weightZ", "forceNull"};
    return keys;
}

/// A setting's value as a file holds it: numbers at full precision, else RenderSettings::get's text.
std::string fileValue(const RenderSettings& settings, const std::string& key)
{
    const double* number = nullptr;
    if (key == "sampleFactor") number = &settings.sampleDistanceFactor;
    if (key == "sampleDistance") number = &settings.sampleDistance;
    if (key == "earlyTermination") number = &settings.earlyTerminationThreshold;
    if (number) return exactNumber(*number);
    if (const volren::ParameterDecl* decl = volren::ParameterCatalog::instance().find(key);
        decl && decl->type == volren::ParameterType::Number) {
        const double v = settings.number(key);
        return std::isfinite(v) ? exactNumber(v) : std::string();
    }
    return settings.get(key);
}

/// The settings as key/value text pairs; keys the scene decides (empty values) are left out.
std::vector<std::pair<std::string, std::string>> settingPairs(const RenderSettings& settings)
{
    std::vector<std::string> order = release01Order();
    for (const auto& entry : RenderSettings::keys())
        if (entry.first != "samplerate" && std::find(order.begin(), order.end(), entry.first) == order.end())
            order.push_back(entry.first);
    std::vector<std::pair<std::string, std::string>> pairs;
    for (const std::string& key : order) {
        std::string value;
        if (const std::string slot = RenderSettings::slotForKey(key); !slot.empty()) {
            auto it = settings.functions.find(slot);
            if (it != settings.functions.end()) value = it->second;
        } else {
            value = fileValue(settings, key);
        }
        if (!value.empty()) pairs.emplace_back(key, value);
    }
    return pairs;
}

// --- Volume and TransferFunction: nested objects, shared by unique id -----------------

bool checkVolume(const VolumeNode& node) { return node.getVolume() != nullptr; }

bool writeVolume(osgDB::OutputStream& os, const VolumeNode& node)
{
    writeObjectField(os, node.getVolume());
    return true;
}

bool readVolume(osgDB::InputStream& is, VolumeNode& node)
{
    osg::ref_ptr<volren::Volume> volume;
    if (!readObjectField(is, volume, "volren::VolumeNode Volume", "volren::Volume")) return false;
    node.setVolume(volume.get());
    return true;
}

bool checkTransferFunction(const VolumeNode& node) { return node.getTransferFunction() != nullptr; }

bool writeTransferFunction(osgDB::OutputStream& os, const VolumeNode& node)
{
    writeObjectField(os, node.getTransferFunction());
    return true;
}

bool readTransferFunction(osgDB::InputStream& is, VolumeNode& node)
{
    osg::ref_ptr<volren::TransferFunction> tf;
    if (!readObjectField(is, tf, "volren::VolumeNode TransferFunction", "volren::TransferFunction")) return false;
    node.setTransferFunction(tf.get());
    return true;
}

// --- Channels: how each channel of a multi-channel volume is shown ------------------------

bool checkChannels(const VolumeNode& node) { return !node.channels.empty(); }

bool writeChannels(osgDB::OutputStream& os, const VolumeNode& node)
{
    writeInt(os, std::int64_t(node.channels.size()));
    os << os.BEGIN_BRACKET << std::endl;
    for (const volren::ChannelDisplay& channel : node.channels) {
        writeProperty(os, "Visible");
        writeBool(os, channel.visible);
        writeProperty(os, "TransferFunction");  // the node's where the channel names none
        writeObjectField(os, channel.transferFunction ? channel.transferFunction.get() : node.getTransferFunction());
        writeProperty(os, "Opacity");
        writeDouble(os, channel.opacity);
    }
    os << os.END_BRACKET << std::endl;
    return true;
}

bool readChannels(osgDB::InputStream& is, VolumeNode& node)
{
    const std::string field = "volren::VolumeNode Channels";
    std::int64_t count = 0;
    if (!readInt(is, count, 0, 4096, field)) return false;
    is >> is.BEGIN_BRACKET;
    std::vector<volren::ChannelDisplay> channels(static_cast<std::size_t>(count));
    for (std::size_t c = 0; c < channels.size(); ++c) {
        const std::string what = field + " " + std::to_string(c);
        if (!readProperty(is, "Visible", what) || !readBool(is, channels[c].visible, what + " Visible") ||
            !readProperty(is, "TransferFunction", what) ||
            !readObjectField(is, channels[c].transferFunction, what + " TransferFunction", "volren::TransferFunction"))
            return false;
        // Opacity came later: text files without it keep 1. Binary files always hold it (.osgb
        // scenes with Channels written before it, one day of development, do not read).
        const bool hasOpacity = is.isBinary() ? readProperty(is, "Opacity", what) : is.matchString("Opacity");
        if (hasOpacity && !readDouble(is, channels[c].opacity, what + " Opacity")) return false;
        if (is.getException()) return false;
        if (channels[c].opacity < 0.0) return fail(is, what + " Opacity: " + std::to_string(channels[c].opacity) + " is negative"), false;
    }
    is >> is.END_BRACKET;
    if (is.getException()) return false;
    node.channels = std::move(channels);
    return true;
}

// --- TimePoint: the time point a time-series volume shows ---------------------------------

bool checkTimePoint(const VolumeNode& node) { return node.timePoint() != 0; }

bool writeTimePoint(osgDB::OutputStream& os, const VolumeNode& node)
{
    writeInt(os, node.timePoint());
    os << std::endl;
    return true;
}

bool readTimePoint(osgDB::InputStream& is, VolumeNode& node)
{
    std::int64_t t = 0;
    if (!readInt(is, t, 0, 1000000000, "volren::VolumeNode TimePoint")) return false;
    node.setTimePoint(int(t));
    return true;
}

// --- Settings ------------------------------------------------------------------------------

bool checkSettings(const VolumeNode&) { return true; }

bool writeSettings(osgDB::OutputStream& os, const VolumeNode& node)
{
    const auto pairs = settingPairs(node.settings);
    writeInt(os, std::int64_t(pairs.size()));
    os << os.BEGIN_BRACKET << std::endl;
    for (const auto& [key, value] : pairs) {
        os << key;  // an identifier: a bare word
        writeString(os, value);
        os << std::endl;
    }
    os << os.END_BRACKET << std::endl;
    return true;
}

bool readSettings(osgDB::InputStream& is, VolumeNode& node)
{
    const std::string field = "volren::VolumeNode Settings";
    std::int64_t count = 0;
    if (!readInt(is, count, 0, 10000, field)) return false;
    is >> is.BEGIN_BRACKET;
    RenderSettings settings;
    const volren::CompositionPolicy policy;
    for (std::int64_t n = 0; n < count; ++n) {
        std::string key, value;
        if (!readString(is, key, field) || !readString(is, value, field + " " + key)) return false;
        try {  // implementation names are checked against the renderer's registry
            volren::applyNodeSetting(settings, key, value, policy);
        } catch (const volren::SettingError& e) {
            return fail(is, field + ": " + e.what()), false;
        }
    }
    is >> is.END_BRACKET;
    if (is.getException()) return false;
    node.settings = settings;
    return true;
}

}  // namespace

REGISTER_OBJECT_WRAPPER(volren_VolumeNode, new volren::VolumeNode, volren::VolumeNode,
                        "osg::Object osg::Node volren::VolumeNode")
{
    ADD_USER_SERIALIZER(Volume);
    ADD_USER_SERIALIZER(TransferFunction);
    ADD_USER_SERIALIZER(Settings);
    ADD_USER_SERIALIZER(Channels);
    ADD_USER_SERIALIZER(TimePoint);
}
