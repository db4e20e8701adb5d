#pragma once
#include <volume_renderer/VolumeScene.h>

#include <pybind11/pybind11.h>

#include <string>

namespace volren::python {

/// A keyword's value as the text of `--set KEY=VALUE`: a bool as on/off, an integer or float as
/// its shortest exact decimal, a str as it is, a list or tuple of those joined by commas
/// (forceNull=['Jitter', 'Gradient']). TypeError naming the key for anything else.
std::string settingText(const std::string& key, const pybind11::handle& value);

/// Applies every keyword as `volren render --set KEY=VALUE` does (volren::applySetting, in the
/// keywords' order); a bad key or value is a ValueError with SettingError's message.
void applySettings(VolumeScene& scene, const pybind11::dict& settings);

}  // namespace volren::python
