#pragma once
#include <string>
#include <vector>

namespace volren {

/// Per-node render settings: plain data, compared by value by the renderer each frame.
struct RenderSettings
{
    /// Step between samples as a factor of the volume's smallest voxel spacing.
    double sampleDistanceFactor = 0.5;
    /// Step in world units; when > 0 it overrides sampleDistanceFactor.
    double sampleDistance = 0.0;
    /// Front-to-back marching stops once accumulated opacity reaches this (1 = never early).
    double earlyTerminationThreshold = 0.95;
    /// Offsets each ray's first sample by a per-pixel hash to break up wood-grain artefacts.
    bool jitter = true;

    bool operator==(const RenderSettings& o) const;
    bool operator!=(const RenderSettings& o) const { return !(*this == o); }

    /// Sets one setting by name (the keys of `volren render --set KEY=VALUE`).
    /// Returns false and fills `error` for an unknown key or a value out of range.
    bool set(const std::string& key, const std::string& value, std::string& error);
    /// Names accepted by set().
    static std::vector<std::string> keys();
};

}  // namespace volren
