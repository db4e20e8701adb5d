#include <volume_gui/TransferFunctionEditor.h>

#include <volume_model/TransferFunctionFile.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <optional>

namespace volren {

namespace {

/// A preset: control points at fractions of the TF's value window.
struct Preset
{
    std::string name;
    std::vector<std::pair<double, osg::Vec4>> points;
};

const std::vector<Preset>& presets()
{
    static const std::vector<Preset> all = {
        {"CT bone", {{0.0, {0, 0, 0, 0}}, {0.45, {0.55f, 0.25f, 0.15f, 0}}, {0.6, {0.9f, 0.8f, 0.7f, 0.3f}}, {1.0, {1, 1, 1, 0.8f}}}},
        {"CT soft tissue",
         {{0.0, {0, 0, 0, 0}}, {0.3, {0.7f, 0.3f, 0.2f, 0}}, {0.4, {0.9f, 0.5f, 0.4f, 0.15f}}, {0.55, {1, 0.8f, 0.7f, 0.05f}},
          {1.0, {1, 1, 1, 0.05f}}}},
        {"MRI",
         {{0.0, {0, 0, 0, 0}}, {0.18, {0.5f, 0.2f, 0.15f, 0}}, {0.33, {0.8f, 0.45f, 0.4f, 0.08f}},
          {0.5, {0.95f, 0.85f, 0.75f, 0.35f}}, {0.7, {1, 0.95f, 0.8f, 0.7f}}, {1.0, {1, 1, 1, 0.8f}}}},
        {"Microscopy green",
         {{0.0, {0, 0, 0, 0}}, {0.3, {0, 0.3f, 0, 0}}, {0.6, {0.2f, 0.9f, 0.3f, 0.15f}}, {1.0, {0.8f, 1, 0.8f, 0.6f}}}},
        {"Microscopy magenta",
         {{0.0, {0, 0, 0, 0}}, {0.3, {0.3f, 0, 0.3f, 0}}, {0.6, {0.9f, 0.2f, 0.9f, 0.15f}}, {1.0, {1, 0.8f, 1, 0.6f}}}},
    };
    return all;
}

ImU32 colourOf(const osg::Vec4& rgba, float alpha = 1.0f)
{
    return ImGui::ColorConvertFloat4ToU32(ImVec4(rgba.r(), rgba.g(), rgba.b(), alpha));
}

constexpr float pointRadius = 5.0f;
constexpr float hitRadius = 7.0f;
constexpr double smallestOpacity = 1e-4;  ///< bottom of the logarithmic opacity axis

}  // namespace

TransferFunctionEditor::TransferFunctionEditor(TransferFunction* tf, const Volume* volume)
    : _tf(tf), _volume(volume), _history(tf)
{
    viewMin = tf->domainMin();
    viewMax = tf->domainMax();
    if (!(viewMax > viewMin)) viewMax = viewMin + 1.0;
}

const std::vector<std::string>& TransferFunctionEditor::presetNames()
{
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const Preset& p : presets()) n.push_back(p.name);
        return n;
    }();
    return names;
}

double TransferFunctionEditor::levelOf(const osg::Vec4& rgba) const
{
    switch (channel) {
    case Channel::Red: return rgba.r();
    case Channel::Green: return rgba.g();
    case Channel::Blue: return rgba.b();
    default: return rgba.a();
    }
}

void TransferFunctionEditor::setLevel(osg::Vec4& rgba, double level) const
{
    const float l = float(std::clamp(level, 0.0, 1.0));
    switch (channel) {
    case Channel::Red: rgba.r() = l; break;
    case Channel::Green: rgba.g() = l; break;
    case Channel::Blue: rgba.b() = l; break;
    default: rgba.a() = l; break;
    }
}

double TransferFunctionEditor::toAxis(double level) const
{
    const bool opacity = channel == Channel::Alpha || channel == Channel::ColourMap;
    if (!(opacity && logOpacity)) return std::clamp(level, 0.0, 1.0);
    if (level <= smallestOpacity) return 0.0;
    return std::clamp(1.0 + std::log10(level) / -std::log10(smallestOpacity), 0.0, 1.0);
}

