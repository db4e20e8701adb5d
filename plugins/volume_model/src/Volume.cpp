#include <volume_model/Volume.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace volren {

namespace {

template <typename T>
double loadAs(const std::uint8_t* p)
{
    T v;
    std::memcpy(&v, p, sizeof(T));
    return double(v);
}

double storedAt(VoxelType type, const std::uint8_t* data, std::size_t i)
{
    switch (type) {
    case VoxelType::UInt8: return data[i];
    case VoxelType::Int8: return double(static_cast<std::int8_t>(data[i]));
    case VoxelType::UInt16: return loadAs<std::uint16_t>(data + 2 * i);
    case VoxelType::Int16: return loadAs<std::int16_t>(data + 2 * i);
    case VoxelType::Float32: return loadAs<float>(data + 4 * i);
    }
    return 0.0;
}

}  // namespace

Volume::Volume() = default;

Volume::Volume(const Volume& other, const osg::CopyOp& copyop)
    : osg::Object(other, copyop),
      sourceFile(other.sourceFile),
      channelHints(other.channelHints),
      _type(other._type),
      _dims(other._dims),
      _channels(other._channels),
      _frames(other._frames),
      _spacing(other._spacing),
      _slope(other._slope),
      _intercept(other._intercept),
      _data(other._data),
      _fullResolution(other._fullResolution),
      _fullResolutionLevel(other._fullResolutionLevel)
{
}

void Volume::setFullResolution(const BrickSource* source, int level)
{
    if (source) {
        if (level < 0 || level >= source->levelCount())
            throw std::invalid_argument(source->file() + ": level " + std::to_string(level) + " is not one of its " +
                                        std::to_string(source->levelCount()) + " levels");
        if (source->levelDims(level) != _dims || source->type() != _type)
            throw std::invalid_argument(source->file() + ": level " + std::to_string(level) +
                                        " differs from the volume in memory in size or voxel type");
        const osg::Vec3d full = osg::componentMultiply(source->spacing(), osg::Vec3d(source->levelDims(0).x(), source->levelDims(0).y(), source->levelDims(0).z()));
        const osg::Vec3d mine = worldSize();
        for (int a = 0; a < 3; ++a)
            if (std::abs(full[a] - mine[a]) > 1e-6 * std::max(full[a], mine[a]))
                throw std::invalid_argument(source->file() + ": level " + std::to_string(level) +
                                            " covers another box than level 0");
    }
    _fullResolution = source;
    _fullResolutionLevel = source ? level : 0;
}

osg::Vec3i Volume::fullDims() const
{
    return _fullResolution ? _fullResolution->levelDims(0) : _dims;
}

std::uint64_t Volume::checkedVoxelCount(const osg::Vec3i& dims, std::uint64_t blocks)
{
    if (dims.x() <= 0 || dims.y() <= 0 || dims.z() <= 0)
        throw std::invalid_argument("volume dimensions must be positive, got " + std::to_string(dims.x()) +
                                    "x" + std::to_string(dims.y()) + "x" + std::to_string(dims.z()));
    if (blocks == 0) throw std::invalid_argument("a volume needs at least one channel and one time point");
    // n stays <= maxVoxels, so the test n * factor <= maxVoxels never overflows.
    std::uint64_t n = 1;
    for (const std::uint64_t factor : {std::uint64_t(dims.x()), std::uint64_t(dims.y()), std::uint64_t(dims.z()), blocks}) {
        if (factor > maxVoxels / n)
            throw std::invalid_argument("volume of " + std::to_string(dims.x()) + "x" + std::to_string(dims.y()) + "x" +
                                        std::to_string(dims.z()) + " voxels x " + std::to_string(blocks) +
                                        " blocks exceeds the limit of " + std::to_string(maxVoxels) + " voxels");
        n *= factor;
    }
    return n;
}

namespace {

std::uint64_t blockCount(int channels, int frames)
{
    if (channels <= 0 || frames <= 0)
        throw std::invalid_argument("channel and time point counts must be positive, got " + std::to_string(channels) +
                                    " and " + std::to_string(frames));
    return std::uint64_t(channels) * std::uint64_t(frames);
}

}  // namespace

void Volume::allocate(VoxelType type, const osg::Vec3i& dims, int channels, int frames)
{
    const std::uint64_t n = checkedVoxelCount(dims, blockCount(channels, frames));
    _data.assign(std::size_t(n) * voxelSize(type), 0);
    _type = type;
    _dims = dims;
    _channels = channels;
    _frames = frames;
    dirty();
}

void Volume::assign(VoxelType type, const osg::Vec3i& dims, std::vector<std::uint8_t>&& bytes, int channels, int frames)
{
    const std::uint64_t n = checkedVoxelCount(dims, blockCount(channels, frames));
    if (bytes.size() != n * voxelSize(type))
        throw std::invalid_argument("voxel buffer holds " + std::to_string(bytes.size()) + " bytes, expected " +
                                    std::to_string(n * voxelSize(type)));
    _data = std::move(bytes);
    _type = type;
    _dims = dims;
    _channels = channels;
    _frames = frames;
    dirty();
}

