#include <volume_gui/RenderSettingsPanel.h>

#include <volume_model/ParameterCatalog.h>

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace volren {

RenderSettingsPanel::RenderSettingsPanel(VolumeNode* node, std::map<std::string, std::vector<std::string>> choices,
                                         ChosenFunctions chosen)
    : _node(node), _choices(std::move(choices)), _chosen(std::move(chosen))
{
}

void RenderSettingsPanel::apply(const std::string& key, const std::string& value)
{
    std::string error;
    if (!_node->settings.set(key, value, error)) _error = key + ": " + error;
    else _error.clear();
}

std::vector<const ParameterDecl*> RenderSettingsPanel::shownParameters() const
{
    std::map<std::string, std::string> chosen = _chosen ? _chosen() : std::map<std::string, std::string>{};
    for (const auto& [slot, name] : _node->settings.functions) chosen[slot] = name;
    for (const std::string& slot : _node->settings.forceNull) chosen[slot] = "null";
    std::vector<const ParameterDecl*> shown;
    for (const ParameterDecl& p : ParameterCatalog::instance().all()) {
        auto it = chosen.find(p.slot);
        if (it != chosen.end() && p.readBy(p.slot, it->second) && p.panel.kind != PanelHint::Hidden) shown.push_back(&p);
    }
    return shown;
}

double RenderSettingsPanel::fade(const std::string& key) const
{
    const WeightCurve curve = _node->settings.parameter<WeightCurve>(key);
    if (curve.knots.empty()) return 0.0;
    const double a = curve.knots.size() > 1 ? curve.knots[1].first : 0.0;
    WeightCurve ramp;
    std::string error;
    std::ostringstream text;
    text.precision(17);
    text << "ramp:" << a;
    return WeightCurve::parse(text.str(), ramp, error) && ramp == curve ? a : -1.0;
}

void RenderSettingsPanel::setFade(const std::string& key, double fraction)
{
    std::ostringstream text;
    text.precision(17);
    if (fraction > 0.0) text << "ramp:" << std::min(fraction, 0.5);
    apply(key, fraction > 0.0 ? text.str() : "none");
}

void RenderSettingsPanel::drawParameter(const ParameterDecl& p)
{
    const std::string label = p.label.empty() ? p.key : p.label;
    const double lo = p.panel.lo != p.panel.hi ? p.panel.lo : p.lo;
    const double hi = p.panel.lo != p.panel.hi ? p.panel.hi : p.hi;
    const std::string current = _node->settings.get(p.key);
    bool changed = false;
    std::ostringstream text;
    switch (p.panel.kind) {
    case PanelHint::Slider:
    case PanelHint::LogSlider: {
        const ImGuiSliderFlags flags = p.panel.kind == PanelHint::LogSlider ? ImGuiSliderFlags_Logarithmic : 0;
        if (p.type == ParameterType::Integer) {
            int v = _node->settings.parameter<int>(p.key);
            if ((changed = ImGui::SliderInt(label.c_str(), &v, int(lo), int(hi), "%d", flags))) text << v;
        } else {
            float v = float(_node->settings.number(p.key));
            if ((changed = ImGui::SliderFloat(label.c_str(), &v, float(lo), float(hi), "%.4g", flags))) text << v;
        }
        break;
    }
    case PanelHint::Checkbox: {
        bool v = _node->settings.parameter<bool>(p.key);
        if ((changed = ImGui::Checkbox(label.c_str(), &v))) text << (v ? "on" : "off");
        break;
    }
    case PanelHint::Combo:
        if (ImGui::BeginCombo(label.c_str(), current.c_str())) {
            for (const std::string& c : p.choices)
                if (ImGui::Selectable(c.c_str(), c == current)) changed = true, text << c;
            ImGui::EndCombo();
        }
        break;
    case PanelHint::Text: {
        ImGui::PushID(p.key.c_str());
        if (p.type == ParameterType::Curve) {  // a fade of both ends, or any curve as text
            const double f = fade(p.key);
            float fraction = float(std::max(f, 0.0));
            if (ImGui::SliderFloat(("fade ends " + label).c_str(), &fraction, 0.0f, 0.5f, f < 0.0 ? "(curve)" : "%.3f"))
                setFade(p.key, fraction);
        }
        char buffer[512];
        std::snprintf(buffer, sizeof(buffer), "%s", current.c_str());
        if ((changed = ImGui::InputText(label.c_str(), buffer, sizeof(buffer), ImGuiInputTextFlags_EnterReturnsTrue)))
            text << buffer;
        ImGui::PopID();
        break;
    }
    case PanelHint::Hidden:
        break;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s: %s (%s)", p.key.c_str(), p.help.c_str(), p.range().c_str());
    if (changed) apply(p.key, text.str());
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
                                                         {"acceleration", "Acceleration"},
                                                         {"weighting", "Weighting"}};
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
    int cell = _node->settings.macrocellSize;
    if (ImGui::SliderInt("macrocell size", &cell, 1, 64, "%d voxels", ImGuiSliderFlags_Logarithmic))
        apply("macrocellSize", std::to_string(cell));
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
    // The parameters of the implementations the node is drawn with, grouped by slot.
    std::string group;
    for (const ParameterDecl* p : shownParameters()) {
        if (p->slot != group) {
            ImGui::Separator();
            ImGui::TextDisabled("%s", (group = p->slot).c_str());
        }
        drawParameter(*p);
    }
    if (!_error.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", _error.c_str());
    ImGui::End();
}

}  // namespace volren
