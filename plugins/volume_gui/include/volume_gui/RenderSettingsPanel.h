#pragma once
#include <volume_model/ParameterDecl.h>
#include <volume_model/VolumeNode.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace volren {

/// Slot -> implementation the renderer draws a node with (e.g. from its last frame's program).
using ChosenFunctions = std::function<std::map<std::string, std::string>()>;

/// The settings of one VolumeNode as an ImGui window ("Volume settings"): traversal,
/// reconstruction, gradient, illumination, shadowing, acceleration and weighting (from the implementation
/// names the caller offers, e.g. the renderer's registry), sample rate, early termination,
/// level of detail, clipping on or off, and then the declared parameters (ParameterCatalog) of
/// the implementations the node is drawn with, each as its declaration says, within its declared
/// range; the list follows the choice as it changes. Every change goes through
/// RenderSettings::set, so it is validated like `--set`; the renderer picks it up in the next frame.
class RenderSettingsPanel
{
public:
    /// `choices`: slot ("RayTraversal", "Reconstruction", "Gradient", "Illumination", "Shadowing",
    /// "Acceleration", "Weighting") -> names. `chosen`: the implementations the node is drawn with; unset,
    /// those its settings name.
    RenderSettingsPanel(VolumeNode* node, std::map<std::string, std::vector<std::string>> choices,
                        ChosenFunctions chosen = {});
    /// Draws the window into the current ImGui frame and applies this frame's changes.
    void draw();
    /// The last rejected change (empty when all were accepted).
    const std::string& error() const { return _error; }
    /// The declared parameters the panel shows now: those read by the chosen implementations
    /// (the node's explicit choices override `chosen`), in declaration order.
    std::vector<const ParameterDecl*> shownParameters() const;
    /// The fraction of its range each end of curve parameter `key` (weightX, ...) fades over when
    /// it is such a ramp (WeightCurve "ramp:A"), 0 when it has no knots, -1 for any other curve.
    double fade(const std::string& key) const;
    /// Sets curve parameter `key` to a fade of both ends over `fraction` of it (0: none).
    void setFade(const std::string& key, double fraction);

private:
    void apply(const std::string& key, const std::string& value);
    void drawParameter(const ParameterDecl& p);

    osg::ref_ptr<VolumeNode> _node;
    std::map<std::string, std::vector<std::string>> _choices;
    ChosenFunctions _chosen;
    std::string _error;
};

}  // namespace volren
