#pragma once
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace volren {

/// Settings of a VolumeScene pass, shared by every volume it draws (saved with the scene as
/// `PassSettings` key/value pairs; `volren render --set` routes these keys here).
struct PassSettings
{
    /// When false the scene's lights are ignored (lighting slots become null).
    bool lighting = true;
    /// Slots forced to null for every volume (testing, cost measurements).
    std::set<std::string> forceNull;
    /// Bricked volumes stream: frames draw the bricks already in the pool (coarser levels
    /// meanwhile) while loader threads read the rest (volren view). Off: every frame waits for
    /// the bricks it plans (offline renders, deterministic).
    bool streamBricks = false;
    /// Megabytes of bricks a streaming frame uploads at most.
    double uploadBudgetMB = 64.0;
    /// A debug output: each pixel's red channel holds the number of samples its ray reconstructed
    /// (every Reconstruction call: the view ray's, its gradients' and shadows'), green and blue 0,
    /// alpha 1, instead of its colour. What empty-space skipping saves, counted (exact in float
    /// targets up to 2^24).
    bool countSamples = false;

    /// Sets a pass setting by name (`lighting`, `forceNullAll`); false with `error` set when the
    /// key is not a pass setting or the value is bad.
    bool set(const std::string& key, const std::string& value, std::string& error);
    /// Current value of pass setting `key` as text ("" for an unknown key).
    std::string get(const std::string& key) const;
    /// Pass setting names with one-line descriptions.
    static std::vector<std::pair<std::string, std::string>> keys();
    /// Whether `key` names a pass setting.
    static bool isKey(const std::string& key);
    /// Whether a scene file saves `key`: every setting, except a debug output while it is off
    /// (countSamples), so scenes written before it existed read and write back unchanged.
    bool isSaved(const std::string& key) const;
};

}  // namespace volren
