#pragma once
#include <volume_model/VolumeNode.h>

#include <osg/Node>

#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <thread>
#include <vector>

namespace volren {

/// Copies the time points after the shown one ahead of time on a background thread, within a
/// RAM budget, for the time-series nodes below a scene root (those whose volumes have several
/// time points): after each step (ahead()), the blocks the nodes draw of the following time
/// points (wrapping after the last) are copied out (VolumeNode::prefetch) until the next time
/// point would pass the budget; blocks of time points no longer ahead are dropped, except the
/// shown one's, which the next cull takes (and which count against the budget until then). A
/// step to a prefetched time point then only uploads. The series' volumes stay whole in memory;
/// the budget bounds the copies only.
class TimePrefetcher
{
public:
    /// Prefetches for the series below `root` within `budgetBytes` of copies.
    TimePrefetcher(osg::Node& root, std::size_t budgetBytes);
    ~TimePrefetcher();
    TimePrefetcher(const TimePrefetcher&) = delete;
    TimePrefetcher& operator=(const TimePrefetcher&) = delete;

    /// Starts copying the time points after `shown` (call after each step, on the thread that
    /// edits the nodes: it reads which channels they draw now); returns at once.
    void ahead(int shown);
    /// Waits until the copies ahead() asked for are made (tests, benchmarks).
    void wait();
    /// Bytes of prefetched copies held now, over every node.
    std::size_t heldBytes() const;
    std::size_t budget() const { return _budget; }  ///< the budget in bytes

private:
    /// What ahead() saw of a node: the channels it draws and their bytes per time point.
    struct Drawn
    {
        osg::ref_ptr<VolumeNode> node;
        std::vector<int> channels;
        std::size_t bytes = 0;  ///< of one time point's blocks of those channels
        bool blocksAtZero = false;  ///< whether time point 0 is drawn as blocks (several channels)
        int frames = 1;             ///< its volume's time points (later ones show its last)
    };
    void run();
    void fill(int shown, const std::vector<Drawn>& drawn);

    std::vector<osg::ref_ptr<VolumeNode>> _nodes;
    std::vector<Drawn> _drawn;  ///< ahead()'s snapshot for the worker
    int _timePoints = 1;
    std::size_t _budget;
    mutable std::mutex _mutex;
    std::condition_variable _changed;
    int _wanted = -1;  ///< the time point to prefetch after (-1: none asked)
    bool _busy = false, _stop = false;
    std::thread _worker;
};

}  // namespace volren
