#pragma once
#include <volume_model/ParameterDecl.h>

#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace volren {

/// Per-node render settings: plain data, compared by value by the renderer each frame. It holds
/// what every volume has (the step, early termination, storage and level of detail) and the
/// chosen implementations; each implementation's own parameters are values of `parameters`,
/// declared beside the implementation (ParameterCatalog).
/// Implementation choices are by slot name (see shaders/slots.glsl); the renderer resolves and
/// validates names against its registry (volren::applyNodeSetting) and its CompositionPolicy
/// fills unset slots from the scene.
struct RenderSettings
{
    /// Step between samples as a factor of the volume's smallest voxel spacing.
    double sampleDistanceFactor = 0.5;
    /// Step in world units; when > 0 it overrides sampleDistanceFactor.
    double sampleDistance = 0.0;
    /// Front-to-back marching stops once accumulated opacity reaches this (1 = never early). The
    /// default stops when the transmittance left is below 1/512: what lies behind could change
    /// a pixel by at most 1/512 of full scale per unit of emission (half an 8-bit step).
    double earlyTerminationThreshold = 1.0 - 1.0 / 512.0;
    /// Edge of the empty-space-skipping macrocells, in voxels (Acceleration occupancy).
    int macrocellSize = 8;
    /// Level of detail: the volume is sampled from this level of its mip chain (0 = full
    /// resolution, each level half the voxels along each axis) with a step 2^lod times as long.
    int lod = 0;
    /// GPU memory for this volume's voxels, in MiB (0 = auto: half of the dedicated memory the
    /// driver reports, else 2048). A volume whose sampled level does not fit, or is larger than
    /// the GPU's largest 3D texture, is drawn from bricks (VolumeStorage bricked) within it.
    int memoryBudgetMB = 0;
    /// Edge of the bricks of a bricked volume, in voxels (each stored with a one-voxel border).
    int brickSize = 32;
    /// Level of detail by distance: on top of lod, the level rises by log2 of the voxels one
    /// pixel covers where the volume is nearest the camera (rounded down), so far volumes sample
    /// coarser and a volume filling the view keeps its full resolution.
    bool lodByDistance = false;
    /// Texture precision of the volume: "native" keeps the voxel type's (R8 for 8-bit data),
    /// "16bit" widens 8-bit data to 16-bit textures (the same values, twice the memory; filtered
    /// finely where a driver rounds filtered 8-bit texels to 8 bits), "auto" widens only on such
    /// drivers (Mesa's llvmpipe).
    std::string texturePrecision = "auto";
    /// Values of the implementations' declared parameters (ParameterCatalog), by key; a
    /// parameter not here has its declared default.
    std::map<std::string, ParameterValue> parameters;

    /// Slot -> implementation chosen by the user ("RayTraversal" -> "mip"); unset slots are
    /// chosen by the scene analysis.
    std::map<std::string, std::string> functions;
    /// Slots forced to their null implementation (for testing equivalences and costs).
    std::set<std::string> forceNull;

    bool operator==(const RenderSettings& o) const;
    bool operator!=(const RenderSettings& o) const { return !(*this == o); }

    /// Sets one setting by name (the keys of `volren render --set KEY=VALUE`).
    /// Returns false and fills `error` for an unknown key or a value out of range.
    bool set(const std::string& key, const std::string& value, std::string& error);
    /// Names accepted by set(), each with a one-line description.
    static std::vector<std::pair<std::string, std::string>> keys();
    /// Current value of `key` as text ("" when the scene decides).
    std::string get(const std::string& key) const;
    /// Value of declared parameter `key` (set, else its default) of type double, int, bool,
    /// std::string or WeightCurve. Throws std::logic_error when no implementation declares `key`
    /// or declares it of another type.
    template <typename T> T parameter(const std::string& key) const;
    /// Value of a Number parameter (parameter<double>).
    double number(const std::string& key) const { return parameter<double>(key); }
    /// Slot chosen by a key ("traversal" -> "RayTraversal"), or "" when the key is not a slot key.
    static std::string slotForKey(const std::string& key);
    /// The key that chooses `slot`'s implementation ("RayTraversal" -> "traversal"), or "".
    static std::string keyForSlot(const std::string& slot);
};

extern template double RenderSettings::parameter<double>(const std::string&) const;
extern template int RenderSettings::parameter<int>(const std::string&) const;
extern template bool RenderSettings::parameter<bool>(const std::string&) const;
extern template std::string RenderSettings::parameter<std::string>(const std::string&) const;
extern template WeightCurve RenderSettings::parameter<WeightCurve>(const std::string&) const;

}  // namespace volren
