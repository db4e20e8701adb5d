#include <volume_gui/RenderSettingsPanel.h>

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace volren {

RenderSettingsPanel::RenderSettingsPanel(VolumeNode* node, std::map<std::string, std::vector<std::string>> choices)
    : _node(node), _choices(std::move(choices))
{
}

void RenderSettingsPanel::apply(const std::string& key, const std::string& value)
{
    std::string error;
    if (!_node->settings.set(key, value, error)) _error = key + ": " + error;
    else _error.clear();
}

namespace {

const char* const weightKeys[3] = {"weightX", "weightY", "weightZ"};

}  // namespace

double RenderSettingsPanel::fade(int axis) const
{
    const WeightCurve& curve = _node->settings.weighting.axes[std::size_t(axis)];
    if (curve.knots.empty()) return 0.0;
    const double a = curve.knots.size() > 1 ? curve.knots[1].first : 0.0;
    WeightCurve ramp;
    std::string error;
    std::ostringstream text;
    text.precision(17);
    text << "ramp:" << a;
    return WeightCurve::parse(text.str(), ramp, error) && ramp == curve ? a : -1.0;
}

void RenderSettingsPanel::setFade(int axis, double fraction)
{
    std::ostringstream text;
    text.precision(17);
    if (fraction > 0.0) text << "ramp:" << std::min(fraction, 0.5);
    apply(weightKeys[axis], fraction > 0.0 ? text.str() : "none");
}

const std::vector<SettingSlider>& RenderSettingsPanel::shadowSliders()
{
    static const std::vector<SettingSlider> sliders = {
        {"shadow step factor", "shadowStepFactor", 0.25f, 8.0f, true},
        {"shadow cutoff", "shadowCutoff", 1e-4f, 0.5f, true},
        {"light volume scale", "lightVolumeScale", 0.1f, 1.0f, false},
        {"cone angle (degrees)", "coneAngle", 0.5f, 90.0f, true},
        {"cone start (voxels)", "coneStart", 0.0f, 8.0f, false},
        {"cone step growth", "coneStepGrowth", 0.25f, 4.0f, true},
        {"cone filter sigma (voxels)", "coneFilterSigma", 0.0f, 3.0f, false},
        {"occlusion distance (voxels)", "aoDistance", 1.0f, 64.0f, true},
        {"anisotropy g", "anisotropy", -0.9f, 0.9f, false},
    };
    return sliders;
}

void RenderSettingsPanel::draw()
{
    ImGui::SetNextWindowSize(ImVec2(400, 420), ImGuiCond_FirstUseEver);
    ImGui::Begin("Volume settings");
    const std::pair<const char*, const char*> slots[] = {{"traversal", "RayTraversal"},
                                                         {"reconstruction", "Reconstruction"},
                                                         {"gradient", "Gradient"},
                                                         {"illumination", "Illumination"},
                                                         {"shadowing", "Shadowing"},
                                                         {"acceleration", "Acceleration"}};
    for (const auto& [key, slot] : slots) {
        const std::string current = _node->settings.get(key);
        if (ImGui::BeginCombo(key, current.empty() ? "(scene decides)" : current.c_str())) {
            if (ImGui::Selectable("(scene decides)", current.empty())) _node->settings.functions.erase(slot);
            for (const std::string& name : _choices[slot])
                if (ImGui::Selectable(name.c_str(), name == current)) apply(key, name);
            ImGui::EndCombo();
        }
    }
    float rate = float(1.0 / _node->settings.sampleDistanceFactor);
    if (ImGui::SliderFloat("samples per voxel", &rate, 0.25f, 16.0f, "%.2f", ImGuiSliderFlags_Logarithmic)) {
        std::ostringstream v;
        v << rate;
        apply("samplerate", v.str());
    }
    float stop = float(_node->settings.earlyTerminationThreshold);
    if (ImGui::SliderFloat("early termination", &stop, 0.5f, 1.0f, "%.3f")) {
        std::ostringstream v;
        v << stop;
        apply("earlyTermination", v.str());
    }
    // Shadows and scattering (Ctrl + drag in the view turns the lights).
    if (ImGui::CollapsingHeader("Shadows and scattering", ImGuiTreeNodeFlags_DefaultOpen)) {
        for (const SettingSlider& s : shadowSliders()) {
            float v = float(std::strtod(_node->settings.get(s.key).c_str(), nullptr));
            if (ImGui::SliderFloat(s.label, &v, s.lo, s.hi, "%.3f", s.logarithmic ? ImGuiSliderFlags_Logarithmic : 0)) {
                std::ostringstream text;
                text << v;
                apply(s.key, text.str());
            }
        }
    }
    int cell = _node->settings.macrocellSize;
    if (ImGui::SliderInt("macrocell size", &cell, 1, 64, "%d voxels", ImGuiSliderFlags_Logarithmic))
        apply("macrocellSize", std::to_string(cell));
    float tolerance = float(_node->settings.adaptiveTolerance);
    if (ImGui::SliderFloat("adaptive tolerance", &tolerance, 1e-4f, 0.1f, "%.4f", ImGuiSliderFlags_Logarithmic)) {
        std::ostringstream v;
        v << tolerance;
        apply("adaptiveTolerance", v.str());
    }
    int steps = _node->settings.adaptiveSteps;
    if (ImGui::SliderInt("adaptive steps", &steps, 1, 64)) apply("adaptiveSteps", std::to_string(steps));
    int lod = _node->settings.lod;
    if (ImGui::SliderInt("level of detail", &lod, 0, 6)) apply("lod", std::to_string(lod));
    bool byDistance = _node->settings.lodByDistance;
    if (ImGui::Checkbox("level of detail by distance", &byDistance)) apply("lodByDistance", byDistance ? "on" : "off");
    bool clipping = !_node->settings.forceNull.count("ClipPosition");
    if (ImGui::Checkbox("clipping", &clipping)) {
        std::set<std::string> nulls = _node->settings.forceNull;
        for (const char* slot : {"ClipPosition", "ClipRay"}) {
            if (clipping) nulls.erase(slot);
            else nulls.insert(slot);
        }
        std::string list;
        for (const std::string& s : nulls) list += (list.empty() ? "" : ",") + s;
        apply("forceNull", list);
    }
    // Spatial weighting: each axis's ends faded (the slider) or any curve "u:w,u:w,..." (Enter applies).
    if (ImGui::CollapsingHeader("spatial weighting")) {
        for (int axis = 0; axis < 3; ++axis) {
            ImGui::PushID(axis);
            const double current = fade(axis);
            float fraction = float(std::max(current, 0.0));
            const std::string label = std::string("fade ends ") + "xyz"[axis];
            if (ImGui::SliderFloat(label.c_str(), &fraction, 0.0f, 0.5f, current < 0.0 ? "(curve)" : "%.3f"))
                setFade(axis, fraction);
            char text[512];
            const std::string curve = _node->settings.get(weightKeys[axis]);
            std::snprintf(text, sizeof(text), "%s", curve.c_str());
            if (ImGui::InputText(weightKeys[axis], text, sizeof(text), ImGuiInputTextFlags_EnterReturnsTrue))
                apply(weightKeys[axis], text);
            ImGui::PopID();
        }
    }
    if (!_error.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", _error.c_str());
    ImGui::End();
}

}  // namespace volren
