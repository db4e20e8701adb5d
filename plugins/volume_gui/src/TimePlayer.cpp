#include <volume_gui/TimePlayer.h>

#include <volume_model/DefaultScene.h>
#include <volume_model/VolumeNode.h>

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace volren {

TimePlayer::TimePlayer(osg::Node& root) : _series(root)
{
    for (VolumeNode* node : findVolumeNodes(root))
        if (node->getVolume() && node->getVolume()->frames() > 1) {
            _current = node->shownTimePoint();
            break;
        }
}

void TimePlayer::show(int t)
{
    _series.show(t);
    _current = t;
    if (_prefetcher) _prefetcher->ahead(t);
}

void TimePlayer::setPrefetcher(TimePrefetcher* prefetcher)
{
    _prefetcher = prefetcher;
    if (_prefetcher) _prefetcher->ahead(_current);
}

bool TimePlayer::advance(double seconds)
{
    if (!playing || timePoints() < 2 || !(framesPerSecond > 0.0) || !(seconds > 0.0)) return false;
    _carried += seconds;
    const double period = 1.0 / framesPerSecond;
    if (_carried < period) return false;
    const auto steps = static_cast<long long>(std::floor(_carried / period));
    _carried -= double(steps) * period;
    show(int((_current + steps) % timePoints()));
    return true;
}

void TimePlayer::draw()
{
    if (timePoints() < 2) return;
    ImGui::SetNextWindowSize(ImVec2(400, 90), ImGuiCond_FirstUseEver);
    ImGui::Begin("Time");
    int t = _current;
    if (ImGui::SliderInt("time point", &t, 0, timePoints() - 1) && t != _current) show(t);
    if (ImGui::Button(playing ? "pause" : "play")) {
        playing = !playing;
        _carried = 0.0;
    }
    ImGui::SameLine();
    float rate = float(framesPerSecond);
    if (ImGui::SliderFloat("time points/s", &rate, 0.5f, 60.0f, "%.1f", ImGuiSliderFlags_Logarithmic))
        framesPerSecond = std::max(0.5f, rate);
    ImGui::End();
    advance(ImGui::GetIO().DeltaTime);
}

}  // namespace volren
