#include <volume_model/LazyOpening.h>
#include <volume_model/LazyRawSource.h>
#include <volume_model/LoadProgress.h>
#include <volume_model/MeanReduction.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace volren {

namespace {

constexpr std::uint64_t slabBytes = std::uint64_t(16) << 20;  // file bytes read per pread while streaming
constexpr std::uint64_t closeRows = 8192;  // rows at most this far apart are read with the gaps between them

std::string dimsText(const osg::Vec3i& d)
{
    return std::to_string(d.x()) + "x" + std::to_string(d.y()) + "x" + std::to_string(d.z());
}

void swapInPlace(std::uint8_t* data, std::size_t count, std::size_t width)
{
    for (std::size_t i = 0; i < count; ++i) std::reverse(data + i * width, data + (i + 1) * width);
}

std::size_t area(const osg::Vec3i& size) { return std::size_t(size.x()) * std::size_t(size.y()); }

}  // namespace

LazyRawSource::LazyRawSource(const Layout& layout, std::uint64_t previewBytes, const osgDB::Options* options) : _layout(layout)
{
    const std::string& path = _layout.path;
    const osg::Vec3i& d = _layout.dims;
    if (d.x() < 1 || d.y() < 1 || d.z() < 1) throw std::invalid_argument(path + ": dims " + dimsText(d) + " must be positive");
    const std::uint64_t vb = voxelSize(_layout.type);
    if (std::uint64_t(d.x()) * std::uint64_t(d.y()) > maxVoxels / std::uint64_t(d.z()))
        throw std::invalid_argument(path + ": dims " + dimsText(d) + " are over the limit of 2^40 voxels");
    const std::uint64_t bytes = std::uint64_t(d.x()) * std::uint64_t(d.y()) * std::uint64_t(d.z()) * vb;
    errno = 0;
    _fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (_fd < 0) throw std::runtime_error(path + ": cannot open: " + (errno == ENOENT ? "does not exist" : std::strerror(errno)));
    try {
        struct stat st {};
        if (::fstat(_fd, &st) != 0) throw std::runtime_error(path + ": cannot stat: " + std::strerror(errno));
        if (S_ISDIR(st.st_mode)) throw std::runtime_error(path + ": is a directory");
        const std::uint64_t fileSize = std::uint64_t(st.st_size);
        if (fileSize < _layout.offset || fileSize - _layout.offset < bytes)
            throw std::runtime_error(path + ": truncated: the file has " + std::to_string(fileSize) + " bytes, " + dimsText(d) + " " +
                                     voxelTypeName(_layout.type) + " voxels need " + std::to_string(bytes) + " from byte " +
                                     std::to_string(_layout.offset));
        _levels.resize(std::size_t(meanLevelCount(d)));
        _preview = previewLevelFor(*this, previewBytes);
        computeResidentLevels(options);
    } catch (...) {
        ::close(_fd);
        throw;
    }
}

LazyRawSource::~LazyRawSource()
{
    if (_fd >= 0) ::close(_fd);
}

osg::Vec3i LazyRawSource::levelDims(int level) const
{
    if (level < 0 || level >= levelCount())
        throw std::out_of_range(_layout.path + ": level " + std::to_string(level) + " of " + std::to_string(levelCount()));
    return meanLevelDims(_layout.dims, level);
}

const std::uint8_t* LazyRawSource::residentLevel(int level) const
{
    return level >= _preview && level < levelCount() ? _levels[std::size_t(level)].data() : nullptr;
}

std::size_t LazyRawSource::residentBytes() const
{
    std::size_t bytes = 0;
    for (const std::vector<std::uint8_t>& level : _levels) bytes += level.size();
    return bytes;
}

