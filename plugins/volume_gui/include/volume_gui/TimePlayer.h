#pragma once
#include <volume_model/TimePrefetcher.h>
#include <volume_model/TimeSeries.h>

#include <osg/Node>

namespace volren {

/// Time-series playback for the viewer, as an ImGui window ("Time"): a time slider, play/pause
/// and the playing frame rate. Every step goes through TimeSeries::show, so only the shown time
/// point's blocks reach the GPU.
class TimePlayer
{
public:
    /// Plays the time series below `root` (TimeSeries), from the time point its first node shows.
    explicit TimePlayer(osg::Node& root);

    /// Time points of the series (1 when there is none).
    int timePoints() const { return _series.timePoints(); }
    /// The time point shown.
    int current() const { return _current; }
    /// Shows time point `t` (and asks the prefetcher, if any, for the ones after it); throws
    /// std::out_of_range when there is none.
    void show(int t);
    /// Copies the time points ahead of each shown one with `prefetcher` (null: none); it must
    /// outlive this player. Starts with the time points after the current one.
    void setPrefetcher(TimePrefetcher* prefetcher);
    /// Advances playback by `seconds` of wall time: while playing, one time point (after the last:
    /// the first) per 1 / framesPerSecond seconds, however many frames that takes; returns
    /// whether the shown time point changed.
    bool advance(double seconds);

    bool playing = false;          ///< playback runs
    double framesPerSecond = 5.0;  ///< time points per second while playing (> 0)

    /// Draws the window into the current ImGui frame and applies this frame's changes (the
    /// slider, play/pause, the rate); advances playback by ImGui's frame time.
    void draw();

private:
    TimeSeries _series;
    TimePrefetcher* _prefetcher = nullptr;
    int _current = 0;
    double _carried = 0.0;  ///< seconds played since the last step
};

}  // namespace volren
