#include <volume_gui/ChannelPanel.h>

#include <volume_model/ChannelDisplay.h>

#include <imgui.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace volren {

namespace {

/// Throws std::out_of_range unless `c` is a channel of `node`'s volume (`count` of them).
void checkChannel(const VolumeNode& node, int c, int count)
{
    if (c < 0 || c >= count)
        throw std::out_of_range("volume '" + node.getName() + "' has no channel " + std::to_string(c) + " (it has " +
                                std::to_string(count) + ", counted from 0)");
}

}  // namespace

ChannelPanel::ChannelPanel(VolumeNode* node) : _node(node) {}

int ChannelPanel::channels() const
{
    return _node->getVolume() ? _node->getVolume()->channels() : 0;
}

void ChannelPanel::select(int c)
{
    checkChannel(*_node, c, channels());
    _selected = c;
}

TransferFunction* ChannelPanel::ownTransferFunction(int c)
{
    checkChannel(*_node, c, channels());
    if (_node->channels.size() < std::size_t(channels())) _node->channels.resize(std::size_t(channels()));
    ChannelDisplay& display = _node->channels[std::size_t(c)];
    if (!display.transferFunction) {
        display.transferFunction = new TransferFunction;
        if (_node->getTransferFunction()) display.transferFunction->assign(*_node->getTransferFunction());
    }
    return display.transferFunction.get();
}

TransferFunctionEditor& ChannelPanel::editor()
{
    TransferFunction* tf = ownTransferFunction(_selected);
    if (_editors.size() < std::size_t(channels())) _editors.resize(std::size_t(channels()));
    std::unique_ptr<TransferFunctionEditor>& e = _editors[std::size_t(_selected)];
    if (!e) e = std::make_unique<TransferFunctionEditor>(tf, _node->channelNode(_selected)->getVolume());  // its histogram
    return *e;
}

ChannelPanel::ColourWindow ChannelPanel::colourWindow(int c) const
{
    checkChannel(*_node, c, channels());
    const TransferFunction* tf = std::size_t(c) < _node->channels.size() && _node->channels[std::size_t(c)].transferFunction
                                     ? _node->channels[std::size_t(c)].transferFunction.get()
                                     : _node->getTransferFunction();
    ColourWindow cw;
    if (!tf || tf->points().empty()) return cw;
    const auto& points = tf->points();
    const osg::Vec4& last = points.rbegin()->second;
    cw.colour.set(last.r(), last.g(), last.b());
    float top = 0.0f;
    for (const auto& [value, rgba] : points) top = std::max(top, rgba.a());
    cw.opacity = top;
    cw.low = points.begin()->first;
    for (const auto& [value, rgba] : points)
        if (rgba.a() <= 0.0f) cw.low = value;
        else break;
    cw.high = points.rbegin()->first;
    for (const auto& [value, rgba] : points)
        if (rgba.a() >= top && value > cw.low) {
            cw.high = value;
            break;
        }
    return cw;
}

void ChannelPanel::setColourWindow(int c, const ColourWindow& cw, bool record)
{
    if (!(cw.low < cw.high)) throw std::invalid_argument("channel window: low must be below high");
    if (!(cw.opacity >= 0.0 && cw.opacity <= 1.0)) throw std::invalid_argument("channel window: opacity must be in [0, 1]");
    TransferFunction* tf = ownTransferFunction(c);
    const int keep = _selected;
    _selected = c;
    TransferFunctionEditor& e = editor();  // its history records the step
    _selected = keep;
    tf->assign(*colourWindowTransferFunction(cw.colour, cw.low, cw.high, cw.opacity));
    if (record) e.history().record();
}

void ChannelPanel::draw()
{
    if (channels() == 0) return;
    ImGui::SetNextWindowSize(ImVec2(400, 60.0f + 70.0f * float(channels())), ImGuiCond_FirstUseEver);
    ImGui::Begin("Channels");
    const Volume* volume = _node->getVolume();
    for (int c = 0; c < channels(); ++c) {
        ImGui::PushID(c);
        if (_node->channels.size() < std::size_t(channels())) _node->channels.resize(std::size_t(channels()));
        ChannelDisplay& display = _node->channels[std::size_t(c)];
        const std::string name = std::size_t(c) < volume->channelHints.size() && !volume->channelHints[std::size_t(c)].name.empty()
                                     ? volume->channelHints[std::size_t(c)].name
                                     : "channel " + std::to_string(c);
        if (ImGui::RadioButton("edit", _selected == c)) _selected = c;
        ImGui::SameLine();
        ImGui::Checkbox(name.c_str(), &display.visible);
        ColourWindow cw = colourWindow(c);
        float colour[3] = {cw.colour.x(), cw.colour.y(), cw.colour.z()};
        const auto [lo, hi] = volume->valueRange();
        float window[2] = {float(cw.low), float(cw.high)};
        // A drag changes the TF every frame and is one undo step when it ends.
        bool changed = ImGui::ColorEdit3("colour", colour, ImGuiColorEditFlags_NoInputs);
        bool finished = ImGui::IsItemDeactivatedAfterEdit();
        ImGui::SameLine();
        changed |= ImGui::DragFloatRange2("window", &window[0], &window[1], float((hi - lo) / 500.0), float(lo), float(hi));
        finished |= ImGui::IsItemDeactivatedAfterEdit();
        float scale = float(display.opacity);
        if (ImGui::SliderFloat("opacity scale", &scale, 0.0f, 10.0f, "%.2f", ImGuiSliderFlags_Logarithmic))
            display.opacity = std::max(0.0f, scale);
        if (_dragging.size() < std::size_t(channels())) _dragging.resize(std::size_t(channels()), false);
        if (changed && window[0] < window[1]) {
            cw.colour.set(colour[0], colour[1], colour[2]);
            cw.low = window[0];
            cw.high = window[1];
            setColourWindow(c, cw, false);
            _dragging[std::size_t(c)] = true;
        }
        if (finished && _dragging[std::size_t(c)]) {  // the drag's one undo step (a menu action alone edits nothing)
            const int keep = _selected;
            _selected = c;
            editor().history().record();
            _selected = keep;
            _dragging[std::size_t(c)] = false;
        }
        ImGui::PopID();
    }
    ImGui::End();
    ImGui::SetNextWindowPos(ImVec2(10.0f, 80.0f + 70.0f * float(channels())), ImGuiCond_FirstUseEver);
    editor().draw();
}

}  // namespace volren
