#include <volume_model/MeanReduction.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace volren {

osg::Vec3i meanLevelDims(const osg::Vec3i& dims, int level)
{
    return {std::max(1, dims.x() >> level), std::max(1, dims.y() >> level), std::max(1, dims.z() >> level)};
}

int meanLevelCount(const osg::Vec3i& dims)
{
    int levels = 1;
    while (meanLevelDims(dims, levels - 1) != osg::Vec3i(1, 1, 1)) ++levels;
    return levels;
}

MeanTaps meanTaps(int n, int size)
{
    if (size < 1 || size > n) throw std::invalid_argument("mean reduction of " + std::to_string(n) + " voxels to " + std::to_string(size));
    MeanTaps t;
    t.begin.reserve(std::size_t(size) + 1);
    const double r = double(n) / size;
    for (int j = 0; j < size; ++j) {
        t.begin.push_back(t.taps.size());
        const double a = j * r, b = (j + 1) * r;
        for (int i = int(std::floor(a)); i < std::min(n, int(std::ceil(b))); ++i) {
            const double w = std::min(b, i + 1.0) - std::max(a, double(i));
            if (w > 0.0) t.taps.push_back({i, w});
        }
    }
    t.begin.push_back(t.taps.size());
    return t;
}

namespace {

template <typename T>
void toFloat(const std::uint8_t* in, std::size_t count, float* out)
{
    for (std::size_t i = 0; i < count; ++i) {
        T v;
        std::memcpy(&v, in + i * sizeof(T), sizeof(T));
        out[i] = float(double(v));
    }
}

template <typename T>
void fromFloat(const float* in, std::size_t count, std::uint8_t* out)
{
    for (std::size_t i = 0; i < count; ++i) {
        T v;
        if constexpr (std::is_floating_point_v<T>) {
            v = T(in[i]);
        } else {
            const double clamped = std::isnan(in[i]) ? 0.0
                                                     : std::clamp(std::round(double(in[i])), double(std::numeric_limits<T>::min()),
                                                                  double(std::numeric_limits<T>::max()));
            v = T(clamped);
        }
        std::memcpy(out + i * sizeof(T), &v, sizeof(T));
    }
}

/// Mean of output `j`'s taps over `in` (input i at in[(i - offset) * stride]), NaN left out.
inline float meanOf(const MeanTaps& t, int j, const float* in, std::size_t stride, int offset)
{
    double sum = 0.0, weight = 0.0;
    for (std::size_t k = t.begin[std::size_t(j)]; k < t.begin[std::size_t(j) + 1]; ++k) {
        const MeanTaps::Tap& tap = t.taps[k];
        const float v = in[std::size_t(tap.input - offset) * stride];
        if (std::isnan(v)) continue;
        sum += tap.weight * double(v);
        weight += tap.weight;
    }
    return weight > 0.0 ? float(sum / weight) : std::numeric_limits<float>::quiet_NaN();
}

/// meanOf for two inputs of weight 1 (an even axis halved): the same sums, without the tap loop.
inline float meanOfPair(float a, float b)
{
    if (std::isnan(a)) return std::isnan(b) ? std::numeric_limits<float>::quiet_NaN() : float(double(b) / 1.0);
    if (std::isnan(b)) return float(double(a) / 1.0);
    return float((double(a) + double(b)) / 2.0);
}

/// Whether every output of `t` averages inputs 2j and 2j+1 with weight 1.
bool isPairwise(const MeanTaps& t)
{
    for (std::size_t j = 0; j + 1 < t.begin.size(); ++j)
        if (t.begin[j + 1] - t.begin[j] != 2 || t.taps[t.begin[j]].input != int(2 * j) || t.taps[t.begin[j]].weight != 1.0 ||
            t.taps[t.begin[j] + 1].weight != 1.0)
            return false;
    return true;
}

}  // namespace

void storedToFloat(VoxelType type, const std::uint8_t* in, std::size_t count, float* out)
{
    switch (type) {
    case VoxelType::UInt8: toFloat<std::uint8_t>(in, count, out); break;
    case VoxelType::Int8: toFloat<std::int8_t>(in, count, out); break;
    case VoxelType::UInt16: toFloat<std::uint16_t>(in, count, out); break;
    case VoxelType::Int16: toFloat<std::int16_t>(in, count, out); break;
    case VoxelType::Float32: toFloat<float>(in, count, out); break;
    }
}

