// The loader threads' side of a BrickStreamer (BrickStreamer.h): reading one brick with its
// one-voxel border from the volume's levels, edges repeated, constant bricks recognised.
#include <volume_renderer/BrickStreamer.h>

#include <osg/Notify>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace volren {

BrickStreamer::Loaded BrickStreamer::load(const BrickId& id) const
{
    const osg::Vec3i& d = _state.layout.levels[std::size_t(id.level)].dims;
    const osg::Vec3i origin = id.brick * _budget.brickSize - osg::Vec3i(1, 1, 1);
    osg::Vec3i lo, hi;
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::clamp(origin[a], 0, d[a] - 1);
        hi[a] = std::clamp(origin[a] + _texels, lo[a] + 1, d[a]);
    }
    const osg::Vec3i size = hi - lo;
    const std::size_t bytes = voxelSize(_source.type);
    std::vector<std::uint8_t> region(std::size_t(size.x()) * size.y() * size.z() * bytes);
    _source.read(id.level, lo, size, region.data());
    Loaded out{id, std::vector<std::uint8_t>(_slotBytes), false, 0.0f};
    // Voxels past the level's edges repeat the edge voxels (as clamp-to-edge would).
    for (int z = 0; z < _texels; ++z)
        for (int y = 0; y < _texels; ++y) {
            const int rz = std::clamp(origin.z() + z, lo.z(), hi.z() - 1) - lo.z();
            const int ry = std::clamp(origin.y() + y, lo.y(), hi.y() - 1) - lo.y();
            const std::uint8_t* row = region.data() + (std::size_t(rz) * size.y() + ry) * size.x() * bytes;
            std::uint8_t* dst = out.texels.data() + (std::size_t(z) * _texels + y) * _texels * bytes;
            for (int x = 0; x < _texels; ++x)
                std::memcpy(dst + std::size_t(x) * bytes,
                            row + std::size_t(std::clamp(origin.x() + x, lo.x(), hi.x() - 1) - lo.x()) * bytes, bytes);
        }
    if (_source.constantBricks) {
        const std::size_t n = out.texels.size() / bytes;
        bool same = true;
        for (std::size_t i = 1; i < n && same; ++i) same = std::memcmp(&out.texels[i * bytes], out.texels.data(), bytes) == 0;
        if (same) {
            out.constant = true;
            out.value = float(texelValue(_source.type, out.texels.data(), 0));
            out.texels.clear();
        }
    }
    return out;
}

void BrickStreamer::loaderLoop()
{
    for (;;) {
        BrickId id;
        {
            std::unique_lock<std::mutex> lock(_mutex);
            _work.wait(lock, [this] { return _stop || !_queue.empty(); });
            if (_stop) return;
            id = _queue.front();
            _queue.pop_front();
            ++_busy;
        }
        Loaded loaded;
        try {
            loaded = load(id);
        } catch (const std::exception& e) {
            // The file failed under the reader (truncated, removed): the brick shows nothing.
            OSG_WARN << "volren: cannot read brick " << id.brick.x() << "," << id.brick.y() << "," << id.brick.z()
                     << " of level " << id.level << " (drawn empty): " << e.what() << std::endl;
            loaded = Loaded{id, {}, true, std::nanf("")};
        }
        {
            std::lock_guard<std::mutex> lock(_mutex);
            _done.push_back(std::move(loaded));
            ++_loaded;
            --_busy;
        }
        _idle.notify_all();
    }
}

}  // namespace volren