double TransferFunctionEditor::fromAxis(double axis) const
{
    axis = std::clamp(axis, 0.0, 1.0);
    const bool opacity = channel == Channel::Alpha || channel == Channel::ColourMap;
    if (!(opacity && logOpacity)) return axis;
    if (axis <= 0.0) return 0.0;
    return std::pow(10.0, (axis - 1.0) * -std::log10(smallestOpacity));
}

ImVec2 TransferFunctionEditor::screenPosition(double value, double level) const
{
    const double tx = (value - viewMin) / (viewMax - viewMin);
    return ImVec2(float(_canvasMin.x + tx * (_canvasMax.x - _canvasMin.x)),
                  float(_canvasMax.y - toAxis(level) * (_canvasMax.y - _canvasMin.y)));
}

std::pair<double, double> TransferFunctionEditor::valueAt(const ImVec2& p) const
{
    const double tx = (p.x - _canvasMin.x) / std::max(1.0f, _canvasMax.x - _canvasMin.x);
    const double ty = (_canvasMax.y - p.y) / std::max(1.0f, _canvasMax.y - _canvasMin.y);
    return {viewMin + tx * (viewMax - viewMin), fromAxis(ty)};
}

void TransferFunctionEditor::draw()
{
    ImGui::SetNextWindowSize(ImVec2(640, 380), ImGuiCond_FirstUseEver);
    ImGui::Begin("Transfer function");
    drawToolbar();
    drawCanvas();
    handleMouse();
    if (channel == Channel::ColourMap && _haveSelection && _tf->points().count(_selected)) {
        osg::Vec4 rgba = _tf->points().at(_selected);
        float rgb[3] = {rgba.r(), rgba.g(), rgba.b()};
        if (ImGui::ColorEdit3("point colour", rgb)) _tf->setPoint(_selected, osg::Vec4(rgb[0], rgb[1], rgb[2], rgba.a()));
        if (ImGui::IsItemDeactivatedAfterEdit()) _history.record();
        ImGui::SameLine();
        ImGui::Text("at %.4g, opacity %.3g", _selected, rgba.a());
    }
    drawFileRow();
    const ImGuiIO& io = ImGui::GetIO();
    if (ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows) && io.KeyCtrl) {
        if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Z))) _history.undo();
        if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Y))) _history.redo();
    }
    ImGui::End();
}

void TransferFunctionEditor::drawToolbar()
{
    int c = int(channel);
    const char* names[] = {"Colour map", "R", "G", "B", "Opacity"};
    for (int i = 0; i < 5; ++i) {
        if (i) ImGui::SameLine();
        ImGui::RadioButton(names[i], &c, i);
    }
    channel = Channel(c);
    ImGui::SameLine();
    ImGui::Checkbox("log histogram", &logHistogram);
    ImGui::SameLine();
    ImGui::Checkbox("log opacity", &logOpacity);
    ImGui::SameLine();
    bool smooth = _tf->interpolation() == TransferFunction::Interpolation::MonotoneCubic;
    if (ImGui::Checkbox("smooth", &smooth)) {
        _tf->setInterpolation(smooth ? TransferFunction::Interpolation::MonotoneCubic : TransferFunction::Interpolation::Linear);
        _history.record();
    }

    ImGui::BeginDisabled(!_history.canUndo());
    if (ImGui::Button("Undo")) _history.undo();
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!_history.canRedo());
    if (ImGui::Button("Redo")) _history.redo();
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::SetNextItemWidth(170);
    if (ImGui::BeginCombo("##preset", "Preset...")) {
        for (const std::string& name : presetNames())
            if (ImGui::Selectable(name.c_str())) applyPreset(name);
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    if (ImGui::Button("Zoom to TF")) viewMin = _tf->domainMin(), viewMax = _tf->domainMax();
    if (_volume) {
        ImGui::SameLine();
        if (ImGui::Button("Zoom to data")) std::tie(viewMin, viewMax) = _volume->valueRange();
    }

    // The canvas's value range (zoom) and the TF's value window.
    double view[2] = {viewMin, viewMax};
    ImGui::SetNextItemWidth(240);
    if (ImGui::InputScalarN("view", ImGuiDataType_Double, view, 2, nullptr, nullptr, "%.6g") && view[1] > view[0])
        viewMin = view[0], viewMax = view[1];
    ImGui::SameLine();
    double window[2] = {_tf->domainMin(), _tf->domainMax()};
    ImGui::SetNextItemWidth(240);
    if (ImGui::InputScalarN("TF window", ImGuiDataType_Double, window, 2, nullptr, nullptr, "%.6g",
                            ImGuiInputTextFlags_EnterReturnsTrue) &&
        window[1] > window[0]) {
        _tf->setDomain(window[0], window[1]);
        _history.record();
    }
}

