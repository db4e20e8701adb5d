#include <volume_renderer/SceneSettings.h>
#include <volume_renderer/Slots.h>

#include <volume_model/DefaultScene.h>
#include <volume_model/ParseNumber.h>
#include <volume_model/RenderSettings.h>
#include <volume_model/TimeSeries.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace volren {

void applyNodeSetting(RenderSettings& settings, const std::string& key, const std::string& value,
                      const CompositionPolicy& policy)
{
    std::string error;
    if (const std::string slot = RenderSettings::slotForKey(key); !slot.empty()) {
        const std::string name = policy.resolve(slot, value);
        if (name.empty()) {
            std::string known;
            for (const auto& n : policy.choosable(slot)) known += (known.empty() ? "" : ", ") + n;
            throw SettingError(key + ": slot " + slot + " has no implementation '" + value + "' (known: " + known + ")");
        }
        if (!settings.set(key, name, error)) throw SettingError(error);
        return;
    }
    if (!settings.set(key, value, error)) throw SettingError(error);
}

namespace {

/// The whole of `text` as a count from 0 (a channel, a time point), or -1.
int countFrom(const std::string& text)
{
    double v = 0.0;
    if (!parseFiniteNumber(text, v) || v < 0.0 || v != std::floor(v) || v > 1e9) return -1;
    return int(v);
}

/// `channels=all|C,...`: the channels every multi-channel volume below `scene` shows.
void showChannels(VolumeScene& scene, const std::string& value)
{
    std::vector<int> shown;
    const bool all = value == "all";
    if (!all) {
        std::stringstream list(value);
        for (std::string item; std::getline(list, item, ',');) {
            const int c = countFrom(item);
            if (c < 0)
                throw SettingError("expected 'all' or channel numbers from 0 separated by commas, got '" + value + "'");
            shown.push_back(c);
        }
        if (shown.empty()) throw SettingError("expected 'all' or channel numbers from 0 separated by commas");
    }
    for (VolumeNode* node : findVolumeNodes(scene)) {
        const int count = node->getVolume() ? node->getVolume()->channels() : 0;
        if (count < 2) continue;
        std::vector<int> these = shown;
        if (all)
            for (int c = 0; c < count; ++c) these.push_back(c);
        try {
            node->showChannels(these);
        } catch (const std::out_of_range& e) {
            throw SettingError(e.what());
        }
    }
}

/// `channelOpacity=S` or `C:S,...`: the opacity scale of every channel, or of the channels named,
/// of the multi-channel volumes below `scene`.
void scaleChannelOpacity(VolumeScene& scene, const std::string& value)
{
    const std::string expected = "expected an opacity scale >= 0, or channel:scale pairs separated by commas (0:2,1:0.5)";
    std::vector<std::pair<int, double>> scales;  // channel -1: every channel
    std::stringstream list(value);
    for (std::string item; std::getline(list, item, ',');) {
        const std::size_t colon = item.find(':');
        const int c = colon == std::string::npos ? -1 : countFrom(item.substr(0, colon));
        double s = 0.0;
        if ((colon != std::string::npos && c < 0) ||
            !parseFiniteNumber(colon == std::string::npos ? item : item.substr(colon + 1), s) || s < 0.0)
            throw SettingError(expected + ", got '" + value + "'");
        scales.emplace_back(c, s);
    }
    if (scales.empty() || (scales.size() > 1 && std::any_of(scales.begin(), scales.end(), [](const auto& p) { return p.first < 0; })))
        throw SettingError(expected + ", got '" + value + "'");
    const std::vector<VolumeNode*> nodes = findVolumeNodes(scene);
    for (VolumeNode* node : nodes) {  // every value checked before any is applied
        const int count = node->getVolume() ? node->getVolume()->channels() : 0;
        for (const auto& [c, s] : scales)
            if (count >= 2 && c >= count)
                throw SettingError("volume '" + node->getName() + "' has no channel " + std::to_string(c) + " (it has " +
                                   std::to_string(count) + ", counted from 0)");
    }
    for (VolumeNode* node : nodes) {
        const int count = node->getVolume() ? node->getVolume()->channels() : 0;
        if (count < 2) continue;
        if (node->channels.size() < std::size_t(count)) node->channels.resize(std::size_t(count));
        for (const auto& [c, s] : scales)
            for (int k = 0; k < count; ++k)
                if (c < 0 || c == k) node->channels[std::size_t(k)].opacity = s;
    }
}

}  // namespace