void LazyRawSource::computeResidentLevels(const osgDB::Options* options)
{
    const std::string& path = _layout.path;
    const osg::Vec3i& d = _layout.dims;
    const std::size_t vb = voxelSize(_layout.type);
    const int last = levelCount() - 1;
    try {
        for (int l = _preview; l <= last; ++l) {
            const osg::Vec3i ld = levelDims(l);
            _levels[std::size_t(l)].resize(area(ld) * std::size_t(ld.z()) * vb);
        }
    } catch (const std::bad_alloc&) {
        throw std::runtime_error(path + ": not enough memory for the preview level " + std::to_string(_preview));
    }
    // One pass over the file, slab by slab: each slice feeds the reduction of every level.
    const std::size_t sliceVoxels = area(d), sliceBytes = sliceVoxels * vb;
    const int slab = int(std::clamp<std::uint64_t>(slabBytes / sliceBytes, 1, std::uint64_t(d.z())));
    std::vector<std::uint8_t> raw(std::size_t(slab) * sliceBytes);
    std::vector<float> values(sliceVoxels);
    MeanReductionStream stream(d, last, {0, 0, 0}, levelDims(last));
    const MeanReductionStream::Sink keep = [&](int level, int z, const float* slice) {
        if (level < _preview) return;
        const std::size_t n = area(levelDims(level));
        floatToStored(_layout.type, slice, n, _levels[std::size_t(level)].data() + std::size_t(z) * n * vb);
    };
    const double total = double(sliceBytes) * d.z();
    if (!reportLoadProgress(options, 0.0, total)) throw std::runtime_error(path + ": cancelled");
    for (int z0 = 0; z0 < d.z(); z0 += slab) {
        const int n = std::min(slab, d.z() - z0);
        readBase({0, 0, z0}, {d.x(), d.y(), n}, raw.data());
        if (_preview == 0) std::memcpy(_levels[0].data() + std::size_t(z0) * sliceBytes, raw.data(), std::size_t(n) * sliceBytes);
        if (last > 0)
            for (int k = 0; k < n; ++k) {
                storedToFloat(_layout.type, raw.data() + std::size_t(k) * sliceBytes, sliceVoxels, values.data());
                stream.push(values.data(), keep);
            }
        if (!reportLoadProgress(options, double(sliceBytes) * (z0 + n), total)) throw std::runtime_error(path + ": cancelled");
    }
}

void LazyRawSource::readBytes(std::uint8_t* out, std::uint64_t bytes, std::uint64_t at) const
{
    while (bytes > 0) {
        const std::size_t want = std::size_t(std::min<std::uint64_t>(bytes, std::uint64_t(1) << 30));
        const ssize_t got = ::pread(_fd, out, want, off_t(at));
        if (got < 0) {
            if (errno == EINTR) continue;
            throw std::runtime_error(_layout.path + ": read error at byte " + std::to_string(at) + ": " + std::strerror(errno));
        }
        if (got == 0)
            throw std::runtime_error(_layout.path + ": truncated: the file ends at byte " + std::to_string(at) + ", the voxels need " +
                                     std::to_string(bytes) + " more bytes");
        out += got;
        at += std::uint64_t(got);
        bytes -= std::uint64_t(got);
    }
}