void TransferFunctionEditor::drawCanvas()
{
    const ImVec2 size(std::max(100.0f, ImGui::GetContentRegionAvail().x), 200.0f);
    _canvasMin = ImGui::GetCursorScreenPos();
    _canvasMax = ImVec2(_canvasMin.x + size.x, _canvasMin.y + size.y);
    ImGui::InvisibleButton("canvas", size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(_canvasMin, _canvasMax, IM_COL32(25, 25, 28, 255));
    draw->PushClipRect(_canvasMin, _canvasMax, true);

    // The histogram behind the curves.
    if (_volume) {
        const Histogram h = _volume->histogram(256);
        std::uint64_t most = 1;
        for (std::uint64_t n : h.counts) most = std::max(most, n);
        for (std::size_t i = 0; i < h.counts.size(); ++i) {
            const double lo = h.minValue + double(i) * h.binWidth(), hi = lo + h.binWidth();
            const double t = logHistogram ? std::log1p(double(h.counts[i])) / std::log1p(double(most))
                                          : double(h.counts[i]) / double(most);
            const float x0 = screenPosition(lo, 0).x, x1 = std::max(x0 + 1.0f, screenPosition(hi, 0).x);
            draw->AddRectFilled(ImVec2(x0, float(_canvasMax.y - t * size.y)), ImVec2(x1, _canvasMax.y),
                                IM_COL32(85, 85, 90, 255));
        }
    }

    // The curves, one point per pixel column; in colour-map mode a colour strip at the bottom.
    std::array<std::vector<ImVec2>, 4> curves;
    for (float x = _canvasMin.x; x <= _canvasMax.x; x += 1.0f) {
        const osg::Vec4 rgba = _tf->evaluate(valueAt(ImVec2(x, 0)).first);
        for (int k = 0; k < 4; ++k) {
            const float y = float(_canvasMax.y - (k == 3 ? toAxis(rgba[k]) : std::clamp(double(rgba[k]), 0.0, 1.0)) * size.y);
            curves[std::size_t(k)].push_back(ImVec2(x, y));
        }
        if (channel == Channel::ColourMap)
            draw->AddLine(ImVec2(x, _canvasMax.y - 10), ImVec2(x, _canvasMax.y), colourOf(rgba));
    }
    const ImU32 curveColours[4] = {IM_COL32(230, 60, 60, 255), IM_COL32(60, 200, 60, 255), IM_COL32(70, 110, 240, 255),
                                   IM_COL32(240, 240, 240, 255)};
    for (int k = 0; k < 4; ++k) {
        const bool active = channel == Channel(k + 1) || (k == 3 && channel == Channel::ColourMap);
        if (channel == Channel::ColourMap && k < 3) continue;  // the strip shows the colour
        draw->AddPolyline(curves[std::size_t(k)].data(), int(curves[std::size_t(k)].size()),
                          active ? curveColours[k] : (curveColours[k] & 0x60FFFFFFu), ImDrawFlags_None, active ? 2.0f : 1.0f);
    }

    // The control points on the active curve.
    for (const auto& [value, rgba] : _tf->points()) {
        const ImVec2 p = screenPosition(value, levelOf(rgba));
        const ImU32 fill = channel == Channel::ColourMap ? colourOf(rgba)
                                                         : curveColours[channel == Channel::Alpha ? 3 : int(channel) - 1];
        draw->AddCircleFilled(p, pointRadius, fill);
        draw->AddCircle(p, pointRadius + 1.0f, _haveSelection && value == _selected ? IM_COL32(255, 220, 0, 255)
                                                                                       : IM_COL32(0, 0, 0, 255),
                        0, 1.5f);
    }
    draw->PopClipRect();
}

void TransferFunctionEditor::handleMouse()
{
    const ImGuiIO& io = ImGui::GetIO();
    const bool hovered = ImGui::IsItemHovered();
    auto hit = [&](const ImVec2& m) -> std::optional<double> {
        std::optional<double> best;
        float nearest = hitRadius * hitRadius;
        for (const auto& [value, rgba] : _tf->points()) {
            const ImVec2 p = screenPosition(value, levelOf(rgba));
            const float d = (p.x - m.x) * (p.x - m.x) + (p.y - m.y) * (p.y - m.y);
            if (d <= nearest) nearest = d, best = value;
        }
        return best;
    };

    if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        if (const auto found = hit(io.MousePos)) {
            _dragValue = *found;
        } else {  // a new point on the active curve; the other channels keep their curves
            const auto [value, level] = valueAt(io.MousePos);
            osg::Vec4 rgba = _tf->evaluate(value);
            setLevel(rgba, level);
            _tf->setPoint(value, rgba);
            _dragValue = value;
        }
        _dragging = true;
        _haveSelection = true;
        _selected = _dragValue;
    } else if (_dragging && ImGui::IsMouseDown(ImGuiMouseButton_Left) &&
               (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
        auto [value, level] = valueAt(io.MousePos);
        const TransferFunction::Points& points = _tf->points();
        const auto here = points.find(_dragValue);
        if (here != points.end()) {
            const double gap = (viewMax - viewMin) * 1e-6;  // never onto or past a neighbour
            if (here != points.begin()) value = std::max(value, std::prev(here)->first + gap);
            if (std::next(here) != points.end()) value = std::min(value, std::next(here)->first - gap);
            osg::Vec4 rgba = here->second;
            setLevel(rgba, level);
            if (value != _dragValue) _tf->removePoint(_dragValue);
            _tf->setPoint(value, rgba);
            _dragValue = _selected = value;
        }
    }
    if (_dragging && ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
        _dragging = false;
        _history.record();
    }
    if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
        if (const auto found = hit(io.MousePos)) {
            _tf->removePoint(*found);
            if (_haveSelection && _selected == *found) _haveSelection = false;
            _history.record();
        }
    }
}

