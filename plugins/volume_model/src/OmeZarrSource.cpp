#include <volume_model/LazyOpening.h>
#include <volume_model/LoadProgress.h>
#include <volume_model/MeanReduction.h>
#include <volume_model/OmeZarrSource.h>

#include <algorithm>
#include <climits>
#include <cstring>
#include <stdexcept>

namespace volren {

namespace {

std::string dimsText(const osg::Vec3i& d)
{
    return std::to_string(d.x()) + "x" + std::to_string(d.y()) + "x" + std::to_string(d.z());
}

std::size_t voxels(const osg::Vec3i& d) { return std::size_t(d.x()) * std::size_t(d.y()) * std::size_t(d.z()); }

}  // namespace

OmeZarrSource::OmeZarrSource(const std::string& path, std::size_t cacheBytes, std::uint64_t previewBytes, int channel, int frame,
                             const osgDB::Options* options)
    : _image(std::make_unique<OmeZarrImage>(path)), _channel(channel), _frame(frame), _cacheBytes(cacheBytes)
{
    const std::string& file = _image->path();
    if (channel < 0 || std::uint64_t(channel) >= _image->channels())
        throw std::runtime_error(file + ": channel " + std::to_string(channel) + " does not exist (" + std::to_string(_image->channels()) + " channels)");
    if (frame < 0 || std::uint64_t(frame) >= _image->frames())
        throw std::runtime_error(file + ": time point " + std::to_string(frame) + " does not exist (" + std::to_string(_image->frames()) +
                                 " time points)");
    _type = _image->level(0).voxelType();
    for (std::size_t i = 0; i < _image->levelCount(); ++i) {
        const std::array<std::uint64_t, 3> s = _image->size(i);
        for (std::uint64_t v : s)
            if (v > std::uint64_t(INT_MAX))
                throw std::runtime_error(file + ": level " + std::to_string(i) + " has " + std::to_string(v) + " voxels along an axis (at most 2^31 - 1)");
        _dims.emplace_back(int(s[0]), int(s[1]), int(s[2]));
    }
    const osg::Vec3i coarsest = _dims.back();
    for (int k = 1; k < meanLevelCount(coarsest); ++k) _dims.push_back(meanLevelDims(coarsest, k));
    _reduced.resize(_dims.size());
    reduceCoarsestLevel(previewBytes, options);
}

OmeZarrSource::~OmeZarrSource() = default;

osg::Vec3i OmeZarrSource::levelDims(int level) const
{
    if (level < 0 || level >= levelCount())
        throw std::out_of_range(file() + ": level " + std::to_string(level) + " of " + std::to_string(levelCount()));
    return _dims[std::size_t(level)];
}

osg::Vec3d OmeZarrSource::spacing() const
{
    const std::array<double, 3> s = _image->spacing(0);
    return {s[0], s[1], s[2]};
}

std::size_t OmeZarrSource::residentBytes() const
{
    std::size_t bytes = 0;
    for (const std::vector<std::uint8_t>& level : _reduced) bytes += level.size();
    std::lock_guard<std::mutex> lock(_cacheMutex);
    return bytes + _cachedBytes;
}

ZarrBox OmeZarrSource::box(int level, const osg::Vec3i& origin, const osg::Vec3i& size) const
{
    const std::size_t n = _image->level(std::size_t(level)).dimensions();
    ZarrBox b;
    b.begin.assign(n, 0);
    b.end.assign(n, 1);
    if (_image->timeAxis() >= 0) {
        b.begin[std::size_t(_image->timeAxis())] = std::uint64_t(_frame);
        b.end[std::size_t(_image->timeAxis())] = std::uint64_t(_frame) + 1;
    }
    if (_image->channelAxis() >= 0) {
        b.begin[std::size_t(_image->channelAxis())] = std::uint64_t(_channel);
        b.end[std::size_t(_image->channelAxis())] = std::uint64_t(_channel) + 1;
    }
    for (int a = 0; a < 3; ++a)
        if (const int axis = _image->spaceAxis(a); axis >= 0) {
            b.begin[std::size_t(axis)] = std::uint64_t(origin[a]);
            b.end[std::size_t(axis)] = std::uint64_t(origin[a]) + std::uint64_t(size[a]);
        }
    return b;
}

OmeZarrSource::Chunk OmeZarrSource::chunk(int level, const std::vector<std::uint64_t>& index) const
{
    ChunkKey key(level, index);
    if (_cacheBytes > 0) {
        std::lock_guard<std::mutex> lock(_cacheMutex);
        if (const auto found = _cached.find(key); found != _cached.end()) {
            _lru.splice(_lru.begin(), _lru, found->second);
            return found->second->second;
        }
    }
    // Decoded outside the lock: threads decode different chunks at once (rarely the same one twice).
    Chunk data = std::make_shared<const std::vector<std::uint8_t>>(_image->level(std::size_t(level)).readChunk(index));
    ++_decodes;
    if (_cacheBytes > 0 && data->size() <= _cacheBytes) {
        std::lock_guard<std::mutex> lock(_cacheMutex);
        if (_cached.find(key) == _cached.end()) {
            _lru.emplace_front(key, data);
            _cached.emplace(std::move(key), _lru.begin());
            _cachedBytes += data->size();
            while (_cachedBytes > _cacheBytes) {
                _cachedBytes -= _lru.back().second->size();
                _cached.erase(_lru.back().first);
                _lru.pop_back();
            }
        }
    }
    return data;
}

void OmeZarrSource::readFileRegion(int level, const osg::Vec3i& origin, const osg::Vec3i& size, std::uint8_t* out) const
{
    const ZarrArray& array = _image->level(std::size_t(level));
    const ZarrArrayMetadata& m = array.metadata();
    const std::size_t n = array.dimensions(), vb = array.voxelBytes();
    std::vector<std::uint64_t> stride(n, 1);
    for (std::size_t d = n - 1; d-- > 0;) stride[d] = stride[d + 1] * m.chunks[d + 1];
    // Channel and time point: fixed chunk index and offset within the chunk.
    std::vector<std::uint64_t> index(n, 0);
    std::uint64_t fixedOffset = 0;
    for (const auto& [axis, value] : {std::pair(_image->timeAxis(), _frame), std::pair(_image->channelAxis(), _channel)})
        if (axis >= 0) {
            index[std::size_t(axis)] = std::uint64_t(value) / m.chunks[std::size_t(axis)];
            fixedOffset += std::uint64_t(value) % m.chunks[std::size_t(axis)] * stride[std::size_t(axis)];
        }
    int axes[3];
    std::uint64_t edge[3], step[3], first[3], last[3];
    for (int a = 0; a < 3; ++a) {
        axes[a] = _image->spaceAxis(a);
        edge[a] = axes[a] >= 0 ? m.chunks[std::size_t(axes[a])] : 1;
        step[a] = axes[a] >= 0 ? stride[std::size_t(axes[a])] : 0;
        first[a] = std::uint64_t(origin[a]) / edge[a];
        last[a] = std::uint64_t(origin[a] + size[a] - 1) / edge[a];
    }
    std::uint64_t c[3];
    for (c[2] = first[2]; c[2] <= last[2]; ++c[2])
        for (c[1] = first[1]; c[1] <= last[1]; ++c[1])
            for (c[0] = first[0]; c[0] <= last[0]; ++c[0]) {
                std::int64_t lo[3], hi[3], corner[3];
                for (int a = 0; a < 3; ++a) {
                    if (axes[a] >= 0) index[std::size_t(axes[a])] = c[a];
                    corner[a] = std::int64_t(c[a] * edge[a]);
                    lo[a] = std::max<std::int64_t>(origin[a], corner[a]);
                    hi[a] = std::min<std::int64_t>(origin[a] + size[a], corner[a] + std::int64_t(edge[a]));
                }
                const Chunk data = chunk(level, index);
                const std::uint8_t* src = data->data();
                const std::size_t row = std::size_t(hi[0] - lo[0]);
                for (std::int64_t z = lo[2]; z < hi[2]; ++z)
                    for (std::int64_t y = lo[1]; y < hi[1]; ++y) {
                        const std::uint64_t from = fixedOffset + std::uint64_t(z - corner[2]) * step[2] + std::uint64_t(y - corner[1]) * step[1] +
                                                   std::uint64_t(lo[0] - corner[0]) * step[0];
                        std::uint8_t* to = out + ((std::size_t(z - origin.z()) * std::size_t(size.y()) + std::size_t(y - origin.y())) * std::size_t(size.x()) +
                                                  std::size_t(lo[0] - origin.x())) * vb;
                        if (step[0] == 1)
                            std::memcpy(to, src + from * vb, row * vb);
                        else
                            for (std::size_t x = 0; x < row; ++x) std::memcpy(to + x * vb, src + (from + x * step[0]) * vb, vb);
                    }
            }
}

void OmeZarrSource::reduceCoarsestLevel(std::uint64_t previewBytes, const osgDB::Options* options)
{
    const int base = fileLevelCount() - 1, last = levelCount() - 1;
    if (last == base) return;
    const std::size_t vb = voxelSize(_type);
    int keepFrom = last;
    for (int l = last; l > base && std::uint64_t(voxels(_dims[std::size_t(l)]) * vb) <= previewBytes; --l) keepFrom = l;
    for (int l = keepFrom; l <= last; ++l) _reduced[std::size_t(l)].resize(voxels(_dims[std::size_t(l)]) * vb);

    // One pass over the coarsest file level, z slabs of whole chunk layers when they are not huge.
    const osg::Vec3i d = _dims[std::size_t(base)];
    const std::size_t slice = std::size_t(d.x()) * std::size_t(d.y());
    const ZarrArray& array = _image->level(std::size_t(base));
    const int chunkZ = _image->spaceAxis(2) >= 0 ? int(std::min<std::uint64_t>(array.metadata().chunks[std::size_t(_image->spaceAxis(2))], INT_MAX)) : 1;
    int slab = std::uint64_t(chunkZ) * slice * vb <= (std::uint64_t(256) << 20) ? chunkZ : int(std::max<std::uint64_t>(1, (std::uint64_t(16) << 20) / (slice * vb)));
    slab = std::min(slab, d.z());
    std::vector<std::uint8_t> raw(std::size_t(slab) * slice * vb);
    std::vector<float> values(slice);
    MeanReductionStream stream(d, last - base, {0, 0, 0}, _dims.back());
    const MeanReductionStream::Sink keep = [&](int k, int z, const float* reduced) {
        const int level = base + k;
        if (level < keepFrom) return;
        const osg::Vec3i& ld = _dims[std::size_t(level)];
        const std::size_t n = std::size_t(ld.x()) * std::size_t(ld.y());
        floatToStored(_type, reduced, n, _reduced[std::size_t(level)].data() + std::size_t(z) * n * vb);
    };
    for (int z0 = 0; z0 < d.z(); z0 += slab) {
        const int n = std::min(slab, d.z() - z0);
        array.readRegion(box(base, {0, 0, z0}, {d.x(), d.y(), n}), raw.data());
        for (int k = 0; k < n; ++k) {
            storedToFloat(_type, raw.data() + std::size_t(k) * slice * vb, slice, values.data());
            stream.push(values.data(), keep);
        }
        if (!reportLoadProgress(options, z0 + n, d.z())) throw std::runtime_error(file() + ": cancelled");
    }
}

void OmeZarrSource::read(int level, const osg::Vec3i& origin, const osg::Vec3i& size, std::uint8_t* out) const
{
    const osg::Vec3i ld = levelDims(level);
    for (int a = 0; a < 3; ++a)
        if (origin[a] < 0 || size[a] < 1 || origin[a] > ld[a] - size[a])
            throw std::invalid_argument(file() + ": region " + dimsText(origin) + " + " + dimsText(size) + " is not inside level " +
                                        std::to_string(level) + " (" + dimsText(ld) + ")");
    const int base = fileLevelCount() - 1;
    if (level <= base) {
        readFileRegion(level, origin, size, out);
        return;
    }
    const std::size_t vb = voxelSize(_type);
    if (const std::vector<std::uint8_t>& resident = _reduced[std::size_t(level)]; !resident.empty()) {
        const std::size_t row = std::size_t(size.x()) * vb;
        for (int z = 0; z < size.z(); ++z)
            for (int y = 0; y < size.y(); ++y)
                std::memcpy(out + (std::size_t(z) * std::size_t(size.y()) + std::size_t(y)) * row,
                            resident.data() + ((std::size_t(origin.z() + z) * std::size_t(ld.y()) + std::size_t(origin.y() + y)) * std::size_t(ld.x()) +
                                               std::size_t(origin.x())) * vb,
                            row);
        return;
    }
    // A reduced level that is not resident: reduced from the region of the coarsest file level.
    MeanReductionStream stream(_dims[std::size_t(base)], level - base, origin, size);
    const osg::Vec3i baseOrigin = stream.regionOrigin(0), baseSize = stream.regionSize(0);
    const std::size_t baseSlice = std::size_t(baseSize.x()) * std::size_t(baseSize.y()), outSlice = std::size_t(size.x()) * std::size_t(size.y());
    const int slab = int(std::clamp<std::uint64_t>((std::uint64_t(8) << 20) / (baseSlice * vb), 1, std::uint64_t(baseSize.z())));
    std::vector<std::uint8_t> raw(std::size_t(slab) * baseSlice * vb);
    std::vector<float> values(baseSlice);
    const MeanReductionStream::Sink collect = [&](int k, int z, const float* slice) {
        if (base + k == level) floatToStored(_type, slice, outSlice, out + std::size_t(z - origin.z()) * outSlice * vb);
    };
    for (int z0 = 0; z0 < baseSize.z(); z0 += slab) {
        const int n = std::min(slab, baseSize.z() - z0);
        readFileRegion(base, {baseOrigin.x(), baseOrigin.y(), baseOrigin.z() + z0}, {baseSize.x(), baseSize.y(), n}, raw.data());
        for (int k = 0; k < n; ++k) {
            storedToFloat(_type, raw.data() + std::size_t(k) * baseSlice * vb, baseSlice, values.data());
            stream.push(values.data(), collect);
        }
    }
}

}  // namespace volren