const std::uint8_t* Volume::block(int channel, int frame) const
{
    if (channel < 0 || channel >= _channels || frame < 0 || frame >= _frames)
        throw std::out_of_range("volume has " + std::to_string(_channels) + " channels and " + std::to_string(_frames) +
                                " time points; no block (" + std::to_string(channel) + ", " + std::to_string(frame) + ")");
    const std::size_t index = std::size_t(frame) * std::size_t(_channels) + std::size_t(channel);
    return _data.data() + index * voxelCount() * voxelSize(_type);
}

std::uint8_t* Volume::block(int channel, int frame)
{
    return const_cast<std::uint8_t*>(static_cast<const Volume&>(*this).block(channel, frame));
}

std::size_t Volume::voxelCount() const
{
    return std::size_t(_dims.x()) * std::size_t(_dims.y()) * std::size_t(_dims.z());
}

void Volume::setSpacing(const osg::Vec3d& spacing)
{
    for (int a = 0; a < 3; ++a)
        if (!(spacing[a] > 0.0) || !std::isfinite(spacing[a]))
            throw std::invalid_argument("voxel spacing must be positive and finite, got " +
                                        std::to_string(spacing.x()) + "," + std::to_string(spacing.y()) +
                                        "," + std::to_string(spacing.z()));
    _spacing = spacing;
    dirty();
}

double Volume::minSpacing() const
{
    const osg::Vec3d s = _fullResolution ? _fullResolution->spacing() : _spacing;
    return std::min({s.x(), s.y(), s.z()});
}

osg::Vec3d Volume::worldSize() const
{
    return osg::Vec3d(_dims.x() * _spacing.x(), _dims.y() * _spacing.y(), _dims.z() * _spacing.z());
}

void Volume::setRescale(double slope, double intercept)
{
    if (!std::isfinite(slope) || slope == 0.0 || !std::isfinite(intercept))
        throw std::invalid_argument("rescale slope must be finite and non-zero and intercept finite");
    _slope = slope;
    _intercept = intercept;
    dirty();
}

double Volume::storedValue(std::size_t i) const
{
    return storedAt(_type, _data.data(), i);
}

double Volume::value(int x, int y, int z) const
{
    return value(std::size_t(x) + std::size_t(_dims.x()) * (std::size_t(y) + std::size_t(_dims.y()) * z));
}

void Volume::computeStatistics() const
{
    Statistics s;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    const std::size_t n = totalVoxelCount();
    for (std::size_t i = 0; i < n; ++i) {
        const double v = storedAt(_type, _data.data(), i);
        if (!std::isfinite(v)) {
            ++s.nonFinite;
            continue;
        }
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    if (lo > hi) lo = hi = 0.0;  // empty or all non-finite
    s.minStored = lo;
    s.maxStored = hi;
    _stats = s;
}

std::pair<double, double> Volume::valueRange() const
{
    std::lock_guard<std::mutex> lock(_statsMutex);
    if (!_stats) computeStatistics();
    const double a = _stats->minStored * _slope + _intercept;
    const double b = _stats->maxStored * _slope + _intercept;
    return {std::min(a, b), std::max(a, b)};
}

std::uint64_t Volume::nonFiniteCount() const
{
    std::lock_guard<std::mutex> lock(_statsMutex);
    if (!_stats) computeStatistics();
    return _stats->nonFinite;
}

Histogram Volume::histogram(std::size_t bins) const
{
    const auto [lo, hi] = valueRange();
    std::lock_guard<std::mutex> lock(_statsMutex);
    if (_histogram && _histogram->counts.size() == bins) return *_histogram;
    Histogram h;
    h.minValue = lo;
    h.maxValue = hi > lo ? hi : lo + 1.0;
    h.counts.assign(std::max<std::size_t>(bins, 1), 0);
    const double scale = double(h.counts.size()) / (h.maxValue - h.minValue);
    const std::size_t n = totalVoxelCount();
    for (std::size_t i = 0; i < n; ++i) {
        const double v = storedAt(_type, _data.data(), i) * _slope + _intercept;
        if (!std::isfinite(v)) {
            ++h.ignored;
            continue;
        }
        const double b = std::floor((v - h.minValue) * scale);
        h.counts[std::size_t(std::clamp(b, 0.0, double(h.counts.size() - 1)))]++;
    }
    _histogram = h;
    return h;
}

void Volume::dirty()
{
    std::lock_guard<std::mutex> lock(_statsMutex);
    _stats.reset();
    _histogram.reset();
    ++_modifiedCount;
}

}  // namespace volren