void applySetting(VolumeScene& scene, const std::string& key, const std::string& value)
{
    try {
        std::string error;
        if (PassSettings::isKey(key)) {
            if (!scene.pass.set(key, value, error)) throw SettingError(error);
            return;
        }
        if (key == "channels") {
            showChannels(scene, value);
            return;
        }
        if (key == "channelOpacity") {
            scaleChannelOpacity(scene, value);
            return;
        }
        if (key == "time") {
            const int t = countFrom(value);
            if (t < 0) throw SettingError("expected a time point from 0, got '" + value + "'");
            try {
                TimeSeries(scene).show(t);
            } catch (const std::out_of_range& e) {
                throw SettingError(e.what());
            }
            return;
        }
        RenderSettings probe;  // checked once, even when the scene has no volume
        applyNodeSetting(probe, key, value, scene.policy());
        for (VolumeNode* node : findVolumeNodes(scene)) applyNodeSetting(node->settings, key, value, scene.policy());
    } catch (const SettingError& e) {
        throw SettingError(key + "=" + value + ": " + e.what());
    }
}

osg::ref_ptr<VolumeScene> asVolumeScene(osg::Node* scene)
{
    osg::ref_ptr<VolumeScene> root = dynamic_cast<VolumeScene*>(scene);
    if (!root) {
        root = new VolumeScene;
        if (scene) root->addChild(scene);
    }
    return root;
}

std::string settingsHelp(const CompositionPolicy& policy)
{
    std::ostringstream out;
    const RenderSettings defaults;
    out << "Per-volume settings (--set KEY=VALUE; value shown is the default, empty = chosen by the scene):\n";
    for (const auto& [key, what] : RenderSettings::keys())
        out << "  " << std::left << std::setw(18) << key << std::setw(14) << defaults.get(key) << what << "\n";
    out << "Scene settings:\n";
    out << "  " << std::left << std::setw(18) << "channels" << std::setw(14) << "all"
        << "channels multi-channel volumes show, all in one ray: all, or numbers from 0 (0,2)\n";
    out << "  " << std::left << std::setw(18) << "channelOpacity" << std::setw(14) << "1"
        << "opacity scale of every channel (2), or per channel (0:2,1:0.5); in MIP modes: brightness\n";
    out << "  " << std::left << std::setw(18) << "time" << std::setw(14) << "0"
        << "time point time-series volumes show (from 0; a shorter series shows its last)\n";
    out << "Pass settings:\n";
    const PassSettings pass;
    for (const auto& [key, what] : PassSettings::keys())
        out << "  " << std::left << std::setw(18) << key << std::setw(14) << pass.get(key) << what << "\n";
    out << "Implementations per slot (default first):\n";
    for (const SlotInfo& s : slots()) {
        out << "  " << std::left << std::setw(16) << s.name << "(" << RenderSettings::keyForSlot(s.name) << "): ";
        const std::vector<std::string> names = policy.choosable(s.name);
        for (std::size_t i = 0; i < names.size(); ++i) out << (i ? ", " : "") << names[i];
        if (!s.isTemplate && CompositionPolicy::neededImplementation(s.name) != CompositionPolicy::defaultImplementation(s.name))
            out << "   [" << CompositionPolicy::neededImplementation(s.name) << " when the scene needs it]";
        std::string sets;  // how volumes that share a ray combine (multi-volume traversals)
        for (const std::string& name : names)
            if (const ShaderFunction* f = policy.registry().find(s.name, name); f && f->traits.multiVolume)
                sets += (sets.empty() ? "" : ", ") + name + " (" + f->traits.combines + ")";
        if (!sets.empty()) out << "   [how overlapping volumes and a volume's channels combine: " << sets << "]";
        std::string leaps;  // implementations chosen by the traversal's leaps (Acceleration)
        for (const std::string& name : names)
            if (const ShaderFunction* f = policy.registry().find(s.name, name);
                f && !f->traits.skips.empty() && !f->traits.multiVolume)
                leaps += (leaps.empty() ? "" : ", ") + name +
                         (f->traits.approximates ? " (only when asked: approximates) leaps by "
                                                 : " where the traversal leaps by ") +
                         f->traits.skips;
        if (!leaps.empty()) out << "   [" << leaps << "]";
        out << (s.isTemplate ? "   [one instance per clip shape, chosen by the scene]" : "") << "\n";
    }
    return out.str();
}

}  // namespace volren
