#pragma once
#include <volume_renderer/CompositionPolicy.h>
#include <volume_renderer/VolumeScene.h>

#include <stdexcept>
#include <string>

namespace volren {

struct RenderSettings;

/// A setting that cannot be applied: an unknown key, a bad value, an implementation the
/// registry does not have. what() names the key and the reason (and the known choices).
struct SettingError : std::invalid_argument
{
    using std::invalid_argument::invalid_argument;
};

/// Sets `key` = `value` on a node's `settings`. Implementation keys (`traversal`, ...) are
/// resolved by `policy` (names, aliases, on/off) and must name a registered implementation;
/// other keys are RenderSettings::set's. Throws SettingError.
void applyNodeSetting(RenderSettings& settings, const std::string& key, const std::string& value,
                      const CompositionPolicy& policy);

/// The one router of `volren render --set KEY=VALUE` (and bench configurations): a pass setting
/// goes to `scene.pass`; `channels` (all, or channel numbers 0,2) to every multi-channel
/// VolumeNode below `scene` (VolumeNode::showChannels), `time` (a time point) to every
/// time series (TimeSeries::show); any other to every VolumeNode below `scene`'s settings.
/// Throws SettingError ("KEY=VALUE: why").
void applySetting(VolumeScene& scene, const std::string& key, const std::string& value);

/// `scene` when it is a VolumeScene, else a new VolumeScene holding it.
osg::ref_ptr<VolumeScene> asVolumeScene(osg::Node* scene);

/// Text of `volren render --help-settings`: every node and pass setting with its default, and
/// every slot's implementations, the policy's default first.
std::string settingsHelp(const CompositionPolicy& policy);

}  // namespace volren