void LazyRawSource::readBase(const osg::Vec3i& origin, const osg::Vec3i& size, std::uint8_t* out) const
{
    const osg::Vec3i& d = _layout.dims;
    const std::uint64_t vb = voxelSize(_layout.type);
    const auto at = [&](int x, int y, int z) {
        return _layout.offset + ((std::uint64_t(z) * std::uint64_t(d.y()) + std::uint64_t(y)) * std::uint64_t(d.x()) + std::uint64_t(x)) * vb;
    };
    const std::uint64_t row = std::uint64_t(size.x()) * vb, plane = row * std::uint64_t(size.y());
    if (size.x() == d.x() && size.y() == d.y()) {
        readBytes(out, plane * std::uint64_t(size.z()), at(0, 0, origin.z()));
    } else {
        // Rows of one slice in one read when they are whole, or close together (then the pages
        // between them are mostly read anyway), else row by row: a pread per row of a brick
        // costs more in system calls than copying the gaps.
        const std::uint64_t stride = std::uint64_t(d.x()) * vb;
        const std::uint64_t span = std::uint64_t(size.y() - 1) * stride + row;
        const bool together = size.x() == d.x() || span <= 2 * plane || stride <= closeRows;
        std::vector<std::uint8_t> spanBuffer(together && size.x() != d.x() ? std::size_t(span) : 0);
        for (int z = 0; z < size.z(); ++z) {
            std::uint8_t* slice = out + std::uint64_t(z) * plane;
            const std::uint64_t first = at(origin.x(), origin.y(), origin.z() + z);
            if (size.x() == d.x()) {
                readBytes(slice, plane, first);
            } else if (together) {
                readBytes(spanBuffer.data(), span, first);
                for (int y = 0; y < size.y(); ++y)
                    std::memcpy(slice + std::uint64_t(y) * row, spanBuffer.data() + std::uint64_t(y) * std::uint64_t(d.x()) * vb, std::size_t(row));
            } else {
                for (int y = 0; y < size.y(); ++y)
                    readBytes(slice + std::uint64_t(y) * row, row, at(origin.x(), origin.y() + y, origin.z() + z));
            }
        }
    }
    if (vb > 1 && _layout.bigEndian != (std::endian::native == std::endian::big))
        swapInPlace(out, std::size_t(plane / vb) * std::size_t(size.z()), std::size_t(vb));
}

void LazyRawSource::read(int level, const osg::Vec3i& origin, const osg::Vec3i& size, std::uint8_t* out) const
{
    const osg::Vec3i ld = levelDims(level);
    for (int a = 0; a < 3; ++a)
        if (origin[a] < 0 || size[a] < 1 || origin[a] > ld[a] - size[a])
            throw std::invalid_argument(_layout.path + ": region " + dimsText(origin) + " + " + dimsText(size) + " is not inside level " +
                                        std::to_string(level) + " (" + dimsText(ld) + ")");
    const std::size_t vb = voxelSize(_layout.type);
    if (const std::uint8_t* resident = residentLevel(level)) {
        const std::size_t row = std::size_t(size.x()) * vb;
        for (int z = 0; z < size.z(); ++z)
            for (int y = 0; y < size.y(); ++y)
                std::memcpy(out + (std::size_t(z) * std::size_t(size.y()) + std::size_t(y)) * row,
                            resident + ((std::size_t(origin.z() + z) * std::size_t(ld.y()) + std::size_t(origin.y() + y)) * std::size_t(ld.x()) +
                                        std::size_t(origin.x())) * vb,
                            row);
        return;
    }
    if (level == 0) {
        readBase(origin, size, out);
        return;
    }
    // A level between 0 and the preview: reduced from the level-0 voxels the region covers.
    MeanReductionStream stream(_layout.dims, level, origin, size);
    const osg::Vec3i baseOrigin = stream.regionOrigin(0), baseSize = stream.regionSize(0);
    const std::size_t baseSlice = area(baseSize), outSlice = area(size);
    const int slab = int(std::clamp<std::uint64_t>(slabBytes / 2 / (baseSlice * vb), 1, std::uint64_t(baseSize.z())));
    std::vector<std::uint8_t> raw(std::size_t(slab) * baseSlice * vb);
    std::vector<float> values(baseSlice);
    const MeanReductionStream::Sink collect = [&](int l, int z, const float* slice) {
        if (l == level) floatToStored(_layout.type, slice, outSlice, out + std::size_t(z - origin.z()) * outSlice * vb);
    };
    for (int z0 = 0; z0 < baseSize.z(); z0 += slab) {
        const int n = std::min(slab, baseSize.z() - z0);
        readBase({baseOrigin.x(), baseOrigin.y(), baseOrigin.z() + z0}, {baseSize.x(), baseSize.y(), n}, raw.data());
        for (int k = 0; k < n; ++k) {
            storedToFloat(_layout.type, raw.data() + std::size_t(k) * baseSlice * vb, baseSlice, values.data());
            stream.push(values.data(), collect);
        }
    }
}

}  // namespace volren
