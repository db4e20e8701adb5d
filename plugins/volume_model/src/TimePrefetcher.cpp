#include <volume_model/TimePrefetcher.h>

#include <volume_model/DefaultScene.h>

#include <osg/Notify>

#include <algorithm>

namespace volren {

TimePrefetcher::TimePrefetcher(osg::Node& root, std::size_t budgetBytes) : _budget(budgetBytes)
{
    for (VolumeNode* node : findVolumeNodes(root))
        if (node->getVolume() && node->getVolume()->frames() > 1 && !node->getVolume()->fullResolution()) {
            _nodes.push_back(node);
            _timePoints = std::max(_timePoints, node->getVolume()->frames());
        }
    if (!_nodes.empty()) _worker = std::thread([this] { run(); });
}

TimePrefetcher::~TimePrefetcher()
{
    {
        std::lock_guard<std::mutex> lock(_mutex);
        _stop = true;
    }
    _changed.notify_all();
    if (_worker.joinable()) _worker.join();
}

void TimePrefetcher::ahead(int shown)
{
    if (_nodes.empty()) return;
    std::vector<Drawn> drawn;
    for (const auto& node : _nodes) {
        const Volume& v = *node->getVolume();
        Drawn d{node, node->drawnChannels(), 0, node->showsChannels(), v.frames()};
        d.bytes = d.channels.size() * v.voxelCount() * voxelSize(v.type());
        drawn.push_back(std::move(d));
    }
    {
        std::lock_guard<std::mutex> lock(_mutex);
        _wanted = shown;
        _drawn = std::move(drawn);
    }
    _changed.notify_all();
}

void TimePrefetcher::wait()
{
    std::unique_lock<std::mutex> lock(_mutex);
    _changed.wait(lock, [this] { return _stop || (_wanted < 0 && !_busy); });
}

std::size_t TimePrefetcher::heldBytes() const
{
    std::size_t bytes = 0;
    for (const auto& node : _nodes) bytes += node->prefetchedBytes();
    return bytes;
}

void TimePrefetcher::run()
{
    for (;;) {
        int shown = -1;
        std::vector<Drawn> drawn;
        {
            std::unique_lock<std::mutex> lock(_mutex);
            _changed.wait(lock, [this] { return _stop || _wanted >= 0; });
            if (_stop) return;
            shown = _wanted;
            _wanted = -1;
            drawn = _drawn;
            _busy = true;
        }
        try {
            fill(shown, drawn);
        } catch (const std::exception& e) {  // memory: prefetching stops, steps copy as without it
            OSG_WARN << "volren: prefetching time points after " << shown << " stopped: " << e.what() << std::endl;
        }
        {
            std::lock_guard<std::mutex> lock(_mutex);
            _busy = false;
        }
        _changed.notify_all();
    }
}

void TimePrefetcher::fill(int shown, const std::vector<Drawn>& drawn)
{
    // The window of time points ahead that fits: each time point costs the blocks every node
    // draws of it (time point 0 of a one-channel node is drawn from its volume, not a block; a
    // node shows its last time point past its own). The shown time point's blocks may still wait
    // for the cull that takes them: they stay, and count.
    auto needed = [](const Drawn& d, int t) { return (t > 0 || d.blocksAtZero) && t < d.frames; };
    auto cost = [&](int t) {
        std::size_t bytes = 0;
        for (const Drawn& d : drawn) bytes += needed(d, t) ? d.bytes : 0;
        return bytes;
    };
    std::vector<int> window{shown};
    std::size_t planned = cost(shown);
    for (int k = 1; k < _timePoints; ++k) {
        const int t = (shown + k) % _timePoints;
        if (planned + cost(t) > _budget) break;
        planned += cost(t);
        window.push_back(t);
    }
    for (const Drawn& d : drawn)  // first, so that the budget holds throughout: what is no longer ahead or drawn
        d.node->dropPrefetched([&](int c, int t) {
            return std::find(window.begin(), window.end(), t) != window.end() && needed(d, t) &&
                   std::find(d.channels.begin(), d.channels.end(), c) != d.channels.end();
        });
    for (int t : window) {
        if (t == shown) continue;  // copied already, or copied by the cull
        {
            std::lock_guard<std::mutex> lock(_mutex);
            if (_stop || _wanted >= 0) return;  // a newer step: its window instead
        }
        for (const Drawn& d : drawn)
            if (needed(d, t)) d.node->prefetch(t, d.channels);
    }
}

}  // namespace volren