void floatToStored(VoxelType type, const float* in, std::size_t count, std::uint8_t* out)
{
    switch (type) {
    case VoxelType::UInt8: fromFloat<std::uint8_t>(in, count, out); break;
    case VoxelType::Int8: fromFloat<std::int8_t>(in, count, out); break;
    case VoxelType::UInt16: fromFloat<std::uint16_t>(in, count, out); break;
    case VoxelType::Int16: fromFloat<std::int16_t>(in, count, out); break;
    case VoxelType::Float32: fromFloat<float>(in, count, out); break;
    }
}

/// Level-1 to level reduction of one region: x and y per input slice, z across slices.
struct MeanReductionStream::Stage
{
    int level = 1;                        ///< the output level
    osg::Vec3i inOrigin, inSize;          ///< region of level - 1 read
    osg::Vec3i outOrigin, outSize;        ///< region of level made
    MeanTaps taps[3];
    bool identity[3] = {false, false, false};  ///< axes where both levels have the same size
    bool pairwise[3] = {false, false, false};  ///< axes halved exactly (output j = mean of inputs 2j, 2j+1)
    int nextIn = 0;                       ///< z (in level - 1) of the next input slice
    int nextOpen = 0;                     ///< next output z to start accumulating
    std::vector<float> rows, plane, out;  ///< x-reduced slice, xy-reduced slice, finished output slice

    struct Pending
    {
        int z = 0;
        std::vector<double> sum, weight;
    };
    std::vector<Pending> pending, spare;  ///< output slices being accumulated (ascending z), recycled buffers
};

MeanReductionStream::MeanReductionStream(const osg::Vec3i& baseDims, int lastLevel, const osg::Vec3i& origin, const osg::Vec3i& size)
{
    if (lastLevel < 0) throw std::invalid_argument("mean reduction to level " + std::to_string(lastLevel));
    const osg::Vec3i top = meanLevelDims(baseDims, lastLevel);
    for (int a = 0; a < 3; ++a)
        if (baseDims[a] < 1 || origin[a] < 0 || size[a] < 1 || origin[a] > top[a] - size[a])
            throw std::invalid_argument("mean reduction: region outside level " + std::to_string(lastLevel));
    _origins.assign(std::size_t(lastLevel) + 1, origin);
    _sizes.assign(std::size_t(lastLevel) + 1, size);
    _stages.resize(std::size_t(lastLevel));
    for (int l = lastLevel; l >= 1; --l) {
        Stage& s = _stages[std::size_t(l) - 1];
        s.level = l;
        const osg::Vec3i in = meanLevelDims(baseDims, l - 1), out = meanLevelDims(baseDims, l);
        s.outOrigin = _origins[std::size_t(l)];
        s.outSize = _sizes[std::size_t(l)];
        for (int a = 0; a < 3; ++a) {
            s.taps[a] = meanTaps(in[a], out[a]);
            s.identity[a] = in[a] == out[a];
            s.pairwise[a] = isPairwise(s.taps[a]);
            const int lo = s.taps[a].first(s.outOrigin[a]), hi = s.taps[a].last(s.outOrigin[a] + s.outSize[a] - 1) + 1;
            s.inOrigin[a] = lo;
            s.inSize[a] = hi - lo;
        }
        _origins[std::size_t(l) - 1] = s.inOrigin;
        _sizes[std::size_t(l) - 1] = s.inSize;
        s.nextIn = s.inOrigin.z();
        s.nextOpen = s.outOrigin.z();
        if (!s.identity[0]) s.rows.resize(std::size_t(s.outSize.x()) * std::size_t(s.inSize.y()));
        if (!s.identity[1]) s.plane.resize(std::size_t(s.outSize.x()) * std::size_t(s.outSize.y()));
        if (!s.identity[2]) s.out.resize(std::size_t(s.outSize.x()) * std::size_t(s.outSize.y()));
    }
}

MeanReductionStream::~MeanReductionStream() = default;

void MeanReductionStream::push(const float* slice, const Sink& sink)
{
    if (!_stages.empty()) feed(0, slice, sink);
}

