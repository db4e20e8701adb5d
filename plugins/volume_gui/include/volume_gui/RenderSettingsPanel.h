#pragma once
#include <volume_model/VolumeNode.h>

#include <map>
#include <string>
#include <vector>

namespace volren {

/// One numeric setting the settings panel shows as a slider over [lo, hi].
struct SettingSlider
{
    const char* label;
    const char* key;  ///< RenderSettings key
    float lo, hi;
    bool logarithmic;
};

/// The settings of one VolumeNode as an ImGui window ("Volume settings"): traversal,
/// reconstruction, gradient, illumination, shadowing and acceleration (from the implementation
/// names the caller offers, e.g. the renderer's registry), sample rate, early termination, the
/// shadowing methods' parameters and scattering anisotropy (shadowSliders), clipping on or off,
/// and the spatial weighting per axis (a fade of both ends, or any curve as text). Every
/// change goes through RenderSettings::set, so it is validated like `--set`; the renderer picks
/// it up in the next frame.
class RenderSettingsPanel
{
public:
    /// `choices`: slot ("RayTraversal", "Reconstruction", "Gradient", "Illumination", "Shadowing",
    /// "Acceleration") -> names.
    RenderSettingsPanel(VolumeNode* node, std::map<std::string, std::vector<std::string>> choices);
    /// Draws the window into the current ImGui frame and applies this frame's changes.
    void draw();
    /// The last rejected change (empty when all were accepted).
    const std::string& error() const { return _error; }
    /// The fraction of axis `axis` (0 x, 1 y, 2 z) each end of it fades over when its weighting is
    /// such a ramp (WeightCurve "ramp:A"), 0 when it has none, -1 for any other curve.
    double fade(int axis) const;
    /// Weighs axis `axis` by a fade of both ends over `fraction` of it (0: no weighting).
    void setFade(int axis, double fraction);
    /// The sliders of the shadowing methods' parameters (shadow rays, light volume, cones and
    /// their ambient occlusion) and of the phase function's anisotropy.
    static const std::vector<SettingSlider>& shadowSliders();

private:
    void apply(const std::string& key, const std::string& value);

    osg::ref_ptr<VolumeNode> _node;
    std::map<std::string, std::vector<std::string>> _choices;
    std::string _error;
};

}  // namespace volren
