#include <volume_renderer/SceneSettings.h>
#include <volume_renderer/Slots.h>

#include <volume_model/DefaultScene.h>
#include <volume_model/RenderSettings.h>

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

void applySetting(VolumeScene& scene, const std::string& key, const std::string& value)
{
    try {
        std::string error;
        if (PassSettings::isKey(key)) {
            if (!scene.pass.set(key, value, error)) throw SettingError(error);
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
    out << "Pass settings:\n";
    const PassSettings pass;
    for (const auto& [key, what] : PassSettings::keys())
        out << "  " << std::left << std::setw(18) << key << std::setw(14) << pass.get(key) << what << "\n";
    out << "Implementations per slot (default first):\n";
    for (const SlotInfo& s : slots()) {
        std::string key;
        for (const auto& entry : RenderSettings::keys())
            if (RenderSettings::slotForKey(entry.first) == s.name) key = entry.first;
        out << "  " << std::left << std::setw(16) << s.name << "(" << key << "): ";
        const std::vector<std::string> names = policy.choosable(s.name);
        for (std::size_t i = 0; i < names.size(); ++i) out << (i ? ", " : "") << names[i];
        if (!s.isTemplate && CompositionPolicy::neededImplementation(s.name) != CompositionPolicy::defaultImplementation(s.name))
            out << "   [" << CompositionPolicy::neededImplementation(s.name) << " when the scene needs it]";
        std::string leaps;  // implementations chosen by the traversal's leaps (Acceleration)
        for (const std::string& name : names)
            if (const ShaderFunction* f = policy.registry().find(s.name, name); f && !f->traits.skips.empty())
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