void MeanReductionStream::feed(std::size_t index, const float* slice, const Sink& sink)
{
    Stage& s = _stages[index];
    const int z = s.nextIn++;
    const std::size_t inX = std::size_t(s.inSize.x()), outX = std::size_t(s.outSize.x());
    const std::size_t area = outX * std::size_t(s.outSize.y());

    // Along x, row by row.
    const float* rows = slice;
    if (!s.identity[0]) {
        const std::size_t skip = std::size_t(2 * s.outOrigin.x() - s.inOrigin.x());  // 0 when pairwise
        for (int y = 0; y < s.inSize.y(); ++y) {
            const float* in = slice + std::size_t(y) * inX;
            float* out = s.rows.data() + std::size_t(y) * outX;
            if (s.pairwise[0])
                for (std::size_t x = 0; x < outX; ++x) out[x] = meanOfPair(in[skip + 2 * x], in[skip + 2 * x + 1]);
            else
                for (std::size_t x = 0; x < outX; ++x) out[x] = meanOf(s.taps[0], s.outOrigin.x() + int(x), in, 1, s.inOrigin.x());
        }
        rows = s.rows.data();
    }
    // Along y, column by column of the x-reduced rows.
    const float* plane = rows;
    if (!s.identity[1]) {
        for (int y = 0; y < s.outSize.y(); ++y) {
            float* out = s.plane.data() + std::size_t(y) * outX;
            if (s.pairwise[1]) {
                const float* a = rows + std::size_t(2 * (s.outOrigin.y() + y) - s.inOrigin.y()) * outX;
                for (std::size_t x = 0; x < outX; ++x) out[x] = meanOfPair(a[x], a[outX + x]);
            } else {
                for (std::size_t x = 0; x < outX; ++x) out[x] = meanOf(s.taps[1], s.outOrigin.y() + y, rows + x, outX, s.inOrigin.y());
            }
        }
        plane = s.plane.data();
    }
    const auto emit = [&](int outZ, const float* values) {
        if (sink) sink(s.level, outZ, values);
        if (index + 1 < _stages.size()) feed(index + 1, values, sink);
    };
    if (s.identity[2]) {
        emit(z, plane);
        return;
    }
    // Along z: every output slice whose box holds this input slice accumulates it, in input
    // order (the order of meanNextLevel's sums), and is finished at its last input.
    const MeanTaps& tz = s.taps[2];
    const int outEnd = s.outOrigin.z() + s.outSize.z();
    while (s.nextOpen < outEnd && tz.first(s.nextOpen) <= z) {
        Stage::Pending p;
        if (!s.spare.empty()) {
            p = std::move(s.spare.back());
            s.spare.pop_back();
        }
        p.z = s.nextOpen++;
        p.sum.assign(area, 0.0);
        p.weight.assign(area, 0.0);
        s.pending.push_back(std::move(p));
    }
    for (Stage::Pending& p : s.pending)
        for (std::size_t k = tz.begin[std::size_t(p.z)]; k < tz.begin[std::size_t(p.z) + 1]; ++k) {
            if (tz.taps[k].input != z) continue;
            const double w = tz.taps[k].weight;
            for (std::size_t i = 0; i < area; ++i) {
                const float v = plane[i];
                if (std::isnan(v)) continue;
                p.sum[i] += w * double(v);
                p.weight[i] += w;
            }
        }
    while (!s.pending.empty() && tz.last(s.pending.front().z) == z) {
        Stage::Pending& p = s.pending.front();
        for (std::size_t i = 0; i < area; ++i)
            s.out[i] = p.weight[i] > 0.0 ? float(p.sum[i] / p.weight[i]) : std::numeric_limits<float>::quiet_NaN();
        const int outZ = p.z;
        s.spare.push_back(std::move(p));
        s.pending.erase(s.pending.begin());
        emit(outZ, s.out.data());
    }
}

std::vector<float> meanNextLevel(const std::vector<float>& values, const osg::Vec3i& dims)
{
    const osg::Vec3i next = meanLevelDims(dims, 1);
    const std::size_t area = std::size_t(dims.x()) * std::size_t(dims.y()), nextArea = std::size_t(next.x()) * std::size_t(next.y());
    if (values.size() != area * std::size_t(dims.z())) throw std::invalid_argument("meanNextLevel: values do not fill the dims");
    std::vector<float> out(nextArea * std::size_t(next.z()));
    MeanReductionStream stream(dims, 1, {0, 0, 0}, next);
    const MeanReductionStream::Sink sink = [&](int, int z, const float* slice) { std::copy(slice, slice + nextArea, out.begin() + std::ptrdiff_t(std::size_t(z) * nextArea)); };
    for (int z = 0; z < dims.z(); ++z) stream.push(values.data() + std::size_t(z) * area, sink);
    return out;
}

}  // namespace volren
