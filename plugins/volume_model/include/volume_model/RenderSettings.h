#pragma once
#include <volume_model/SpatialWeighting.h>

#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace volren {

/// Per-node render settings: plain data, compared by value by the renderer each frame.
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
    /// Adaptive sampling (Acceleration adaptive): a macrocell whose classified RGBA (opacity and
    /// opacity-weighted colour) varies by at most this over its values is homogeneous, and one
    /// sample stands for up to adaptiveSteps steps of the march inside it.
    double adaptiveTolerance = 1.0 / 256.0;
    /// Most steps of the march one sample stands for in a homogeneous macrocell (1 = none).
    int adaptiveSteps = 4;
    /// Henyey-Greenstein anisotropy g of the scattering Illumination (0 isotropic, > 0 forward).
    double anisotropy = 0.0;
    /// Shadow rays (Shadowing ray): their step as a factor of the view ray's step.
    double shadowStepFactor = 1.0;
    /// Shadow rays stop once the light's transmittance falls below this (0 = never early).
    double shadowCutoff = 1.0 / 512.0;
    /// Propagated light volume (Shadowing light_volume): its resolution as a fraction of the
    /// volume's along each axis (0, 1].
    double lightVolumeScale = 0.5;
    /// Cone tracing (Shadowing cone, cone_ao): the shadow cones' full aperture in degrees.
    double coneAngle = 10.0;
    /// Cone tracing: where the cones start, in voxels from the sample (its own neighbourhood
    /// casts no shadow on it).
    double coneStart = 0.5;
    /// Cone tracing: each step is this times the cone's diameter there (at least the shadow step;
    /// the diameter is at least one voxel); 1.25 has the error of 1 at less time (docs/bench/shadows.md).
    double coneStepGrowth = 1.25;
    /// Cone tracing: the Gaussian pre-filter of the opacity volume, its sigma in voxels (0: none).
    double coneFilterSigma = 0.0;
    /// Ambient occlusion (Shadowing cone_ao): how far its cones reach, in voxels.
    double aoDistance = 8.0;
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
    /// Data value of the isosurface (isosurface traversal); NaN = the TF's first opaque value.
    double isoValue = std::numeric_limits<double>::quiet_NaN();
    /// Samples below this classified opacity are not lit (lighting_threshold shading).
    double shadingThreshold = 0.05;
    /// Ambient light, as a fraction of the classified colour.
    double ambient = 0.2;
    /// Specular strength and Blinn-Phong exponent.
    double specular = 0.3, shininess = 24.0;
    /// Cook-Torrance surface roughness (0..1].
    double roughness = 0.35;
    /// Threshold of threshold classification, 0..1 of the value window.
    double threshold = 0.5;
    /// What debug shading shows: 0 scalar, 1 position, 2 classification, 3 gradient, 4 normal,
    /// 5 view direction, 6 light direction.
    int debugView = 4;
    /// Spatial weighting: per-axis curves over the normalised coordinates scaling each sample's
    /// opacity (the Weighting slot's axes implementation; all 1 = none).
    SpatialWeighting weighting;

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
    /// Slot chosen by a key ("traversal" -> "RayTraversal"), or "" when the key is not a slot key.
    static std::string slotForKey(const std::string& key);
};

}  // namespace volren