void TransferFunctionEditor::drawFileRow()
{
    char buffer[1024];
    const std::size_t n = std::min(path.size(), sizeof(buffer) - 1);
    path.copy(buffer, n);
    buffer[n] = '\0';
    ImGui::SetNextItemWidth(300);
    if (ImGui::InputText("file", buffer, sizeof(buffer))) path = buffer;
    ImGui::SameLine();
    std::string error;
    if (ImGui::Button("Load")) load(error);
    ImGui::SameLine();
    if (ImGui::Button("Save")) save(error);
    if (!_message.empty()) ImGui::TextWrapped("%s", _message.c_str());
}

bool TransferFunctionEditor::save(std::string& error)
{
    try {
        writeTransferFunctionFile(*_tf, path);
        _message = "saved " + path;
        return true;
    } catch (const std::exception& e) {
        error = e.what();
        _message = "not saved: " + error;
        return false;
    }
}

bool TransferFunctionEditor::load(std::string& error)
{
    try {
        osg::ref_ptr<TransferFunction> loaded = readTransferFunctionFile(path);
        _tf->assign(*loaded);
        _history.record();
        _haveSelection = false;
        _message = "loaded " + path;
        return true;
    } catch (const std::exception& e) {
        error = e.what();
        _message = "not loaded: " + error;
        return false;
    }
}

bool TransferFunctionEditor::applyPreset(const std::string& name)
{
    for (const Preset& p : presets()) {
        if (p.name != name) continue;
        const double lo = _tf->domainMin(), hi = _tf->domainMax();
        _tf->clearPoints();
        for (const auto& [t, rgba] : p.points) _tf->setPoint(lo + t * (hi - lo), rgba);
        _tf->setDomain(lo, hi);
        _history.record();
        _haveSelection = false;
        return true;
    }
    return false;
}

}  // namespace volren
